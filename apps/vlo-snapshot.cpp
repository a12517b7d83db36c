// vlo-snapshot: offscreen PNG snapshots of a run's results, no display needed: a top-down view of
// trajectories (against ground truth), a 3D view of a point-cloud map, camera frames with the LiDAR
// scan projected. See doc/SNAPSHOTS.md.
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/io/pcd.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/projected_scan.h>
#include <vlo/viz/topdown.h>

#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

using namespace vlo;

namespace
{
/// The PNGs written so far: a failure later (a --frame beyond the rawlog) removes them, and the folder if
/// it made it, so that a failed call leaves nothing (issue 34, section 2).
struct Written
{
	std::vector<std::string> files;
	std::string made_dir;
	void removeAll() const
	{
		std::error_code ec;
		for (const auto& f : files) std::filesystem::remove(f, ec);
		if (!made_dir.empty()) std::filesystem::remove(made_dir, ec);  // only when empty
	}
};
Written written;

/// Runs f and prints "vlo-snapshot: wrote PATH (N ms)".
template <typename F>
void timed(const std::string& path, F&& f)
{
	const auto t0 = std::chrono::steady_clock::now();
	written.files.push_back(path);
	f();
	const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	std::cout << "vlo-snapshot: wrote " << path << " (" << long(ms) << " ms)" << std::endl;
}

std::set<long> frameIndices(const CommandLine& cl)
{
	std::set<long> ks;
	for (const auto& s : cl.getAll("frame"))
	{
		char* end = nullptr;
		const long k = std::strtol(s.c_str(), &end, 10);
		if (s.empty() || *end != '\0' || k < 0) failInput("--frame", "'" + s + "' is not a frame index (0, 1, ...)");
		ks.insert(k);
	}
	if (ks.empty()) ks.insert(0);
	return ks;
}

void projectedFrames(
	io::RawlogReader& reader, const std::string& rawlog, const std::set<long>& ks, const std::string& out)
{
	Frame f;
	long k = -1;
	for (long want : ks)
	{
		while (k < want)
		{
			if (!reader.next(f))
				failInput(rawlog, "has only " + std::to_string(k + 1) + " frames; --frame " + std::to_string(want) + " does not exist");
			++k;
		}
		if (!f.has_image || !f.has_scan)
			failInput(rawlog, "frame " + std::to_string(k) + " lacks " + (f.has_image ? "a LiDAR scan" : "an image"));
		char name[32];
		std::snprintf(name, sizeof(name), "/frame_%06ld.png", k);  // as vlo-run's snapshots
		const std::string png = out + name;
		viz::ProjectedScanStyle style;
		char t[48];
		std::snprintf(t, sizeof t, "  (t = %.3f s)", f.t);
		style.title = "frame " + std::to_string(k) + t;
		timed(png, [&] { viz::renderProjectedScan(f.image, f.scan, f.rig, png, {}, style); });
	}
}

/// Every PNG asked for, into `out`.
void draw(const CommandLine& cl, const std::vector<viz::NamedTrajectory>& trajs, const Trajectory* gtp, const PointCloud& map,
	const std::set<long>& frames, io::RawlogReader* reader, const std::string& out);

int run(int argc, char** argv)
{
	const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 1,
		{{"traj", "A.tum", "estimated trajectory (TUM, vehicle frame of frame 0)", false, true},
			{"name", "NAME", "legend name of the matching --traj, in order (default: file name)", false, true},
			{"gt", "GT.tum", "ground truth (TUM), drawn in grey"},
			{"map", "MAP.pcd", "point-cloud map (PCD, same frame as the trajectories)"},
			{"rawlog", "R.rawlog", "rawlog with CAMERA and LIDAR observations"},
			{"frame", "K", "frame index in --rawlog to draw with the projected scan (default 0)", false, true},
			{"title", "TEXT", "title above the top-down and 3D views"},
			{"out", "DIR", "output folder (created if missing)", true}},
		"vlo-snapshot --traj A.tum [--traj B.tum ...] [--name A ...] [--gt GT.tum]\n"
		"             [--map map.pcd] [--rawlog R.rawlog --frame K ...] --out DIR\n\n"
		"Writes DIR/topdown.png (trajectories, from above), DIR/map3d.png (map with\n"
		"trajectories, oblique) and DIR/frame_KKKKKK.png (image with the LiDAR scan projected).\n"
		"Headless: no display is needed. See doc/SNAPSHOTS.md.");
	const auto trajFiles = cl.getAll("traj"), names = cl.getAll("name");
	if (names.size() > trajFiles.size())
		failInput("--name",
			std::to_string(names.size()) + " names for " + std::to_string(trajFiles.size()) + " --traj files");
	if (cl.has("frame") && !cl.has("rawlog")) failInput("--frame", "needs --rawlog");
	if (trajFiles.empty() && !cl.has("gt") && !cl.has("map") && !cl.has("rawlog"))
		failInput("command line", "nothing to draw: give --traj, --gt, --map or --rawlog");

	// Read every input before writing anything, so that a bad file leaves no partial output.
	std::vector<viz::NamedTrajectory> trajs;
	for (size_t i = 0; i < trajFiles.size(); ++i)
	{
		Trajectory t = io::readTum(trajFiles[i]);
		if (t.empty()) failInput(trajFiles[i], "no poses");
		trajs.push_back({i < names.size() ? names[i] : mrpt::system::extractFileName(trajFiles[i]), std::move(t), {}});
	}
	Trajectory gt;
	if (cl.has("gt") && (gt = io::readTum(cl.get("gt"))).empty()) failInput(cl.get("gt"), "no poses");
	const Trajectory* gtp = cl.has("gt") ? &gt : nullptr;
	PointCloud map;
	if (cl.has("map") && (map = io::readPcd(cl.get("map"))).empty()) failInput(cl.get("map"), "no valid points");
	const std::set<long> frames = frameIndices(cl);
	std::unique_ptr<io::RawlogReader> reader;  // opened now: a missing or foreign file fails before any output
	if (cl.has("rawlog")) reader = std::make_unique<io::RawlogReader>(cl.get("rawlog"));

	const std::string out = cl.get("out");
	std::error_code ec;
	if (!std::filesystem::exists(out, ec)) written.made_dir = out;
	std::filesystem::create_directories(out, ec);
	if (ec || !std::filesystem::is_directory(out)) failInput(out, "cannot create the output folder");
	try
	{
		draw(cl, trajs, gtp, map, frames, reader.get(), out);
	}
	catch (...)
	{
		written.removeAll();
		throw;
	}
	return 0;
}

void draw(const CommandLine& cl, const std::vector<viz::NamedTrajectory>& trajs, const Trajectory* gtp, const PointCloud& map,
	const std::set<long>& frames, io::RawlogReader* reader, const std::string& out)
{
	if (!trajs.empty() || gtp)
	{
		viz::TopDownStyle style;
		style.title = cl.get("title");
		timed(out + "/topdown.png", [&] { viz::renderTopDown(trajs, gtp, out + "/topdown.png", style); });
	}
	if (cl.has("map"))
	{
		viz::Map3DStyle style;
		style.title = cl.get("title");
		timed(out + "/map3d.png", [&] { viz::renderMap3D(map, trajs, gtp, out + "/map3d.png", style); });
	}
	if (reader) projectedFrames(*reader, cl.get("rawlog"), frames, out);
}
}  // namespace

int main(int argc, char** argv)
{
	return runApp("vlo-snapshot", [&] { return run(argc, argv); });
}
