// Milliseconds of the monocular VO at 1241x376, one thread: feature extraction per frame (each
// detector), tracking per frame, local mapping per keyframe, over a drive.
//   build/bin/bench_vo                                   rendered street (60 frames)
//   VLO_BENCH_RAWLOG=X.rawlog build/bin/bench_vo          also a real sequence (e.g. KITTI 06)
// Sequence benchmarks report counters: extract_ms and track_ms per frame, mapping_ms per keyframe,
// mapping_max_ms, keyframes and tracked frames per run. Repeatability: the fraction of features
// found again after a 6 x 4 px image shift (on the rawlog's middle frame when one is given).
#include <benchmark/benchmark.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/vo/orb_extractor.h>
#include <vlo/vo/visual_odometry.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
// One thread, as the per-frame budget is counted: OpenCV would otherwise use its TBB pool.
const bool kOneThread = [] {
	cv::setNumThreads(1);
	return true;
}();

struct Sequence
{
	PinholeCamera cam;
	std::vector<cv::Mat> images;
	std::vector<double> times;
};

const Sequence& street()
{
	static std::unique_ptr<Sequence> s;
	if (!s)
	{
		s = std::make_unique<Sequence>();
		s->cam = test::kittiCamera();
		test::StreetRenderer r(test::StreetScene(), s->cam);
		for (int k = 0; k < 60; ++k)
		{
			s->images.push_back(r.render(test::drivePose(k)));
			s->times.push_back(0.1 * k);
		}
	}
	return *s;
}

const Sequence* rawlog()
{
	static std::unique_ptr<Sequence> s;
	const char* path = std::getenv("VLO_BENCH_RAWLOG");
	if (!s && path)
	{
		s = std::make_unique<Sequence>();
		io::RawlogReaderOptions ro;
		ro.need_lidar = false;
		io::RawlogReader reader(path, ro);
		Frame f;
		while (reader.next(f))
		{
			s->cam = f.rig.camera;
			s->images.push_back(f.image.asCvMatRef().clone());
			s->times.push_back(f.t);
		}
	}
	return s.get();
}

void BM_Extract(benchmark::State& state, const char* detector)
{
	const Sequence& seq = street();
	OrbOptions opt;
	opt.detector = detector;
	const OrbExtractor ex(opt);
	std::size_t i = 0, n = 0;
	for (auto _ : state)
	{
		const Features f = ex.extract(seq.images[i++ % seq.images.size()]);
		n += f.size();
		benchmark::DoNotOptimize(f.keys.data());
	}
	state.counters["features"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kAvgIterations);
}

/// Fraction of features found again, at the same level and place with a descriptor distance <= 50,
/// after the image is shifted by (6, 4) px: how repeatable a detector's selection is.
double repeatability(const OrbExtractor& ex, const cv::Mat& img)
{
	const cv::Mat M = (cv::Mat_<double>(2, 3) << 1, 0, 6, 0, 1, 4);
	cv::Mat shifted;
	cv::warpAffine(img, shifted, M, img.size());
	const Features a = ex.extract(img), b = ex.extract(shifted);
	int n = 0, found = 0;
	for (std::size_t i = 0; i < a.size(); ++i)
	{
		const cv::KeyPoint& k = a.keys[i];
		if (k.pt.x > img.cols - 40 || k.pt.y > img.rows - 40) continue;  // shifted out of view
		++n;
		int best = 256;
		for (int j : b.grid.inArea(k.pt.x + 6, k.pt.y + 4, 1.5 * std::pow(1.2, k.octave), k.octave, k.octave))
			best = std::min(best, hamming(a.descriptor(i), b.descriptor(static_cast<std::size_t>(j))));
		found += best <= 50;
	}
	return n ? static_cast<double>(found) / n : 0.0;
}

void BM_Repeatability(benchmark::State& state, const char* detector)
{
	OrbOptions opt;
	opt.detector = detector;
	const OrbExtractor ex(opt);
	const Sequence* real = rawlog();
	const cv::Mat& img = real && !real->images.empty() ? real->images[real->images.size() / 2] : street().images[30];
	double r = 0;
	for (auto _ : state) r = repeatability(ex, img);
	state.counters["repeat"] = r;
}

void runSequence(benchmark::State& state, const Sequence& seq, const char* detector)
{
	double extract = 0, track = 0, mapping = 0, mapping_max = 0;
	long frames = 0, kfs = 0, tracked = 0;
	for (auto _ : state)
	{
		VoOptions opt;
		opt.orb.detector = detector;
		VisualOdometry vo(seq.cam, opt);
		for (std::size_t k = 0; k < seq.images.size(); ++k)
		{
			const VoFrameInfo i = vo.process(seq.images[k], seq.times[k]);
			extract += i.ms.ms("extract");
			track += i.ms.ms("track");
			++frames;
			tracked += i.pose.has_value();
			if (i.keyframe && !i.new_map)
			{
				mapping += i.ms.ms("mapping");
				mapping_max = std::max(mapping_max, i.ms.ms("mapping"));
				++kfs;
			}
		}
	}
	state.counters["extract_ms"] = extract / std::max(frames, 1L);
	state.counters["track_ms"] = track / std::max(frames, 1L);
	state.counters["mapping_ms"] = mapping / std::max(kfs, 1L);
	state.counters["mapping_max_ms"] = mapping_max;
	state.counters["keyframes"] = static_cast<double>(kfs) / static_cast<double>(state.iterations());
	state.counters["tracked"] = static_cast<double>(tracked) / static_cast<double>(state.iterations());
}

void BM_Street(benchmark::State& state, const char* detector) { runSequence(state, street(), detector); }

void BM_Rawlog(benchmark::State& state, const char* detector)
{
	const Sequence* seq = rawlog();
	if (!seq || seq->images.empty())
	{
		state.SkipWithError("set VLO_BENCH_RAWLOG to a rawlog with camera images");
		for (auto _ : state) {}
		return;
	}
	runSequence(state, *seq, detector);
}
}  // namespace

BENCHMARK_CAPTURE(BM_Extract, anms, "anms")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Extract, quadtree, "quadtree")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Extract, opencv, "opencv")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Repeatability, anms, "anms")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Repeatability, quadtree, "quadtree")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Repeatability, opencv, "opencv")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Street, anms, "anms")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_Street, opencv, "opencv")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_Rawlog, anms, "anms")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_Rawlog, quadtree, "quadtree")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(BM_Rawlog, opencv, "opencv")->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
