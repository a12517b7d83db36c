#include <vlo/loop/loop_worker.h>
#include <vlo/loop/verification.h>

#include <cmath>

namespace vlo::loop
{
namespace
{
PlaceRecognitionParams placeParams(const LoopOptions& o)
{
	PlaceRecognitionParams p;
	p.descriptor.range = o.descriptor_range;
	p.descriptor.rings = o.descriptor_rings;
	p.descriptor.sectors = o.descriptor_sectors;
	p.descriptor.sensor_height = o.sensor_height;
	p.candidates = o.candidates;
	p.max_distance = o.max_descriptor_distance;
	p.min_revisit_path = o.min_revisit_path;
	p.query_shift = o.query_shift;
	return p;
}
}  // namespace

LoopWorker::LoopWorker(const LoopOptions& options) : options_(options), places_(placeParams(options)) {}

void LoopWorker::process(Keyframe keyframe)
{
	const std::size_t k = keyframes_.size();
	if (k == 0)
		graph_.addNode(keyframe.odometry);
	else
	{
		// A new node continues the corrected chain with the odometry's last step.
		const Eigen::Isometry3d step = keyframes_[k - 1].odometry.inverse() * keyframe.odometry;
		graph_.addNode(graph_.pose(k - 1) * step);
		graph_.addEdge(k - 1, k, step, invertPositive(keyframe.odometry_covariance), 0);
	}
	const auto candidate = places_.addAndQuery(keyframe.points, keyframe.path);
	keyframes_.push_back(std::move(keyframe));
	if (!candidate) return;

	const Keyframe& current = keyframes_[k];
	const Keyframe& earlier = keyframes_[candidate->keyframe];
	const Eigen::Isometry3d odometry_relative = earlier.odometry.inverse() * current.odometry;
	const double path_between = current.path - earlier.path;
	std::optional<Verification> out_of_reach = rejectOutOfReach(candidate->match, odometry_relative, path_between, options_);
	Verification v = out_of_reach
		? std::move(*out_of_reach)
		: verifyLoop(current.points, candidateSubmap(keyframes_, candidate->keyframe, options_.submap_keyframes, k),
			  candidate->match, odometry_relative, path_between, options_);
	v.record.frame = current.frame;
	v.record.candidate_frame = earlier.frame;
	if (v.record.accepted)
	{
		graph_.addEdge(candidate->keyframe, k, v.record.candidate_T_current, v.information, options_.loop_huber);
		++accepted_;
		graph_.optimise();
	}
	loops_.push_back(std::move(v.record));
}

double LoopWorker::finalOptimisation()
{
	if (!closed()) return 0;
	return graph_.optimise().seconds;
}
}  // namespace vlo::loop
