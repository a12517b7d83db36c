#pragma once
// Ceres residuals of a keypoint observation: pixel error over the keypoint's sigma (its pyramid
// scale), so that the squared residual is the chi-square statistic with 2 dof. Poses are 6 doubles:
// angle-axis then translation of Tcw. Jacobians are analytic (several times faster than automatic
// differentiation, which dominated the local BA); tests check them against Ceres' autodiff.
#include <ceres/ceres.h>
#include <vlo/vo/geometry.h>

namespace vlo::vo::detail
{
/// d(R(w) X)/dw = -R [X]x Jr(w), Jr the right Jacobian of SO(3).
Eigen::Matrix3d rotatedPointJacobian(const Mat3& R, const Vec3& w, const Vec3& X);
Mat3 rotationFromParams(const double* p);

class ReprojectionError : public ceres::SizedCostFunction<2, 6, 3>
{
   public:
	ReprojectionError(const Vec2& obs, double inv_sigma, const PinholeCamera& c) : obs_(obs), w_(inv_sigma), c_(c) {}
	bool Evaluate(double const* const* p, double* r, double** J) const override;
	static ceres::CostFunction* create(const Vec2& obs, double inv_sigma, const PinholeCamera& c)
	{
		return new ReprojectionError(obs, inv_sigma, c);
	}

   private:
	Vec2 obs_;
	double w_;
	PinholeCamera c_;
};

/// The same with the point held fixed (pose-only optimisation).
class PoseOnlyError : public ceres::SizedCostFunction<2, 6>
{
   public:
	PoseOnlyError(const Vec3& X, const Vec2& obs, double inv_sigma, const PinholeCamera& c) : X_(X), e_(obs, inv_sigma, c) {}
	bool Evaluate(double const* const* p, double* r, double** J) const override;
	static ceres::CostFunction* create(const Vec3& X, const Vec2& obs, double inv_sigma, const PinholeCamera& c)
	{
		return new PoseOnlyError(X, obs, inv_sigma, c);
	}

   private:
	Vec3 X_;
	ReprojectionError e_;
};

void toParams(const SE3& T, double* p);
SE3 fromParams(const double* p);
ceres::Solver::Options solverOptions(int iterations, bool schur);
}  // namespace vlo::vo::detail
