#include <vlo/core/atomic_file.h>
#include <vlo/core/build_info.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/io/pcd.h>
#include <vlo/pipeline/run_outputs.h>
#include <vlo/viz/run_snapshots.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vlo::pipeline
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
	io::writeTum(dir + "/trajectory_" + name + ".tum", traj);
	if (cam0_T_vehicle && traj.size() == frames)
		io::writeKittiPoses(dir + "/trajectory_" + name + ".kitti.txt", io::vehicleToCamera(relativeToFirst(traj), *cam0_T_vehicle));
}
}  // namespace

void RunOutputs::addSampleFrame(const Frame& f)
{
	Frame copy = f;
	copy.image = f.image.makeDeepCopy();  // the reader may reuse the image buffer
	sample_frames.offer(std::move(copy));
}

void RunOutputs::setMotion(const kernel::MotionSource& source)
{
	motion = source.trajectory();
	const double last_t = table.numbers("t").back();
	while (!motion.empty() && motion.back().t > last_t + 1e-9) motion.pop_back();
	motion_label = source.label();
	figures = source.figures();
}

void RunOutputs::setLoops(const loop::LoopClosure& closure)
{
	slam = closure.corrected();
	if (slam.size() != lidar.size())
		throw std::logic_error("loop closure: " + std::to_string(slam.size()) + " corrected poses for " +
			std::to_string(lidar.size()) + " frames");
	loops = closure.loops();
	std::size_t accepted = 0;
	for (const auto& l : loops)
	{
		const auto row = frameRow(l.frame);
		if (!row) continue;  // a frame after the rows kept (a run stopped early)
		kernel::FrameTable cells;
		cells.set("loop_candidate", l.candidate_frame);
		cells.set("loop_distance", l.descriptor_distance, 3);
		cells.set("loop_yaw_deg", l.yaw_deg, 1);
		cells.set("loop_inliers", l.inlier_fraction, 3);
		cells.set("loop_rms", l.rms, 3);
		cells.set("loop_accepted", l.accepted);
		if (!l.accepted) cells.set("loop_rejected", l.reason);
		table.setCellsAt(*row, cells);
		accepted += l.accepted;
	}
	figures.push_back({"loop_keyframes", static_cast<double>(closure.keyframes())});
	figures.push_back({"loop_candidates", static_cast<double>(loops.size())});
	figures.push_back({"loops_accepted", static_cast<double>(accepted)});
	figures.push_back({"loop_final_optimisation_s", closure.finalOptimisationSeconds()});
}

std::optional<std::size_t> RunOutputs::frameRow(long long frame) const
{
	const std::vector<double> frames = table.numbers("frame");
	const auto row = std::find(frames.begin(), frames.end(), static_cast<double>(frame));
	if (row == frames.end()) return std::nullopt;
	return static_cast<std::size_t>(row - frames.begin());
}

std::vector<Eigen::Isometry3d> RunOutputs::loopCorrections() const
{
	std::vector<Eigen::Isometry3d> c;
	c.reserve(slam.size());
	for (std::size_t i = 0; i < slam.size() && i < lidar.size(); ++i) c.push_back(slam[i].pose * lidar[i].pose.inverse());
	return c;
}

RunSummary RunOutputs::write(const std::string& dir, const std::string& effectiveIni) const
{
	RunSummary s;
	s.mode = plan.name;
	const Trajectory& finalTraj = plan.lidar_odometry ? lidar : motion;
	s.final_trajectory = "trajectory_" + plan.name + ".tum";
	if (!lidar.empty()) writeTrajectory(dir, plan.name, lidar, cam0_T_vehicle, table.rows());
	if (!motion.empty()) writeTrajectory(dir, "vo", motion, cam0_T_vehicle, table.rows());
	if (!slam.empty())
	{
		writeTrajectory(dir, "slam", slam, cam0_T_vehicle, table.rows());
		s.slam_trajectory = "trajectory_slam.tum";
	}
	s.path_length_m = pathLength(finalTraj);
	s.max_step_m = maxStep(finalTraj);
	s.figures = figures;
	table.write(dir + "/frames.csv");
	if (!map.empty()) io::writePcd(dir + "/map.pcd", map);
	AtomicOutputFile ini(dir + "/run.ini");
	const BuildInfo& b = buildInfo();
	ini.stream() << "# Effective options of this run (defaults included).\n# Written by vlo " << b.version << ", git "
				 << b.git_commit << ", " << b.build_type << " build.\n"
				 << effectiveIni;
	ini.commit();
	return s;
}

void writeSnapshots(const std::string& dir, const RunOutputs& o, const kernel::MotionSource* motion, const std::string& gtPath)
{
	viz::RunSnapshots run;
	run.mode = o.plan.name;
	run.frames = o.table.rows();
	if (!o.slam.empty()) run.trajectories.push_back({"loop-closed (" + o.plan.lidar_label + " + loops)", o.slam, std::nullopt});
	if (!o.lidar.empty()) run.trajectories.push_back({o.plan.lidar_label, o.lidar, std::nullopt});
	for (const auto& l : o.loops)
	{
		if (!l.accepted) continue;
		const auto a = o.frameRow(l.candidate_frame), b = o.frameRow(l.frame);
		if (a && b && *a < o.lidar.size() && *b < o.lidar.size())
			run.loops.push_back({o.lidar[*a].pose.translation(), o.lidar[*b].pose.translation()});
	}
	if (!o.motion.empty()) run.trajectories.push_back({o.motion_label, o.motion, std::nullopt});
	run.gt_path = gtPath;
	const std::vector<double> t = o.table.numbers("t");
	run.t_first = t.front(), run.t_last = t.back();
	try
	{
		viz::renderRunSnapshots(dir, std::move(run), o.map, o.sample_frames.items());
		if (motion) motion->writeSnapshots(dir);
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
	if (!s.slam_trajectory.empty()) j["trajectory_slam"] = s.slam_trajectory;
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
}  // namespace vlo::pipeline
