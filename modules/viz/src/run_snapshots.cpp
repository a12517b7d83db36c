#include <vlo/eval/trajectory_alignment.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/projected_scan.h>
#include <vlo/viz/run_snapshots.h>

#include <cstdio>
#include <filesystem>

namespace vlo::viz
{
namespace
{
/// Only the part of the ground truth the run covered (it may have stopped early), from its first pose there.
Trajectory groundTruthOf(const RunSnapshots& run)
{
	Trajectory gt;
	if (run.gt_path.empty()) return gt;
	const double t0 = run.t_first - 1e-6, t1 = run.t_last + 1e-6;
	for (const auto& p : io::readTum(run.gt_path))
		if (p.t >= t0 && p.t <= t1) gt.push_back(p);
	return relativeToFirst(gt);
}

/// Mode vo alone: the VO's path is in map units.
void presentUnscaledVo(NamedTrajectory& vo, const Trajectory& gt, TopDownStyle& style)
{
	if (const auto S = eval::sim3ToGroundTruth(gt, vo.traj))
	{
		vo.traj = eval::transformed(std::move(vo.traj), *S);
		vo.name += " (Sim(3)-aligned to the ground truth)";
		style.title += ", VO unscaled: Sim(3)-aligned to the ground truth";
		return;
	}
	vo.name += " (unscaled)";
	style.title += ", VO unscaled (map units, not metres)";
	style.unit = "map units";
}

void renderSampleFrame(const std::string& dir, const Frame& f)
{
	ProjectedScanStyle ps;
	char t[48];
	std::snprintf(t, sizeof t, "  (t = %.3f s)", f.t);  // as vlo-snapshot's
	ps.title = "frame " + std::to_string(f.index) + t;
	char name[64];
	std::snprintf(name, sizeof(name), "/frame_%06zu.png", f.index);
	renderProjectedScan(f.image, f.scan, f.rig, dir + name, {}, ps);
}
}  // namespace

void renderRunSnapshots(const std::string& dir, RunSnapshots run, const PointCloud& map, const std::vector<Frame>& samples)
{
	std::filesystem::create_directories(dir);
	const Trajectory gt = groundTruthOf(run);
	auto& trajs = run.trajectories;
	if (trajs.empty()) return;
	TopDownStyle td;
	td.title = "vlo-run (" + run.mode + "), " + std::to_string(run.frames) + " frames";
	if (run.mode == "vo") presentUnscaledVo(trajs.back(), gt, td);
	td.links = run.loops;
	renderTopDown(trajs, gt.empty() ? nullptr : &gt, dir + "/topdown.png", td);
	if (!map.empty())
	{
		Map3DStyle ms;
		ms.title = "map and trajectory";
		renderMap3D(map, trajs, gt.empty() ? nullptr : &gt, dir + "/map3d.png", ms);
	}
	for (const auto& f : samples)
		if (f.has_image && f.has_scan) renderSampleFrame(dir, f);
}
}  // namespace vlo::viz
