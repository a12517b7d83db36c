// vlo-eval: scores an estimated trajectory against ground truth (KITTI odometry metric, ATE/ARE, RPE,
// revisit error).
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/eval/camera_frame.h>
#include <vlo/eval/evaluate.h>
#include <vlo/eval/report.h>
#include <vlo/io/trajectory.h>
#include <vlo/viz/eval_plots.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

using namespace vlo;

namespace
{
std::vector<double> parseLengths(const std::string& s)
{
	std::vector<double> v;
	std::string tok;
	for (std::istringstream ss(s); std::getline(ss, tok, ',');)
	{
		char* end = nullptr;
		const double d = std::strtod(tok.c_str(), &end);
		if (tok.empty() || *end != '\0' || !(d > 0)) failInput("--kitti-lengths", "'" + tok + "' is not a positive length");
		v.push_back(d);
	}
	if (v.empty()) failInput("--kitti-lengths", "no length given");
	return v;
}

/// Legend names: each file's name without folder and extension, or the path as given when two would clash.
std::vector<std::string> runNames(const std::vector<std::string>& files)
{
	std::vector<std::string> names;
	std::set<std::string> seen;
	bool clash = false;
	for (const auto& f : files)
	{
		names.push_back(std::filesystem::path(f).stem().string());
		clash = clash || !seen.insert(names.back()).second;
	}
	return clash ? files : names;
}

/// A TUM file as it is; KITTI poses (camera 0 in its frame at frame 0) moved onto the vehicle with the rig,
/// timed by the KITTI times file or 0.1 s apart.
Trajectory readInVehicleFrame(const std::string& path, const eval::EvalOptions& opts, const std::vector<double>& kitti_times)
{
	if (io::trajectoryFormatOf(path) == io::TrajectoryFormat::Tum) return io::readTum(path);
	if (!opts.cam0_T_vehicle)
		failInput(path, "KITTI poses (12 numbers a line) are camera 0's: give --kitti-calib or --cam0-T-vehicle to "
						"move them into the vehicle frame");
	return io::cameraToVehicle(io::readKittiPoses(path, kitti_times), *opts.cam0_T_vehicle);
}

/// Why the devkit's plots are missing: the KITTI metric's own note, or too few segments of every length.
std::string whyNoKittiPlots(const eval::EvalReport& r)
{
	if (!r.kitti_note.empty()) return r.kitti_note;
	std::ostringstream s;
	s.precision(4);
	s << "the devkit plots a segment length only with 3 segments of it, and the " << r.gt_length_m
	  << " m of ground truth over the matched poses give fewer (see --kitti-lengths)";
	return s.str();
}

int run(int argc, char** argv)
{
	const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 1,
		{{"gt", "GT", "ground truth: TUM (vehicle frame) or KITTI poses (camera 0, needs the rig)", true},
			{"est", "EST", "estimated trajectory, TUM or KITTI poses as --gt; repeat to compare several", true, true},
			{"kitti-times", "times.txt", "times of KITTI poses' lines (default 0.1 s apart from 0)"},
			{"metric", "kitti|ate|rpe|revisit|all", "metrics to compute (default all)"},
			{"align", "se3|sim3|none", "alignment before ATE/ARE (default se3; sim3 for unscaled monocular)"},
			{"json", "OUT.json", "also write the results as JSON"},
			{"max-dt", "S", "largest ground-truth gap to interpolate across, s (default 3x its median spacing)"},
			{"gt-translation-only", "", "ground-truth orientations are not valid (e.g. RTK): ATE only"},
			{"cam0-T-vehicle", "\"12 numbers\"", "rig, row-major 3x4: KITTI metric in camera 0"},
			{"kitti-calib", "calib.txt", "rig from the Tr line of a KITTI calib.txt: KITTI metric in camera 0"},
			{"kitti-lengths", "L1,L2,..", "KITTI segment lengths, m (default 100,200,...,800)"},
			{"kitti-step", "N", "KITTI first frames every N matched frames (default 10)"},
			{"revisit-radius", "M", "ground-truth positions this close are the same place, m (default 3)"},
			{"revisit-min-path", "M", "path between two visits of a place, m (default 50)"},
			{"write-aligned", "OUT.tum", "write the aligned, matched estimate (TUM)"},
			{"plots", "DIR", "write the KITTI devkit's error plots and the path coloured by ATE (PNG)"}},
		"vlo-eval --gt GT --est EST [--est EST2 ..] [options]\n\n"
		"Scores an estimated trajectory against ground truth: the KITTI odometry metric and\n"
		"ATE/ARE after Umeyama alignment, the frame-to-frame relative pose error, and the revisit\n"
		"error (the relative pose between two visits of a place). Files are TUM (8 numbers a line)\n"
		"or KITTI poses (12). See doc/EVALUATION.md.");
	eval::EvalOptions opts;
	opts.gt_name = cl.get("gt");
	eval::parseMetric(cl.get("metric", "all"), opts);
	opts.align = eval::parseAlignment(cl.get("align", "se3"));
	opts.association.max_gap_s = cl.getDouble("max-dt", 0);
	if (cl.has("max-dt") && !(opts.association.max_gap_s > 0)) failInput("--max-dt", "must be positive");
	opts.gt_translation_only = cl.has("gt-translation-only");
	if (cl.has("cam0-T-vehicle") && cl.has("kitti-calib"))
		failInput("command line", "give either --cam0-T-vehicle or --kitti-calib, not both");
	if (cl.has("cam0-T-vehicle")) opts.cam0_T_vehicle = eval::parseCam0TVehicle(cl.get("cam0-T-vehicle"));
	if (cl.has("kitti-calib")) opts.cam0_T_vehicle = eval::readKittiCalibTr(cl.get("kitti-calib"));
	if (cl.has("kitti-lengths")) opts.kitti_options.lengths = parseLengths(cl.get("kitti-lengths"));
	const long step = cl.getInt("kitti-step", 10);
	if (step < 1) failInput("--kitti-step", "must be at least 1");
	opts.kitti_options.step = static_cast<std::size_t>(step);
	opts.revisit_options.radius_m = cl.getDouble("revisit-radius", opts.revisit_options.radius_m);
	if (!(opts.revisit_options.radius_m > 0) || !std::isfinite(opts.revisit_options.radius_m))
		failInput("--revisit-radius", "must be a positive number of metres");
	opts.revisit_options.min_path_m = cl.getDouble("revisit-min-path", opts.revisit_options.min_path_m);
	if (!(opts.revisit_options.min_path_m >= 0) || !std::isfinite(opts.revisit_options.min_path_m))
		failInput("--revisit-min-path", "must be zero or a positive number of metres");

