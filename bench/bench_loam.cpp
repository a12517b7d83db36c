// Milliseconds per frame of the LiDAR odometry stages on synthetic HDL-64E (~125k points) and
// VLP-16 (~26k points) scans of an urban street, one thread (CPU time is the figure to read on a
// busy machine).
//   build/bin/bench_loam [--benchmark_filter=Hdl64]
// Stages: preprocess (rings, timing), features, odometry (scan-to-scan incl. its search index),
// mapping (scan-to-map against a map built from the preceding frames, plus the map update), and
// the whole LidarOdometry::process() of consecutive frames.
#include <benchmark/benchmark.h>
#include <vlo/loam/lidar_odometry.h>

#include <map>

#include "urban_street_scans.h"

using namespace vlo;
using namespace vlo::loam;
using namespace vlo::loam::test;

namespace
{
constexpr int kFrames = 20;

struct Sequence
{
	LoamOptions opt;
	const std::vector<PointCloud>& scans;
};

const Sequence& sequence(bool hdl)
{
	if (hdl)
	{
		static const Sequence s{hdl64Options(), urbanStreetScans(true, kFrames)};
		return s;
	}
	static const Sequence s{vlp16Options(), urbanStreetScans(false, kFrames)};
	return s;
}

void BM_Preprocess(benchmark::State& state, bool hdl)
{
	const Sequence& seq = sequence(hdl);
	ScanPreprocessor pre(seq.opt.scan);
	int i = 0;
	for (auto _ : state) benchmark::DoNotOptimize(pre.process(seq.scans[i++ % kFrames]));
	state.counters["points"] = static_cast<double>(seq.scans[0].size());
}

void BM_Features(benchmark::State& state, bool hdl)
{
	const Sequence& seq = sequence(hdl);
	ScanPreprocessor pre(seq.opt.scan);
	FeatureExtractor fx(seq.opt.features);
	std::vector<RingScan> rs;
	for (const auto& s : seq.scans) rs.push_back(pre.process(s));
	int i = 0;
	for (auto _ : state) benchmark::DoNotOptimize(fx.extract(rs[i++ % kFrames]));
}

// Features of every frame, computed once.
std::vector<FeatureSet> features(const Sequence& seq)
{
	ScanPreprocessor pre(seq.opt.scan);
	FeatureExtractor fx(seq.opt.features);
	std::vector<FeatureSet> f;
	for (const auto& s : seq.scans) f.push_back(fx.extract(pre.process(s)));
	return f;
}

// Poses of every frame from a full run (the guesses below are constant-velocity ones, as in use).
const std::vector<Eigen::Isometry3d>& poses(bool hdl)
{
	static std::map<bool, std::vector<Eigen::Isometry3d>> cache;
	auto& p = cache[hdl];
	if (p.empty())
	{
		const Sequence& seq = sequence(hdl);
		LidarOdometry lo(seq.opt);
		for (int i = 0; i < kFrames; ++i) p.push_back(lo.process(0.1 * i, seq.scans[i], std::nullopt).pose);
	}
	return p;
}

Eigen::Isometry3d constantVelocityGuess(const std::vector<Eigen::Isometry3d>& p, int k)
{
	return k >= 2 ? p[k - 2].inverse() * p[k - 1] : Eigen::Isometry3d::Identity();
}

void BM_Odometry(benchmark::State& state, bool hdl)
{
	const Sequence& seq = sequence(hdl);
	const std::vector<FeatureSet> f = features(seq);
	const auto& p = poses(hdl);
	ScanToScanOdometry odo(seq.opt.odometry, ScanPreprocessor(seq.opt.scan).model());
	int i = 0;
	for (auto _ : state)
	{
		const int k = 2 + i++ % (kFrames - 2);
		odo.setReference(f[k - 1]);  // counted: the pipeline builds the index every frame
		benchmark::DoNotOptimize(odo.match(f[k], constantVelocityGuess(p, k)));
	}
}

void BM_Mapping(benchmark::State& state, bool hdl)
{
	const Sequence& seq = sequence(hdl);
	const auto& p = poses(hdl);
	const std::vector<FeatureSet> f = features(seq);
	ScanToMap mapper(seq.opt.mapping);
	for (int i = 0; i + 1 < kFrames; ++i) mapper.insert(f[i], p[i]);
	const int k = kFrames - 1;
	ScanToMap::Result r;
	for (auto _ : state)
	{
		r = mapper.align(mapper.prepare(f[k]), p[k - 1] * constantVelocityGuess(p, k));
		benchmark::DoNotOptimize(r);
		state.PauseTiming();
		ScanToMap copy = mapper;  // the update is measured on a copy so the map stays the same
		state.ResumeTiming();
		copy.insert(f[k], r.T_map_curr);
	}
	state.counters["edges"] = r.n_edges;
	state.counters["planes"] = r.n_planes;
	state.counters["map_points"] = static_cast<double>(mapper.edgeMap().numPoints() + mapper.planeMap().numPoints());
}

void BM_Frame(benchmark::State& state, bool hdl)
{
	const Sequence& seq = sequence(hdl);
	LidarOdometry lo(seq.opt);
	int i = 0;
	for (auto _ : state)
	{
		if (i == kFrames)
		{
			state.PauseTiming();
			lo.reset();
			i = 0;
			state.ResumeTiming();
		}
		benchmark::DoNotOptimize(lo.process(0.1 * i, seq.scans[i], std::nullopt));
		++i;
	}
}
}  // namespace

#define VLO_BENCH_SENSOR(name, hdl) \
	BENCHMARK_CAPTURE(BM_Preprocess, name, hdl)->Unit(benchmark::kMillisecond); \
	BENCHMARK_CAPTURE(BM_Features, name, hdl)->Unit(benchmark::kMillisecond); \
	BENCHMARK_CAPTURE(BM_Odometry, name, hdl)->Unit(benchmark::kMillisecond); \
	BENCHMARK_CAPTURE(BM_Mapping, name, hdl)->Unit(benchmark::kMillisecond); \
	BENCHMARK_CAPTURE(BM_Frame, name, hdl)->Unit(benchmark::kMillisecond)
VLO_BENCH_SENSOR(Hdl64, true);
VLO_BENCH_SENSOR(Vlp16, false);
BENCHMARK_MAIN();
