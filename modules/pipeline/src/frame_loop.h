#pragma once
// The frame loop of a run: each frame through the motion source, then the LiDAR odometry, into the
// run's outputs; with two threads, reading ahead and the two stages of consecutive frames side by side.
#include <vlo/core/error.h>
#include <vlo/core/progress.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/kernel/lidar_odometry.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/pipeline/global_map.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/lidar_options.h>
#include <vlo/pipeline/run_outputs.h>

#include <memory>

namespace vlo::pipeline
{
/// The input failed after the frame loop started (a rawlog cut short or damaged in the middle, an image
/// missing): the frames before it are the run's, and runPipeline keeps them.
struct InputEndedEarly : InputError
{
	explicit InputEndedEarly(const InputError& e) : InputError(e) {}
};

/// The modules of a run, created by name and configured.
struct Stages
{
	std::unique_ptr<kernel::MotionSource> motion;
	std::unique_ptr<kernel::LidarOdometryModule> lidar;
	std::unique_ptr<loop::LoopClosure> loop;  ///< [pipeline] loop_closure, over the LiDAR odometry
};

/// Runs the reader's frames (up to [pipeline] max_frames) through the stages: one row of
/// outputs.table per frame, outputs.lidar, the sample frames, and the scans of map.pcd into `map`
/// (anchored to their row of outputs.lidar); each pose and scan also to the loop closure when it runs.
/// Each scan gets its point times ([lidar]) before the LiDAR odometry sees it.
/// With [pipeline] threads 2 the outputs are the same as with 1 (each module gets the same inputs in
/// the same order). Returns once every
/// thread it started has ended, also when it throws: InputEndedEarly when reading fails, Interrupted
/// after a frame's row on Ctrl-C, with the rows of the frames before complete.
void runFrames(io::RawlogReader& reader, const Stages& stages, const PipelineOptions& popt, const LidarOptions& lidar,
	const RunPlan& plan, RunOutputs& outputs, GlobalMap& map, ProgressLine& progress);
}  // namespace vlo::pipeline