	const std::vector<std::string> est_files = cl.getAll("est");
	if (est_files.size() > 1)
		for (const char* single : {"json", "write-aligned"})
			if (cl.has(single)) failInput(std::string("--") + single, "needs a single --est");

	const std::vector<double> kitti_times = cl.has("kitti-times") ? io::readKittiTimes(cl.get("kitti-times")) : std::vector<double>{};
	const Trajectory gt = readInVehicleFrame(opts.gt_name, opts, kitti_times);
	const std::vector<std::string> names = runNames(est_files);
	std::vector<viz::EvalRun> runs;
	for (std::size_t i = 0; i < est_files.size(); ++i)
	{
		opts.est_name = est_files[i];
		runs.push_back({names[i], eval::evaluate(gt, readInVehicleFrame(est_files[i], opts, kitti_times), opts)});
	}
	for (const auto& run : runs)
	{
		for (const auto& w : run.report.warnings) logger().logStr(mrpt::system::LVL_WARN, w);
		if (runs.size() > 1) std::cout << (&run == &runs.front() ? "" : "\n") << "== " << run.name << " ==\n";
		std::cout << formatTable(run.report);
	}
	if (cl.has("plots"))  // first: a folder that cannot be made then leaves nothing behind
	{
		const std::string dir = cl.get("plots");
		const auto files = viz::writeEvalPlots(dir, runs);
		if (files.empty()) logger().logStr(mrpt::system::LVL_WARN, "--plots: nothing to plot (no KITTI segment, no ATE)");
		else if (std::none_of(files.begin(), files.end(), [](const std::string& f) { return f.rfind("kitti_", 0) == 0; }))
			logger().logStr(mrpt::system::LVL_WARN, "--plots: no KITTI devkit plots: " + whyNoKittiPlots(runs.front().report));
		for (const auto& f : files) std::cout << "vlo-eval: plot " << dir << "/" << f << "\n";
	}
	const eval::EvalReport& report = runs.front().report;
	if (cl.has("json")) eval::writeJson(cl.get("json"), report);
	if (cl.has("write-aligned")) io::writeTum(cl.get("write-aligned"), eval::alignedEstimate(report));
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	return runApp("vlo-eval", [&] { return run(argc, argv); });
}
