// What writing a run's whole-drive map costs in memory at the end of the run (issue 16): the peak resident
// memory each step adds over a GlobalMap holding N points, as vlo-run does it: hand the map to the outputs,
// write map.pcd, render snapshots/map3d.png. Not a Google Benchmark: it prints one markdown row.
// Usage: bench_output_memory [MILLION_POINTS (default 1.4: the 1.1 km urban drive)] [TMP_DIR (default /tmp)]
#include <vlo/io/pcd.h>
#include <vlo/pipeline/global_map.h>
#include <vlo/viz/map3d.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

using namespace vlo;

namespace
{
/// kB from /proc/self/status.
long statusKb(const char* key)
{
	std::ifstream in("/proc/self/status");
	std::string k;
	long v = 0;
	while (in >> k)
	{
		if (k == key)
		{
			in >> v;
			return v;
		}
		in.ignore(1 << 20, '\n');
	}
	return 0;
}

/// Resets the peak (VmHWM) to the current resident size (Linux >= 4.0).
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

/// Runs f and returns how far above the resident size before it the peak went [MB].
template <typename F>
double peakAbove(F&& f)
{
	resetPeak();
	const long before = statusKb("VmRSS:");
	f();
	return (statusKb("VmHWM:") - before) / 1024.0;
}
}  // namespace

int main(int argc, char** argv)
{
	const double million = argc > 1 ? std::atof(argv[1]) : 1.4;
	const std::string dir = argc > 2 ? argv[2] : "/tmp";
	const auto n = static_cast<std::size_t>(million * 1e6);
	if (!(million > 0) || million > 100) return std::fprintf(stderr, "bench_output_memory: MILLION_POINTS in (0, 100]\n"), 2;

	// A street-like map: scans 1 m apart, points on two facades and the ground out to 30 m, 0.2 m voxels.
	pipeline::GlobalMap map(0.2, 60);
	std::mt19937 rng(1);
	std::uniform_real_distribution<float> along(-30, 30), up(0, 12), across(-8, 8);
	Trajectory path;
	for (int k = 0; map.points().size() < n; ++k)
	{
		PointCloud scan(20000);
		for (std::size_t i = 0; i < scan.size(); ++i)
		{
			auto& p = scan[i];
			p.x = along(rng);
			p.y = i % 3 == 0 ? across(rng) : (i % 3 == 1 ? -8.f : 8.f);
			p.z = i % 3 == 0 ? -1.7f : up(rng);
		}
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation().x() = k;
		map.insert(scan, T);
		path.push_back({0.1 * k, T});
	}
	const double base = statusKb("VmRSS:") / 1024.0;

	PointCloud outputs;
	const double handOver = peakAbove([&] { outputs = map.takePoints(); });
	const double pcd = peakAbove([&] { io::writePcd(dir + "/bench_output_memory.pcd", outputs); });
	const double png = peakAbove([&] {
		viz::Map3DStyle style;
		style.title = "bench_output_memory";
		viz::renderMap3D(outputs, {{"path", path, std::nullopt}}, nullptr, dir + "/bench_output_memory.png", style);
	});
	std::printf("| map points | RSS with the map [MB] | + hand-over to the outputs | + map.pcd | + map3d.png |\n");
	std::printf("|---:|---:|---:|---:|---:|\n");
	std::printf("| %zu | %.0f | %.0f | %.0f | %.0f |\n", outputs.size(), base, handOver, pcd, png);
	return 0;
}
