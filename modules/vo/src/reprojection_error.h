#pragma once
// Residuals of a keypoint observation for vlo's own bundle solver: pixel error over the keypoint's
// sigma (its pyramid scale), so that the squared residual is the chi-square statistic with 2 dof.
// Poses are 6 doubles: angle-axis then translation of Tcw. Jacobians are analytic (several times
// faster than automatic differentiation, which dominated the local BA); tests check them against
// Ceres' autodiff, the only use of Ceres here (the tests link it, the library does not).
#include <vlo/vo/geometry.h>

#include <cmath>
#include <vector>

namespace vlo::vo::detail
{
/// A depth kept 1e-9 away from zero, its sign kept: a point behind the camera (an outlier) still gets
/// a finite residual, as with autodiff (failing the evaluation would stop a whole solve).
inline double safeDepth(double z) { return std::abs(z) < 1e-9 ? (z < 0 ? -1e-9 : 1e-9) : z; }

/// Jr(w), the right Jacobian of SO(3).
Mat3 rightJacobian(const Vec3& w);
/// d(R(w) X)/dw = -R [X]x Jr(w).
Eigen::Matrix3d rotatedPointJacobian(const Mat3& R, const Mat3& Jr, const Vec3& X);
Mat3 rotationFromParams(const double* p);

/// R(w) and Jr(w) of each pose of a problem at the parameters last asked for, so that the
/// observations of a pose share them within an evaluation of the problem (a keyframe has hundreds).
/// One per solve: not for several threads.
class PoseRotations
{
   public:
	struct Rotation
	{
		Mat3 R, Jr;
	};
	explicit PoseRotations(std::size_t n_poses) : entries_(n_poses) {}
	/// The rotation of pose `pose` at angle-axis w[0..3).
	const Rotation& at(std::size_t pose, const double* w);

   private:
	struct Entry
	{
		double w[3];
		bool valid = false;
		Rotation rot;
	};
	std::vector<Entry> entries_;
};

/// Ceres' cost-function interface without its base class: 2 residuals of a 6-parameter pose and a
/// 3-parameter point.
class ReprojectionError
{
   public:
	/// `rotations`: where the pose's rotation is looked up (as pose number `pose`), else computed.
	ReprojectionError(const Vec2& obs, double inv_sigma, const PinholeCamera& c, PoseRotations* rotations = nullptr,
		std::size_t pose = 0)
		: obs_(obs), w_(inv_sigma), c_(c), rotations_(rotations), pose_(pose)
	{
	}
	/// r[0..2); when J and J[i] are given, J[0] (2x6) and J[1] (2x3), row-major. Always true.
	bool Evaluate(double const* const* p, double* r, double** J) const;

   private:
	Vec2 obs_;
	double w_;
	PinholeCamera c_;
	PoseRotations* rotations_;
	std::size_t pose_;
};

void toParams(const SE3& T, double* p);
SE3 fromParams(const double* p);
}  // namespace vlo::vo::detail
