#include "frame_loop.h"

#include <vlo/core/stopwatch.h>
#include <vlo/io/undistort.h>
#include <vlo/pipeline/frame_prefetcher.h>
#include <vlo/pipeline/stage_worker.h>

#include <functional>
#include <memory>
#include <optional>

namespace vlo::pipeline
{
namespace
{
/// A frame between its motion source and its LiDAR odometry.
struct FrameInFlight : ReadFrame
{
	std::optional<kernel::MotionGuess> guess;  ///< the vehicle's motion since the previous frame
	kernel::FrameTable motion_row;  ///< the motion source's columns
	double ms = 0;  ///< spent in the motion source
};
}  // namespace

void runFrames(io::RawlogReader& reader, const Stages& stages, const PipelineOptions& popt, const LidarOptions& lidar,
	const RunPlan& plan, RunOutputs& outputs, GlobalMap& map, ProgressLine& progress)
{
	io::ImageUndistorter undistorter;  // the camera's estimators and snapshots see ideal pinhole images
	const bool threaded = popt.threadCount() >= 2;
	// The [lidar] corrections, and the LiDAR odometry's work on a frame alone (LOAM's features), run
	// where the frame is read: with two threads beside both stages, which leaves the stages more even.
	const auto prepare = [&stages, &lidar](Frame& f) {
		applyLidarOptions(f.scan, lidar);
		return stages.lidar ? stages.lidar->prepare(f) : std::unique_ptr<kernel::PreparedScan>();
	};
	FramePrefetcher frames(reader, threaded ? 2 : 0, std::size_t(popt.max_frames), prepare);

	// Each frame's motion source, then its LiDAR odometry and its row of the table. With two threads
	// the LiDAR odometry runs on the worker, up to kAhead frames behind the motion source: the
	// motion source never reads the LiDAR odometry's results (it takes only the frame), so the order of each
	// module's calls, and with it every output, is the same as with one thread.
	constexpr std::size_t kAhead = 3;
	const auto lidarAndRow = [&](FrameInFlight& done) {
		kernel::FrameTable lidarRow;
		std::optional<Eigen::Isometry3d> pose;
		std::optional<Matrix6d> information;  // of the vehicle's motion since the previous frame
		double lidarMs = 0;
		if (stages.lidar)
		{
			const auto t0 = SteadyClock::now();
			kernel::LidarOdometryStep step = stages.lidar->process(
				done.frame, std::move(done.prepared), plan.bootstrapping ? done.guess : std::nullopt, lidarRow);
			pose = step.pose;
			information = step.information;
			if (popt.map_every > 0 && done.frame.index % popt.map_every == 0)
				map.insert(done.frame.scan, *pose * done.frame.rig.vehicle_T_lidar, static_cast<std::uint32_t>(outputs.lidar.size()));
			lidarMs = done.prepared_ms + msSince(t0);
		}
		double loopMs = 0;
		if (stages.loop && pose)
		{
			const auto t0 = SteadyClock::now();
			stages.loop->addFrame(static_cast<long long>(done.frame.index), done.frame.t, *pose, information,
				done.frame.scan, done.frame.rig.vehicle_T_lidar);
			loopMs = msSince(t0);
		}
		auto& table = outputs.table;
		table.newRow();
		table.set("frame", static_cast<long long>(done.frame.index));
		table.set("t", done.frame.t, 6);
		table.setCells(done.motion_row);
		if (pose)
		{
			if (stages.motion) table.set("vo_metric_motion", done.guess.has_value());
			table.set("lo_point_times", std::string(pointTimeSource(done.frame.scan)));
			table.setCells(lidarRow);
			outputs.lidar.push_back({done.frame.t, *pose});
			table.set("x", pose->translation().x(), 3);
			table.set("y", pose->translation().y(), 3);
			table.set("z", pose->translation().z(), 3);
		}
		if (stages.loop) table.set("ms_loop", loopMs, 2);
		table.set("ms_total", done.ms + lidarMs + loopMs, 2);
		if (popt.sample_frame_every > 0 && done.frame.index % popt.sample_frame_every == 0)
			outputs.addSampleFrame(done.frame);
		progress.update(table.rows(), frames.progress());
	};
	StageWorker worker(threaded, kAhead);  // after what its jobs use: destroyed, and so waited for, first
	for (;;)
	{
		auto cur = std::make_shared<FrameInFlight>();
		bool more = false;
		try
		{
			more = frames.next(*cur);
		}
		catch (const InputError& e)
		{
			worker.wait();  // the frames before end first, as in a serial run
			throw InputEndedEarly(e);
		}
		if (!more) break;
		if (stages.motion)
		{
			try
			{
				const auto t0 = SteadyClock::now();
				undistorter.apply(cur->frame);
				// Shared with the motion source, which may keep it for the next frame.
				cur->guess = stages.motion->process(std::shared_ptr<const Frame>(cur, &cur->frame), cur->motion_row);
				cur->ms = msSince(t0);
			}
			catch (...)
			{
				worker.wait();  // the frames before fail first, as in a serial run
				throw;
			}
		}
		worker.start([&lidarAndRow, cur] { lidarAndRow(*cur); });
	}
	worker.wait();
}
}  // namespace vlo::pipeline
