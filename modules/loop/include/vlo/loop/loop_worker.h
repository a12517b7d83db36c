#pragma once
// What the loop thread does with each keyframe, in order: place recognition among the earlier ones,
// verification of the candidate, the pose graph's node, odometry edge and loop edge, and an
// optimisation after each accepted loop. Single-threaded itself: LoopClosure runs it on its thread.
#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/loop/options.h>
#include <vlo/loop/place_recognition.h>
#include <vlo/loop/pose_graph.h>

#include <vector>

namespace vlo::loop
{
class LoopWorker
{
   public:
	explicit LoopWorker(const LoopOptions& options);

	void process(Keyframe keyframe);
	/// Optimises the whole graph when it holds a loop; returns the wall time [s] (0 without loops).
	double finalOptimisation();

	const std::vector<Keyframe>& keyframes() const { return keyframes_; }
	const std::vector<LoopRecord>& loops() const { return loops_; }
	bool closed() const { return accepted_ > 0; }
	/// The keyframe's pose corrected by the graph (the odometry's before any loop).
	Eigen::Isometry3d corrected(std::size_t keyframe) const { return graph_.pose(keyframe); }

   private:
	LoopOptions options_;
	PlaceDatabase places_;
	PoseGraph graph_;
	std::vector<Keyframe> keyframes_;
	std::vector<LoopRecord> loops_;
	std::size_t accepted_ = 0;
};
}  // namespace vlo::loop
