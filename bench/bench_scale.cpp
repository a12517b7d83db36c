// Milliseconds per frame of the scale corrector at 1241x376 (KITTI) on a rendered textured street,
// with a synthetic HDL-64E (~100k points) or VLP-16 (~25k points) scan, on one core (OpenCV's
// thread pool set to 1 thread, as in the paper's single-core timing).
//   build/bin/bench_scale [--benchmark_filter=Hdl64]
// Stages: projection (eq. 1), keypoint selection (FAST + gradient + NMS), LK tracking (both
// pyramids + forward and backward), and the whole ScaleCorrector::estimate(). Counters: scan points,
// selected keypoints, RANSAC inliers.
#include <benchmark/benchmark.h>
#include <vlo/scale/projection.h>
#include <vlo/scale/scale_corrector.h>
#include <vlo/scale/selection.h>
#include <vlo/scale/tracking.h>

#include <opencv2/core/utility.hpp>

#include <map>
#include <memory>

#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::scale;
using namespace vlo::scale::test;

namespace
{
struct Case
{
	FramePair pair;
	ScaleOptions opt;
	Eigen::Isometry3d vo;  ///< the VO relative pose: translation 30 % too long
};

// Frames are rendered once per sensor and shared by every benchmark.
const Case& testCase(bool hdl)
{
	static std::map<bool, std::unique_ptr<Case>> cache;
	auto& c = cache[hdl];
	if (!c)
	{
		static const Scene scene = streetScene(3);
		c = std::make_unique<Case>();
		c->pair = makePair(scene, hdl ? hdl64() : vlp16());
		if (!hdl) c->opt.keypoint_test = KeypointTest::Fast12Pretest;
		c->vo = withScaledTranslation(c->pair.cur_T_prev, 1.3);
	}
	return *c;
}

std::vector<DepthPixel> project(const Case& c)
{
	return projectScan(c.pair.scan, c.pair.rig.camera, c.pair.rig.camera_T_lidar(), c.opt.min_depth, c.opt.max_depth,
		c.opt.border);
}

void BM_Projection(benchmark::State& state, bool hdl)
{
	const Case& c = testCase(hdl);
	for (auto _ : state) benchmark::DoNotOptimize(project(c));
	state.counters["points"] = static_cast<double>(c.pair.scan.size());
	state.counters["in_view"] = static_cast<double>(project(c).size());
}

void BM_Selection(benchmark::State& state, bool hdl)
{
	const Case& c = testCase(hdl);
	const auto projected = project(c);
	for (auto _ : state) benchmark::DoNotOptimize(selectKeypoints(c.pair.prev, projected, c.opt));
	state.counters["selected"] = static_cast<double>(selectKeypoints(c.pair.prev, projected, c.opt).size());
}

void BM_Tracking(benchmark::State& state, bool hdl)
{
	const Case& c = testCase(hdl);
	const auto projected = project(c);
	std::vector<cv::Point2f> pts;
	for (const auto& k : selectKeypoints(c.pair.prev, projected, c.opt)) pts.push_back(projected[k.projected].px);
	for (auto _ : state) benchmark::DoNotOptimize(trackPoints(c.pair.prev, c.pair.cur, pts, c.opt));
	state.counters["keypoints"] = static_cast<double>(pts.size());
}

void BM_Corrector(benchmark::State& state, bool hdl)
{
	const Case& c = testCase(hdl);
	const ScaleCorrector corrector(c.opt);
	ScaleEstimate e;
	for (auto _ : state)
		e = corrector.estimate(
			c.pair.prev, c.pair.scan, c.pair.cur, c.pair.rig.camera, c.pair.rig.camera_T_lidar(), c.vo);
	state.counters["points"] = static_cast<double>(c.pair.scan.size());
	state.counters["selected"] = e.counts.selected;
	state.counters["inliers"] = e.counts.inliers;
	state.counters["scale_err_pct"] = 100 * (e.scale * 1.3 - 1);
}
}  // namespace

BENCHMARK_CAPTURE(BM_Projection, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Selection, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Tracking, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Corrector, Hdl64, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Projection, Vlp16, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Selection, Vlp16, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Tracking, Vlp16, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Corrector, Vlp16, false)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv)
{
	cv::setNumThreads(1);
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
