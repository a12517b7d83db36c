// The run loop, as the paper's figure: frame -> motion source -> LiDAR odometry -> outputs.
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>
#include <vlo/core/log.h>
#include <vlo/core/progress.h>
#include <vlo/core/stopwatch.h>
#include <vlo/eval/camera_frame.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>
#include <vlo/pipeline/global_map.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>
#include <vlo/pipeline/run_folder.h>
#include <vlo/pipeline/run_outputs.h>
#include <vlo/pipeline/run_report.h>
#include <vlo/pipeline/stage_timings.h>

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>

#include "frame_loop.h"

namespace vlo::pipeline
{
namespace
{
/// Fails early when the output folder could not be made, without making it: it is created only once
/// the run has something to write, so bad input or Ctrl-C leaves no empty folder behind.
void checkOutputDir(const std::string& dir)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	fs::path p = fs::absolute(dir, ec);
	while (!p.empty() && !fs::exists(p, ec) && p != p.parent_path()) p = p.parent_path();
	if (!fs::is_directory(p, ec)) failInput(dir, "cannot create output folder (" + p.string() + " is not a folder)");
	if (::access(p.c_str(), W_OK) != 0) failInput(dir, "cannot create output folder (" + p.string() + " is not writable)");
}

/// After the outputs of an early stop are written: the stop again, saying what was kept.
[[noreturn]] void throwStoppedEarly(const std::exception_ptr& stop, const RunSummary& s, const std::string& out)
{
	const std::string frames = s.frames == 1 ? "the 1 frame, frame " + std::to_string(s.last_frame) + ", is"
											 : "the " + std::to_string(s.frames) + " frames up to frame " +
			std::to_string(s.last_frame) + " are";
	const std::string kept = frames + " kept in " + out + " (summary.json: \"complete\": false)";
	try
	{
		std::rethrow_exception(stop);
	}
	catch (const Interrupted&)
	{
		throw Interrupted(kept);
	}
	catch (const InputError& e)
	{
		failInput(e.what(), "the run stopped there; " + kept);
	}
}

/// After the frame loop: the loop closure's last optimisation, its trajectory, loops and map. A failure
/// there costs the loop-closed outputs, not the odometry's.
void closeLoops(loop::LoopClosure& closure, RunOutputs& outputs, GlobalMap& map)
{
	try
	{
		closure.finish();
		outputs.setLoops(closure);
		map.correct(outputs.loopCorrections());
	}
	catch (const std::exception& e)
	{
		outputs.slam.clear();
		logger().logStr(mrpt::system::LVL_WARN, std::string("loop closure failed, trajectory_slam.tum not written: ") + e.what());
	}
}

void prepareOutputDir(const std::string& dir)
{
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec || !std::filesystem::is_directory(dir)) failInput(dir, "cannot create output folder");
}


/// One sensor INI serves every mode and every method: each registered module of a family loads and
/// checks its sections, so that the sections of a module not chosen are no error and a typo is one
/// whichever module runs.
template <class Family, class... Args>
void checkOptionsOfAll(kernel::RunConfig& config, const Args&... args)
{
	for (auto& [name, module] : kernel::registry<Family>().createAll()) module->configure(config, args...);
}

/// Creates and configures the modules the plan runs, and no other.
Stages makeStages(const PipelineOptions& popt, const RunPlan& plan, kernel::RunConfig& config)
{
	const auto where = [&config](const char* key) { return config.where("pipeline", key); };
	kernel::registry<kernel::MotionSource>().require(popt.motion_source, where("motion_source"));
	kernel::registry<kernel::VisualOdometryModule>().require(popt.visual_odometry, where("visual_odometry"));
	kernel::registry<kernel::ScaleCorrectionModule>().require(popt.scale_correction, where("scale_correction"));
	kernel::registry<kernel::LidarOdometryModule>().require(popt.lidar_odometry, where("lidar_odometry"));
	checkOptionsOfAll<kernel::VisualOdometryModule>(config);
	checkOptionsOfAll<kernel::ScaleCorrectionModule>(config, 0);
	checkOptionsOfAll<kernel::LidarOdometryModule>(config);
	loop::LoopOptions loopOptions;
	config.load(loopOptions, "loop");  // checked in every mode, as the modules' sections
	Stages s;
	if (popt.loop_closure && plan.lidar_odometry) s.loop = std::make_unique<loop::LoopClosure>(loopOptions);
	if (!plan.motion_source.empty())
	{
		s.motion = kernel::registry<kernel::MotionSource>().create(plan.motion_source, where("motion_source"));
		s.motion->configure(config, popt.motionSourceSetup());
	}
	if (plan.lidar_odometry)
	{
		s.lidar = kernel::registry<kernel::LidarOdometryModule>().create(popt.lidar_odometry, where("lidar_odometry"));
		s.lidar->configure(config);
	}
	config.checkAllKeysUsed();
	return s;
}
}  // namespace

