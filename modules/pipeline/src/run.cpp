#include <vlo/core/error.h>
#include <vlo/core/progress.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/undistort.h>
#include <vlo/io/trajectory.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/global_map.h>
#include <vlo/pipeline/lidar_odometry_module.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>
#include <vlo/pipeline/metric_vo_path.h>
#include <vlo/pipeline/run_outputs.h>
#include <vlo/pipeline/scale_stage.h>
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
	const bool vlo = popt.mode == "vlo";
	// Visual bootstrapping: LOAM takes the VO's motion as its initial guess unless told otherwise.
	if (vlo && popt.bootstrapping) config.setDefault("loam.prior", "source", "external");
	// Every module reads its sections whatever the mode, so that one sensor INI serves all modes and a
	// typo is an error in any of them; only the modules of the mode run.
	auto visual = visualOdometryRegistry().create(popt.visual_odometry, config.origin() + ": [pipeline] visual_odometry");
	visual->configure(config);
	auto lidar = lidarOdometryRegistry().create(popt.lidar_odometry, config.origin() + ": [pipeline] lidar_odometry");
	lidar->configure(config);
	auto scaleStage = std::make_unique<ScaleStage>(config, popt.scale_snapshot_every);
	if (!popt.needsCamera()) visual.reset();
	if (!popt.needsLidar()) lidar.reset();
	if (!vlo) scaleStage.reset();
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
	std::optional<MetricVoPath> metricVo;
	Frame frame, prev;
	bool hasPrev = false;
	ImageUndistorter undistorter;  // the estimators and snapshots see ideal pinhole images
	while ((popt.max_frames == 0 || outputs.table.rows() < std::size_t(popt.max_frames)) && reader.next(frame))
	{
		auto& table = outputs.table;
		table.newRow();
		table.set("frame", static_cast<long long>(frame.index));
		table.set("t", frame.t, 6);
		const auto t0 = SteadyClock::now();
		if (visual) undistorter.apply(frame);
		std::optional<Eigen::Isometry3d> guess;  // LOAM's initial guess of the vehicle motion
		if (visual)
		{
			auto t1 = SteadyClock::now();
			const VisualOdometryStep step = visual->process(frame, table);
			table.set("ms_vo", lapMs(t1), 2);
			if (!vlo && step.pose) outputs.vo.push_back({frame.t, *step.pose});
			if (vlo)
			{
				const ScaleApplied applied = scaleStage->process(hasPrev ? &prev : nullptr, frame, step, *visual, table);
				if (!metricVo) metricVo.emplace(frame.rig.vehicle_T_camera);
				const auto motion = metricVo->update(frame.t, step, applied);
				if (popt.bootstrapping) guess = motion;
				table.set("vo_metric_motion", motion.has_value());
			}
		}
		if (lidar)
		{
			const Eigen::Isometry3d pose = lidar->process(frame, guess, table);
			outputs.lo.push_back({frame.t, pose});
			if (popt.map_every > 0 && frame.index % popt.map_every == 0)
				globalMap.insert(frame.scan, pose * frame.rig.vehicle_T_lidar);
			table.set("x", pose.translation().x(), 3);
			table.set("y", pose.translation().y(), 3);
			table.set("z", pose.translation().z(), 3);
		}
		table.set("ms_total", msSince(t0), 2);
		if (popt.sample_frame_every > 0 && frame.index % popt.sample_frame_every == 0) outputs.addSampleFrame(frame);
		if (vlo)
		{
			prev = frame;
			prev.image = frame.image.makeDeepCopy();  // the reader may reuse the image buffer
			hasPrev = true;
		}
		progress.update(table.rows(), reader.progress());
	}
	progress.finish();
	const double loopSeconds = msSince(loopStart) / 1000.0;
	if (outputs.table.rows() == 0) failInput(req.rawlog, "no frame to process");

	outputs.map = globalMap.points();
	if (metricVo) outputs.vo = metricVo->trajectory();
	if (scaleStage) outputs.scale_snapshots = scaleStage->snapshots();
	RunSummary summary = outputs.write(req.out, popt, config.effectiveIni(), req.gt);
	summary.frames = outputs.table.rows();
	summary.seconds = loopSeconds;
	summary.ms_per_frame = 1000.0 * loopSeconds / summary.frames;
	summary.reader_stats = reader.statsSummary();
	if (scaleStage)
	{
		summary.figures.push_back({"scale_estimates", double(scaleStage->estimates())});
		summary.figures.push_back({"scale_valid", double(scaleStage->valid())});
		summary.figures.push_back({"scale_corrections", double(scaleStage->corrections())});
	}
	writeSummaryJson(req.out + "/summary.json", summary, req);
	return summary;
}
}  // namespace vlo
