// The loop closure's final optimisation (issue 33: under 2 s for 4000 keyframes): a pose graph of
// 4000 keyframes 2 m apart on a 500 m circuit driven 16 times, the odometry drifting (1 % scale,
// 0.02 deg/m of yaw), and 50 loop edges between visits of the same place with 2 cm / 0.05 deg of noise,
// optimised from the odometry as LoopClosure::finish() does, single-threaded.
//   build/bin/bench_loop
// Counters: Ceres iterations, and the RMS position error of the keyframes before and after.
// BM_PlaceQuery: one keyframe's place recognition (its Scan Context, the ring keys of 2000 earlier
// keyframes, 10 full descriptors), [loop] query_shift off (0) and on (3.5 m: three queries).
// BM_OdometryChainAdd: what addFrame adds per frame on the odometry's thread for the odometry edges
// (the frame's information inverted, its covariance composed onto the chain's).
#include <benchmark/benchmark.h>
#include <vlo/loop/odometry_chain.h>
#include <vlo/loop/place_recognition.h>
#include <vlo/loop/pose_graph.h>

#include <cmath>
#include <random>

using namespace vlo;
using namespace vlo::loop;

namespace
{
constexpr int kKeyframes = 4000, kPerLap = 250, kLoops = 50;
constexpr double kStep = 2.0, kDeg = M_PI / 180;

Eigen::Isometry3d circuitPose(int k)
{
	const double radius = kPerLap * kStep / (2 * M_PI), angle = 2 * M_PI * k / kPerLap;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(angle + M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	// A slope, so that the graph is not flat.
	T.translation() = Eigen::Vector3d(radius * std::cos(angle), radius * std::sin(angle), 5 * std::sin(3 * angle));
	return T;
}

struct Problem
{
	PoseGraph graph;
	std::vector<Eigen::Isometry3d> truth;
};

Problem buildProblem()
{
	Problem p;
	std::mt19937 rng(1);
	std::normal_distribution<double> n(0, 1);
	Eigen::Isometry3d odometry = circuitPose(0);
	for (int k = 0; k < kKeyframes; ++k)
	{
		p.truth.push_back(circuitPose(k));
		if (k > 0)
		{
			Eigen::Isometry3d step = p.truth[k - 1].inverse() * p.truth[k];
			step.translation() *= 1.01;
			step.linear() = Eigen::AngleAxisd(0.02 * kDeg * kStep, Eigen::Vector3d::UnitZ()) * step.linear();
			odometry = odometry * step;
			p.graph.addNode(odometry);
			p.graph.addEdge(k - 1, k, step, invertPositive(distanceCovariance(kStep, 0.01, 0.05 * kDeg)), 0);
		}
		else
			p.graph.addNode(odometry);
	}
	std::uniform_int_distribution<int> place(0, kPerLap - 1), lap(0, kKeyframes / kPerLap - 2);
	Matrix6d loop_information = Matrix6d::Zero();
	loop_information.diagonal() << 2500, 2500, 2500, 1.3e6, 1.3e6, 1.3e6;  // 2 cm, 0.05 deg
	for (int l = 0; l < kLoops; ++l)
	{
		const int a = place(rng) + kPerLap * lap(rng);
		const int b = a + kPerLap * (1 + lap(rng) % 3);
		if (b >= kKeyframes) continue;
		Eigen::Isometry3d measured = p.truth[a].inverse() * p.truth[b];
		measured.translation() += 0.02 * Eigen::Vector3d(n(rng), n(rng), n(rng));
		p.graph.addEdge(a, b, measured, loop_information, 1.0);
	}
	return p;
}

double rmsError(const Problem& p)
{
	double sum = 0;
	for (int k = 0; k < kKeyframes; ++k)
		sum += (p.graph.pose(k).translation() - p.truth[k].translation()).squaredNorm();
	return std::sqrt(sum / kKeyframes);
}

void BM_FinalOptimisation4000Keyframes(benchmark::State& state)
{
	PoseGraph::Summary summary;
	double before = 0, after = 0;
	std::size_t edges = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		Problem p = buildProblem();
		before = rmsError(p);
		edges = p.graph.edgeCount();
		state.ResumeTiming();
		summary = p.graph.optimise();
		state.PauseTiming();
		after = rmsError(p);
		state.ResumeTiming();
	}
	state.counters["iterations"] = summary.iterations;
	state.counters["edges"] = static_cast<double>(edges);
	state.counters["rms_before_m"] = before;
	state.counters["rms_after_m"] = after;
}
BENCHMARK(BM_FinalOptimisation4000Keyframes)->Unit(benchmark::kMillisecond)->Iterations(3);

/// A keyframe's thinned points: ground and walls at random within 80 m.
ScanPoints randomKeyframe(std::mt19937& rng, int points)
{
	std::uniform_real_distribution<float> u(-80.f, 80.f), h(-2.f, 10.f);
	ScanPoints out;
	for (int i = 0; i < points; ++i) out.emplace_back(u(rng), u(rng), i % 2 ? -2.f : h(rng));
	return out;
}

void BM_PlaceQuery(benchmark::State& state)
{
	PlaceRecognitionParams params;
	params.query_shift = static_cast<double>(state.range(0)) / 10;
	PlaceDatabase places(params);
	std::mt19937 rng(2);
	constexpr int kPoints = 20000;
	double path = 0;
	for (int k = 0; k < 2000; ++k, path += 2) places.addAndQuery(randomKeyframe(rng, kPoints), path);
	const ScanPoints query = randomKeyframe(rng, kPoints);
	for (auto _ : state) benchmark::DoNotOptimize(places.addAndQuery(query, path += 2));
}
BENCHMARK(BM_PlaceQuery)->Arg(0)->Arg(35)->Unit(benchmark::kMillisecond);
}  // namespace

void BM_OdometryChainAdd(benchmark::State& state)
{
	Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Random();
	const Matrix6d information = M * M.transpose() * 1e4 + Matrix6d::Identity();
	const Eigen::Isometry3d motion = circuitPose(1) * circuitPose(0).inverse();
	OdometryChain chain{LoopOptions{}};
	int n = 0;
	for (auto _ : state)
	{
		chain.add(motion, information);
		if (++n % 3 == 0) benchmark::DoNotOptimize(chain.take());
	}
}
BENCHMARK(BM_OdometryChainAdd)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
