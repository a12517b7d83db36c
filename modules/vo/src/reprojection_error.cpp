#include "reprojection_error.h"

#include <cmath>
#include <cstring>

namespace vlo::vo::detail
{
Mat3 rotationFromParams(const double* p)
{
	const Vec3 v(p[0], p[1], p[2]);
	const double a = v.norm();
	return a < 1e-12 ? Mat3::Identity() : Eigen::AngleAxisd(a, v / a).toRotationMatrix();
}

Mat3 rightJacobian(const Vec3& w)
{
	const double t = w.norm();
	const Mat3 W = skew(w);
	Mat3 Jr = Mat3::Identity();
	if (t > 1e-8)
		Jr += -(1 - std::cos(t)) / (t * t) * W + (t - std::sin(t)) / (t * t * t) * W * W;
	else
		Jr += -0.5 * W;
	return Jr;
}

Eigen::Matrix3d rotatedPointJacobian(const Mat3& R, const Mat3& Jr, const Vec3& X) { return -R * skew(X) * Jr; }

const PoseRotations::Rotation& PoseRotations::at(std::size_t pose, const double* w)
{
	Entry& e = entries_[pose];
	// Bitwise: the same parameters give the same rotation, as computing it again would.
	if (!e.valid || std::memcmp(e.w, w, sizeof e.w) != 0)
	{
		std::memcpy(e.w, w, sizeof e.w);
		e.valid = true;
		e.rot.R = rotationFromParams(w);
		e.rot.Jr = rightJacobian(Vec3(w[0], w[1], w[2]));
	}
	return e.rot;
}

bool ReprojectionError::Evaluate(double const* const* p, double* r, double** J) const
{
	const double* pose = p[0];
	const Vec3 X(p[1][0], p[1][1], p[1][2]);
	const PoseRotations::Rotation* shared = rotations_ ? &rotations_->at(pose_, pose) : nullptr;
	const Mat3 R = shared ? shared->R : rotationFromParams(pose);
	const Vec3 Xc = R * X + Vec3(pose[3], pose[4], pose[5]);
	const double z = safeDepth(Xc.z());
	const double iz = 1.0 / z;
	r[0] = (c_.fx * Xc.x() * iz + c_.cx - obs_.x()) * w_;
	r[1] = (c_.fy * Xc.y() * iz + c_.cy - obs_.y()) * w_;
	if (!J) return true;
	Eigen::Matrix<double, 2, 3> Jp;
	Jp << c_.fx * iz, 0, -c_.fx * Xc.x() * iz * iz, 0, c_.fy * iz, -c_.fy * Xc.y() * iz * iz;
	Jp *= w_;
	if (J[0])
	{
		Eigen::Map<Eigen::Matrix<double, 2, 6, Eigen::RowMajor>> Jpose(J[0]);
		const Mat3 Jr = shared ? shared->Jr : rightJacobian(Vec3(pose[0], pose[1], pose[2]));
		Jpose.leftCols<3>() = Jp * rotatedPointJacobian(R, Jr, X);
		Jpose.rightCols<3>() = Jp;
	}
	if (J[1])
	{
		Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> Jx(J[1]);
		Jx = Jp * R;
	}
	return true;
}

void toParams(const SE3& T, double* p)
{
	const Eigen::AngleAxisd aa(T.linear());
	const Vec3 v = aa.axis() * aa.angle();
	p[0] = v.x(), p[1] = v.y(), p[2] = v.z();
	p[3] = T.translation().x(), p[4] = T.translation().y(), p[5] = T.translation().z();
}

SE3 fromParams(const double* p) { return makeSE3(rotationFromParams(p), Vec3(p[3], p[4], p[5])); }
}  // namespace vlo::vo::detail
