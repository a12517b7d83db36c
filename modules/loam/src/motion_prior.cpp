#include <vlo/loam/motion_prior.h>

#include <vlo/core/se3.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace vlo::loam
{
namespace
{
/// motion^a on SE(3), approximated like A-LOAM: rotation angle and translation (the chord) both
/// scaled by a. Not the constant twist of the deskews: kept as A-LOAM's, whose prior this is.
Eigen::Isometry3d scaleAngleAndChord(const Eigen::Isometry3d& motion, double a)
{
	Eigen::AngleAxisd aa(motion.rotation());
	Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
	out.linear() = Eigen::AngleAxisd(aa.angle() * a, aa.axis()).toRotationMatrix();
	out.translation() = motion.translation() * a;
	return out;
}
}  // namespace

Eigen::Isometry3d ConstantVelocityPrior::predict(double t, const std::optional<Eigen::Isometry3d>&)
{
	if (!t_prev_ || last_dt_ <= 0)
	{
		source_ = t_prev_ ? "constant_velocity" : "none";
		return last_;
	}
	source_ = "constant_velocity";
	// A dropped frame doubles the interval: scale the motion (bounded, timestamps can be odd).
	const double ratio = std::clamp((t - *t_prev_) / last_dt_, 0.0, 3.0);
	if (std::abs(ratio - 1.0) < 0.05) return last_;
	return scaleAngleAndChord(last_, ratio);
}

void ConstantVelocityPrior::update(double t, const Eigen::Isometry3d& T_prev_curr)
{
	if (t_prev_ && t > *t_prev_)
	{
		last_ = T_prev_curr;
		last_dt_ = t - *t_prev_;
	}
	t_prev_ = t;
}

void ConstantVelocityPrior::reset()
{
	last_ = Eigen::Isometry3d::Identity();
	last_dt_ = 0;
	t_prev_.reset();
	source_ = "none";
}

bool ExternalPrior::plausible(const Eigen::Isometry3d& T) const
{
	if (!T.matrix().allFinite()) return false;
	const Eigen::Matrix3d R = T.linear();
	if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-3 || R.determinant() < 0) return false;
	return T.translation().norm() <= opt_.max_translation && rotationAngle(R) * 180.0 / M_PI <= opt_.max_rotation_deg;
}

bool ExternalPrior::agrees(const Eigen::Isometry3d& external, const Eigen::Isometry3d& cv) const
{
	const Eigen::Isometry3d d = cv.inverse() * external;
	return d.translation().norm() <= opt_.max_deviation &&
		rotationAngle(orthonormalize(d.linear())) * 180.0 / M_PI <= opt_.max_deviation_deg;
}

Eigen::Isometry3d ExternalPrior::predict(double t, const std::optional<Eigen::Isometry3d>& external)
{
	const Eigen::Isometry3d cv = fallback_.predict(t, std::nullopt);
	const std::optional<Eigen::Isometry3d> previous = std::exchange(last_external_, std::nullopt);
	set_aside_.reset();
	if (!external || !plausible(*external))
	{
		source_ = fallback_.lastSource();
		return cv;
	}
	last_external_ = *external;
	// A visual odometry that loses track jumps away from both the vehicle's motion so far and its own
	// motion of the frame before; LOAM failing in a degenerate scene makes constant velocity wrong
	// but leaves the visual odometry consistent with itself, so it is followed then.
	const bool consistent = previous && agrees(*external, *previous);
	if (fallback_.hasVelocity() && !agrees(*external, cv) && !consistent)
	{
		source_ = "constant_velocity (external rejected)";
		return cv;
	}
	source_ = "external";
	if (fallback_.hasVelocity()) set_aside_ = cv;
	Eigen::Isometry3d T = *external;
	T.linear() = orthonormalize(T.linear());  // visual odometry output may be slightly off SO(3)
	return T;
}

std::unique_ptr<MotionPrior> makeMotionPrior(const PriorOptions& o)
{
	if (o.source == "external") return std::make_unique<ExternalPrior>(o);
	return std::make_unique<ConstantVelocityPrior>();
}
}  // namespace vlo::loam
