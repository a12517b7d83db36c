#include "metric_vo_path.h"

namespace vlo::pipeline
{
namespace
{
Eigen::Isometry3d scaled(Eigen::Isometry3d T, double s)
{
	T.translation() *= s;
	return T;
}
}  // namespace

void MetricVoPath::push(double t, const Eigen::Isometry3d& camera_pose)
{
	last_ = camera_pose;
	path_.push_back({t, toVehicle(camera_pose)});
}

std::optional<Eigen::Isometry3d> MetricVoPath::update(
	double t, const kernel::VisualOdometryStep& step, const kernel::ScaleCorrection& correction)
{
	if (step.new_map)
	{
		// The VO starts a new map where its trajectory left off: here, the last metric pose.
		origin_ = last_.value_or(Eigen::Isometry3d::Identity());
		pending_.clear();
		metric_ = false;
	}
	if (!step.camera_map_pose) return std::nullopt;  // not tracked: a gap in the path
	if (!metric_)
	{
		pending_.emplace_back(t, *step.camera_map_pose);
		if (correction.kind != kernel::ScaleCorrection::Kind::Initial) return std::nullopt;
		// The map's first scale multiplies the whole map about its frame: so do its frames so far.
		for (const auto& [tp, mapPose] : pending_) push(tp, origin_ * scaled(mapPose, correction.factor));
		pending_.clear();
		metric_ = true;
	}
	else
	{
		if (!step.camera_motion || !last_) return std::nullopt;
		push(t, *last_ * scaled(*step.camera_motion, correction.factor));
	}
	if (!step.camera_motion) return std::nullopt;
	return toVehicle(scaled(*step.camera_motion, correction.factor));
}
}  // namespace vlo::pipeline