RunSummary runPipeline(const RunRequest& req)
{
	auto config = kernel::RunConfig::fromFile(req.ini, req.overrides);
	PipelineOptions popt;
	config.load(popt, "pipeline");
	LidarOptions lidar;
	config.load(lidar, "lidar");
	const RunPlan plan = popt.plan();
	Stages stages = makeStages(popt, plan, config);
	logger().logFmt(mrpt::system::LVL_DEBUG, "mode %s: motion source '%s', LiDAR odometry '%s'", plan.name.c_str(),
		plan.motion_source.empty() ? "none" : plan.motion_source.c_str(), plan.lidar_odometry ? popt.lidar_odometry.c_str() : "none");
	checkOutputDir(req.out);
	RunFolder folder(req.out, req.overwrite);
	// Every input is read and checked before the first frame: a bad one found at the end would cost the run.
	if (!req.gt.empty()) io::readTum(req.gt);
	std::optional<Eigen::Isometry3d> cam0_T_vehicle;
	if (!req.kitti_calib.empty()) cam0_T_vehicle = eval::readKittiCalibTr(req.kitti_calib);

	io::RawlogReaderOptions ropt;
	ropt.camera_label = popt.camera_label;
	ropt.lidar_label = popt.lidar_label;
	ropt.max_time_diff = popt.max_time_diff;
	ropt.need_camera = stages.motion != nullptr;
	ropt.need_lidar = stages.lidar != nullptr;
	io::RawlogReader reader(req.rawlog, ropt);

	RunOutputs outputs;
	outputs.plan = plan;
	GlobalMap globalMap(popt.map_voxel, popt.map_max_range);
	ProgressLine progress("vlo-run: frame", 0);
	const auto loopStart = SteadyClock::now();
	std::exception_ptr stop;  // why the frame loop ended before the input did, if it did
	std::string stopReason;
	try
	{
		pipeline::runFrames(reader, stages, popt, lidar, plan, outputs, globalMap, progress);
	}
	catch (const Interrupted&)
	{
		stop = std::current_exception(), stopReason = "interrupted (Ctrl-C or SIGTERM)";
	}
	catch (const InputEndedEarly& e)
	{
		stop = std::current_exception(), stopReason = e.what();
	}
	progress.finish();
	const double loopSeconds = msSince(loopStart) / 1000.0;
	const bool noTrajectory = !plan.lidar_odometry && (!stages.motion || stages.motion->trajectory().empty());
	if (stop && (outputs.table.rows() == 0 || noTrajectory)) std::rethrow_exception(stop);  // nothing to keep
	if (outputs.table.rows() == 0) failInput(req.rawlog, "no frame to process");
	if (noTrajectory)
		failInput(req.rawlog,
			"the visual odometry never initialised in " + std::to_string(outputs.table.rows()) +
				" frames: no trajectory to write (too few frames, or too little texture or motion)");

	if (stages.motion) outputs.setMotion(*stages.motion);
	if (stages.loop && !outputs.lidar.empty()) closeLoops(*stages.loop, outputs, globalMap);
	outputs.map = globalMap.takePoints();
	outputs.cam0_T_vehicle = cam0_T_vehicle;
	if (!outputs.cam0_T_vehicle && reader.vehicleTCamera0()) outputs.cam0_T_vehicle = reader.vehicleTCamera0()->inverse();
	prepareOutputDir(req.out);
	folder.clearPreviousRun();
	RunSummary summary;
	try
	{
		summary = outputs.write(req.out, config.effectiveIni());
		if (popt.snapshots) writeSnapshots(req.out + "/snapshots", outputs, stages.motion.get(), req.gt);
		summary.frames = outputs.table.rows();
		summary.seconds = loopSeconds;
		summary.ms_per_frame = 1000.0 * loopSeconds / summary.frames;
		summary.reader_stats = reader.statsSummary();
		summary.stage_timings = stageTimings(outputs.table);
		summary.complete = !stop;
		summary.stop_reason = stopReason;
		summary.last_frame = static_cast<long long>(outputs.table.numbers("frame").back());
		writeSummaryJson(req.out + "/summary.json", summary, req);
		writeRunReport(req.out, summary, req, outputs.table, popt.snapshots);
		folder.recordWritten();
	}
	catch (...)
	{
		folder.removeWritten();  // e.g. a full disk: no run without its summary and list of files
		throw;
	}
	logger().logStr(mrpt::system::LVL_DEBUG, summary.reader_stats);
	// With two threads the stages of consecutive frames overlap: each frame's ms_total then exceeds the wall
	// time per frame, which is said beside it.
	char wall[160];
	std::snprintf(wall, sizeof(wall), "\nwall time per frame: %.2f ms with %d thread%s (ms_total: each frame's own time in its stages%s)",
		summary.ms_per_frame, popt.threadCount(), popt.threadCount() > 1 ? "s" : "",
		popt.threadCount() > 1 ? ", which overlap with other frames'" : "");
	logger().logStr(mrpt::system::LVL_INFO,
		"time per stage over " + std::to_string(summary.frames) + " frames (frames.csv):\n" +
			formatStageTimings(summary.stage_timings) + wall);
	if (stop) throwStoppedEarly(stop, summary, req.out);
	return summary;
}
}  // namespace vlo::pipeline
