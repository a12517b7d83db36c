// Milliseconds per frame of KISS-ICP's method (modules/icp) beside A-LOAM (modules/loam) on the same
// synthetic HDL-64E (~125k points) and VLP-16 (~26k points) scans of an urban street, one thread
// (CPU time is the figure to read on a busy machine).
//   build/bin/bench_icp [--benchmark_filter=Hdl64]
// Counters of the ICP rows: wall milliseconds of its stages (preprocess = deskew, crop, two voxel
// downsamplings; registration; map update), averaged over the frames run.
#include <benchmark/benchmark.h>
#include <vlo/icp/icp_odometry.h>
#include <vlo/loam/lidar_odometry.h>

#include <memory>

#include "urban_street_scans.h"

using namespace vlo;
using namespace vlo::loam::test;

namespace
{
constexpr int kFrames = 20;

const std::vector<PointCloud>& scans(bool hdl) { return urbanStreetScans(hdl, kFrames); }

/// Runs `process(i)` on frames 0..kFrames-1 over and over, rebuilding the odometry between rounds.
template <class Odometry, class MakeOdometry, class Process>
void runFrames(benchmark::State& state, MakeOdometry make, Process process)
{
	std::unique_ptr<Odometry> odo = make();
	int i = 0;
	for (auto _ : state)
	{
		if (i == kFrames)
		{
			state.PauseTiming();
			odo = make();
			i = 0;
			state.ResumeTiming();
		}
		process(*odo, i++);
	}
}

void BM_IcpFrame(benchmark::State& state, bool hdl)
{
	const auto& s = scans(hdl);
	double features = 0, mapping = 0, iterations = 0;
	int n = 0;
	runFrames<icp::IcpOdometry>(
		state, [] { return std::make_unique<icp::IcpOdometry>(icp::IcpOptions{}); },
		[&](icp::IcpOdometry& odo, int i) {
			const icp::IcpResult r = odo.process(0.1 * i, s[i], std::nullopt);
			features += r.ms.ms("features");
			mapping += r.ms.ms("mapping");
			iterations += r.registration.iterations;
			++n;
		});
	state.counters["ms_features"] = features / n;
	state.counters["ms_mapping"] = mapping / n;
	state.counters["iterations"] = iterations / n;
}

void BM_AloamFrame(benchmark::State& state, bool hdl)
{
	const auto& s = scans(hdl);
	runFrames<loam::LidarOdometry>(
		state, [hdl] { return std::make_unique<loam::LidarOdometry>(hdl ? hdl64Options() : vlp16Options()); },
		[&](loam::LidarOdometry& lo, int i) { benchmark::DoNotOptimize(lo.process(0.1 * i, s[i], std::nullopt)); });
}
}  // namespace

BENCHMARK_CAPTURE(BM_IcpFrame, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AloamFrame, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IcpFrame, Vlp16, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AloamFrame, Vlp16, false)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
