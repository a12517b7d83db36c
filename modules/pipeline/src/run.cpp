#include <vlo/core/error.h>
#include <vlo/core/progress.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/global_map.h>
#include <vlo/pipeline/lidar_odometry_module.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>
#include <vlo/pipeline/run_outputs.h>
#include <vlo/pipeline/visual_odometry_module.h>

#include <filesystem>

namespace vlo
{
namespace
{
void prepareOutputDir(const std::string& dir)
{
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec || !std::filesystem::is_directory(dir)) failInput(dir, "cannot create output folder");
}
}  // namespace

RunSummary runPipeline(const RunRequest& req)
{
	auto config = RunConfig::fromFile(req.ini, req.overrides);
	PipelineOptions popt;
	config.load(popt, "pipeline");
	popt.validate(config.origin());
	if (popt.mode == "vlo")
		failInput(config.origin() + ": [pipeline] mode", "'vlo' needs the scale corrector, which is not built yet");
	std::unique_ptr<VisualOdometryModule> visual;
	if (popt.needsCamera())
	{
		visual = visualOdometryRegistry().create(popt.visual_odometry, config.origin() + ": [pipeline] visual_odometry");
		visual->configure(config);
	}
	std::unique_ptr<LidarOdometryModule> lidar;
	if (popt.needsLidar())
	{
		lidar = lidarOdometryRegistry().create(popt.lidar_odometry, config.origin() + ": [pipeline] lidar_odometry");
		lidar->configure(config);
	}
	config.checkAllKeysUsed();
	prepareOutputDir(req.out);

	RawlogReaderOptions ropt;
	ropt.camera_label = popt.camera_label;
	ropt.lidar_label = popt.lidar_label;
	ropt.max_time_diff = popt.max_time_diff;
	ropt.need_camera = popt.needsCamera();
	ropt.need_lidar = popt.needsLidar();
	RawlogReader reader(req.rawlog, ropt);

	RunOutputs outputs;
	GlobalMap globalMap(popt.map_voxel, popt.map_max_range);
	outputs.mode = popt.mode;
	ProgressLine progress("vlo-run: frame", 0);
	const auto loopStart = SteadyClock::now();
	Frame frame;
	while ((popt.max_frames == 0 || outputs.table.rows() < std::size_t(popt.max_frames)) && reader.next(frame))
	{
		auto& table = outputs.table;
		table.newRow();
		table.set("frame", static_cast<long long>(frame.index));
		table.set("t", frame.t, 6);
		const auto t0 = SteadyClock::now();
		if (visual)
		{
			const auto t1 = SteadyClock::now();
			const VisualOdometryStep step = visual->process(frame, table);
			table.set("ms_vo", msSince(t1), 2);
			if (step.pose) outputs.vo.push_back({frame.t, *step.pose});
		}
		if (lidar)
		{
			const Eigen::Isometry3d pose = lidar->process(frame, std::nullopt, table);
			outputs.lo.push_back({frame.t, pose});
			if (popt.map_every > 0 && frame.index % popt.map_every == 0)
				globalMap.insert(frame.scan, pose * frame.rig.vehicle_T_lidar);
			table.set("x", pose.translation().x(), 3);
			table.set("y", pose.translation().y(), 3);
			table.set("z", pose.translation().z(), 3);
		}
		table.set("ms_total", msSince(t0), 2);
		if (popt.sample_frame_every > 0 && frame.index % popt.sample_frame_every == 0) outputs.addSampleFrame(frame);
		progress.update(table.rows(), reader.progress());
	}
	progress.finish();
	const double loopSeconds = msSince(loopStart) / 1000.0;
	if (outputs.table.rows() == 0) failInput(req.rawlog, "no frame to process");

	outputs.map = globalMap.points();
	RunSummary summary = outputs.write(req.out, popt, config.effectiveIni(), req.gt);
	summary.frames = outputs.table.rows();
	summary.seconds = loopSeconds;
	summary.ms_per_frame = 1000.0 * loopSeconds / summary.frames;
	summary.reader_stats = reader.statsSummary();
	writeSummaryJson(req.out + "/summary.json", summary, req);
	return summary;
}
}  // namespace vlo
