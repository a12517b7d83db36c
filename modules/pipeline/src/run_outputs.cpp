#include <vlo/core/atomic_file.h>
#include <vlo/core/build_info.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/eval/association.h>
#include <vlo/eval/umeyama.h>
#include <vlo/io/pcd.h>
#include <vlo/pipeline/run_outputs.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/projected_scan.h>
#include <vlo/viz/topdown.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace vlo
{
namespace
{
double maxStep(const Trajectory& t)
{
	double m = 0;
	for (std::size_t i = 1; i < t.size(); ++i)
		m = std::max(m, (t[i].pose.translation() - t[i - 1].pose.translation()).norm());
	return m;
}

/// trajectory_<name>.tum, and with KITTI's camera 0 known trajectory_<name>.kitti.txt: the poses of camera 0
/// in its frame at the first frame, as the KITTI devkit reads them. The devkit pairs poses by line, so only a
/// trajectory with a pose for each of the run's frames gets one (not a VO that started late or got lost).
void writeTrajectory(const std::string& dir, const std::string& name, const Trajectory& traj,
	const std::optional<Eigen::Isometry3d>& cam0_T_vehicle, std::size_t frames)
{
	writeTum(dir + "/trajectory_" + name + ".tum", traj);
	if (cam0_T_vehicle && traj.size() == frames)
		writeKittiPoses(dir + "/trajectory_" + name + ".kitti.txt", vehicleToCamera(relativeToFirst(traj), *cam0_T_vehicle));
}

/// Mode vo alone: the VO's path is in map units, so it is Sim(3)-aligned to the ground truth when there is
/// one, and says so; without one, the legend and title say "unscaled" and lengths and axes are in map units.
void presentUnscaledVo(NamedTrajectory& vo, const Trajectory& gt, TopDownStyle& style)
{
	const Association a = associate(gt, vo.traj);
	if (a.matched() >= 3)
	{
		std::vector<Eigen::Vector3d> src, dst;
		for (std::size_t i = 0; i < a.matched(); ++i)
			src.push_back(a.est[i].pose.translation()), dst.push_back(a.gt[i].pose.translation());
		const Sim3 S = umeyama(src, dst, true);
		for (auto& p : vo.traj)
		{
			p.pose.translation() = S * Eigen::Vector3d(p.pose.translation());
			p.pose.linear() = S.R * p.pose.linear();
		}
		vo.name += " (Sim(3)-aligned to the ground truth)";
		style.title += ", VO unscaled: Sim(3)-aligned to the ground truth";
		return;
	}
	vo.name += " (unscaled)";
	style.title += ", VO unscaled (map units, not metres)";
	style.unit = "map units";
}

/// Snapshots are a convenience: a failure to render is reported, not fatal to the run.
void writeSnapshots(const std::string& dir, const RunOutputs& o, const std::string& gtPath)
{
	std::filesystem::create_directories(dir);
	Trajectory gt;
	if (!gtPath.empty())
	{
		// Only the part of the ground truth the run covered (it may have stopped early).
		const double t0 = o.table.numbers("t").front() - 1e-6, t1 = o.table.numbers("t").back() + 1e-6;
		for (const auto& p : readTum(gtPath))
			if (p.t >= t0 && p.t <= t1) gt.push_back(p);
		gt = relativeToFirst(gt);
	}
	std::vector<NamedTrajectory> trajs;
	if (!o.lidar.empty()) trajs.push_back({o.plan.lidar_label, o.lidar, std::nullopt});
	if (o.motion_source && !o.motion_source->trajectory().empty())
		trajs.push_back({o.motion_source->label(), o.motion_source->trajectory(), std::nullopt});
	if (trajs.empty()) return;
	TopDownStyle td;
	td.title = "vlo-run (" + o.plan.name + "), " + std::to_string(o.table.rows()) + " frames";
	if (o.plan.name == "vo") presentUnscaledVo(trajs.back(), gt, td);
	renderTopDown(trajs, gt.empty() ? nullptr : &gt, dir + "/topdown.png", td);
	if (!o.map.empty())
	{
		Map3DStyle ms;
		ms.title = "map and trajectory";
		renderMap3D(o.map, trajs, gt.empty() ? nullptr : &gt, dir + "/map3d.png", ms);
	}
	for (const auto& f : o.sample_frames.items())
	{
		if (!f.has_image || !f.has_scan) continue;
		ProjectedScanStyle ps;
		char t[48];
		std::snprintf(t, sizeof t, "  (t = %.3f s)", f.t);  // as vlo-snapshot's
		ps.title = "frame " + std::to_string(f.index) + t;
		char name[64];
		std::snprintf(name, sizeof(name), "/frame_%06zu.png", f.index);
		renderProjectedScan(f.image, f.scan, f.rig, dir + name, {}, ps);
	}
	if (o.motion_source) o.motion_source->writeSnapshots(dir);
}
}  // namespace

void RunOutputs::addSampleFrame(const Frame& f)
{
	Frame copy = f;
	copy.image = f.image.makeDeepCopy();  // the reader may reuse the image buffer
	sample_frames.offer(std::move(copy));
}

RunSummary RunOutputs::write(
	const std::string& dir, const PipelineOptions& opt, const std::string& effectiveIni, const std::string& gtPath) const
{
	RunSummary s;
	s.mode = plan.name;
	Trajectory motion = motion_source ? motion_source->trajectory() : Trajectory{};
	// A run stopped early with two threads: the motion source may be a few frames past the last row.
	const double last_t = table.numbers("t").back();
	while (!motion.empty() && motion.back().t > last_t + 1e-9) motion.pop_back();
	const Trajectory& finalTraj = plan.lidar_odometry ? lidar : motion;
	s.final_trajectory = "trajectory_" + plan.name + ".tum";
	if (!lidar.empty()) writeTrajectory(dir, plan.name, lidar, cam0_T_vehicle, table.rows());
	if (!motion.empty()) writeTrajectory(dir, "vo", motion, cam0_T_vehicle, table.rows());
	s.path_length_m = pathLength(finalTraj);
	s.max_step_m = maxStep(finalTraj);
	if (motion_source) s.figures = motion_source->figures();
	table.write(dir + "/frames.csv");
	if (!map.empty()) writePcd(dir + "/map.pcd", map);
	{
		AtomicOutputFile ini(dir + "/run.ini");
		const BuildInfo& b = buildInfo();
		ini.stream() << "# Effective options of this run (defaults included).\n# Written by vlo " << b.version << ", git "
					 << b.git_commit << ", " << b.build_type << " build.\n"
					 << effectiveIni;
		ini.commit();
	}
	if (opt.snapshots)
	{
		try
		{
			writeSnapshots(dir + "/snapshots", *this, gtPath);
		}
		catch (const InputError&)
		{
			throw;  // a bad --gt file is the user's to fix
		}
		catch (const std::exception& e)
		{
			logger().logStr(mrpt::system::LVL_WARN, std::string("snapshots not written: ") + e.what());
		}
	}
	return s;
}

void writeSummaryJson(const std::string& path, const RunSummary& s, const RunRequest& req)
{
	// Keys in this order; a NaN or infinite figure is written as null (doc/FORMATS.md).
	const BuildInfo& b = buildInfo();
	nlohmann::ordered_json j = {{"mode", s.mode}, {"rawlog", req.rawlog}, {"ini", req.ini}, {"version", b.version},
		{"git_commit", b.git_commit}, {"build_type", b.build_type}, {"complete", s.complete},
		{"stop_reason", s.complete ? nlohmann::ordered_json() : nlohmann::ordered_json(s.stop_reason)},
		{"last_frame", s.last_frame}, {"frames", s.frames},
		{"seconds", s.seconds}, {"ms_per_frame", s.ms_per_frame}, {"path_length_m", s.path_length_m},
		{"max_step_m", s.max_step_m}, {"trajectory", s.final_trajectory}, {"reader", s.reader_stats}};
	for (const auto& [key, value] : s.figures)
	{
		// A module's figures are doubles; whole numbers (counts) are written as integers, as readers expect.
		if (std::isfinite(value) && std::fabs(value) < 9.0e15 && value == std::floor(value))
			j[key] = static_cast<long long>(value);
		else
			j[key] = value;
	}
	j["stage_timings"] = nlohmann::ordered_json::array();
	for (const auto& t : s.stage_timings)
		j["stage_timings"].push_back(
			{{"stage", t.stage}, {"mean_ms", t.mean}, {"p95_ms", t.p95}, {"max_ms", t.max}, {"frames", t.count}});
	AtomicOutputFile f(path);
	f.stream() << j.dump(2) << "\n";
	f.commit();
}
}  // namespace vlo
