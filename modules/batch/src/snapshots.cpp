#include <vlo/batch/jobs.h>
#include <vlo/batch/snapshots.h>
#include <vlo/core/log.h>
#include <vlo/viz/topdown.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace vlo::batch
{
namespace
{
bool samePoses(const Trajectory& a, const Trajectory& b)
{
	return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const StampedPose& x, const StampedPose& y) {
		return x.t == y.t && x.pose.matrix() == y.pose.matrix();
	});
}

bool drawSequence(const Sequence& s, const std::vector<RunResult>& results, const std::string& png)
{
	const std::vector<viz::NamedTrajectory> trajs = sequenceTrajectories(s, results);
	if (trajs.empty()) return false;
	Trajectory gt;
	if (std::filesystem::is_regular_file(s.gt)) gt = io::readTum(s.gt);
	viz::TopDownStyle style;
	style.title = s.name + ": " + std::to_string(trajs.size()) + " trajectories";
	viz::renderTopDown(trajs, gt.empty() ? nullptr : &gt, png, style);
	return true;
}
}  // namespace

std::vector<viz::NamedTrajectory> sequenceTrajectories(const Sequence& s, const std::vector<RunResult>& results)
{
	std::vector<viz::NamedTrajectory> trajs;
	for (const auto& r : results)
	{
		if (r.sequence != s.name) continue;
		const std::size_t first = trajs.size();  // this run's
		for (const auto& t : r.trajectories)
		{
			// An unscaled monocular estimate means nothing next to metric ones before its Sim(3) alignment.
			const bool useAligned = !t.aligned.empty();
			const std::string file = useAligned ? t.aligned : r.dir + "/" + files::trajectory(t.name);
			Trajectory traj = io::readTum(file);
			const auto same = [&traj](const viz::NamedTrajectory& o) { return samePoses(o.traj, traj); };
			if (std::any_of(trajs.begin() + static_cast<std::ptrdiff_t>(first), trajs.end(), same)) continue;
			trajs.push_back({r.config + " / " + t.name + (useAligned ? " (Sim(3) aligned)" : ""), std::move(traj), std::nullopt});
		}
	}
	return trajs;
}

std::vector<std::string> writeSnapshots(const Plan& plan, const std::vector<RunResult>& results, const std::string& out)
{
	std::vector<std::string> written;
	std::filesystem::create_directories(out + "/snapshots");
	for (const auto& s : plan.sequences)
	{
		const std::string rel = "snapshots/" + s.name + ".png";
		try
		{
			if (drawSequence(s, results, out + "/" + rel)) written.push_back(rel);
		}
		catch (const std::exception& e)
		{
			std::string msg = e.what();
			logger().logStr(mrpt::system::LVL_WARN, rel + " not written: " + msg.substr(0, msg.find('\n')));
		}
	}
	return written;
}
}  // namespace vlo::batch
