// Not a Google Benchmark: the loop closure on a recorded drive that revisits places (doc/LOOP.md's
// "Accuracy on a simulated revisit"). The drive's ground truth, given a drift (scale and a yaw bias
// per metre), stands for the odometry; every frame goes through LoopClosure as the pipeline feeds it,
// with point times from the azimuth ([lidar] point_times = auto) unless --no-times. Prints every
// candidate, what addFrame cost, and the revisit error (frame pairs within 3 m, 100 frames apart).
//   build/bin/bench_loop_revisit RAWLOG GT.tum [scale=1.005] [yaw_deg_per_100m=0.5] [--no-times]
// A revisit of KITTI 00's start (frames 0-150, then 4380-4540; poses from ../shared/data's
// kitti_gt_poses.tar.xz):
//   (sed -n 1,151p 00.txt; sed -n 4381,4541p 00.txt) > revisit.txt
//   build/bin/vlo-sim --trajectory revisit.txt --frames 312 --out rev.rawlog
//   build/bin/bench_loop_revisit rev.rawlog rev.gt.tum 1.01 1
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/pipeline/lidar_options.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "synthetic_places.h"  // driftingOdometry, revisitError

using namespace vlo;
int main(int argc, char** argv)
{
	std::vector<std::string> args(argv + 1, argv + argc);
	const bool times = std::find(args.begin(), args.end(), "--no-times") == args.end();
	args.erase(std::remove(args.begin(), args.end(), "--no-times"), args.end());
	if (args.size() < 2)
	{
		std::fprintf(stderr, "usage: bench_loop_revisit RAWLOG GT.tum [scale] [yaw_deg_per_100m] [--no-times]\n");
		return 2;
	}
	const std::string rawlog = args[0], gt = args[1];
	const double scale = args.size() > 2 ? std::atof(args[2].c_str()) : 1.005;
	const double bias_deg_per_100m = args.size() > 3 ? std::atof(args[3].c_str()) : 0.5;
	const Trajectory truth = io::readTum(gt);
	const Trajectory odo = loop::test::driftingOdometry(truth, scale, bias_deg_per_100m * M_PI / 180 / 100);
	io::RawlogReaderOptions ro;
	ro.need_camera = false;
	io::RawlogReader reader(rawlog, ro);
	loop::LoopOptions opt;
	loop::LoopClosure lc(opt);
	Frame f;
	std::size_t i = 0;
	double add_ms = 0, max_add = 0;
	while (reader.next(f) && i < truth.size())
	{
		if (times) pipeline::applyLidarOptions(f.scan, pipeline::LidarOptions{});
		const auto t0 = std::chrono::steady_clock::now();
		lc.addFrame(static_cast<long long>(i), f.t, odo[i].pose, std::nullopt, f.scan, f.rig.vehicle_T_lidar);
		const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
		add_ms += ms;
		max_add = std::max(max_add, ms);
		++i;
	}
	const auto t0 = std::chrono::steady_clock::now();
	lc.finish();
	std::printf("frames %zu keyframes %zu addFrame mean %.2f ms max %.2f ms; finish waited %.1f s, final opt %.3f s\n", i,
		lc.keyframes(), add_ms / i, max_add,
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), lc.finalOptimisationSeconds());
	for (const auto& l : lc.loops())
		std::printf("loop %lld -> %lld: desc %.3f yaw %.1f inl %.2f rms %.3f constr %.3f drift %.2f path %.0f %s\n", l.frame,
			l.candidate_frame, l.descriptor_distance, l.yaw_deg, l.inlier_fraction, l.rms, l.constraint, l.drift,
			l.path_between, l.accepted ? "ACCEPTED" : l.reason.c_str());
	const Trajectory cor = lc.corrected();
	std::vector<std::pair<std::size_t, std::size_t>> pairs;
	for (std::size_t j = 0; j < i; ++j)
	{
		std::size_t best = 0;
		double bd = 1e9;
		for (std::size_t k = 0; k + 100 < j; ++k)
		{
			const double d = (truth[k].pose.translation() - truth[j].pose.translation()).norm();
			if (d < bd) bd = d, best = k;
		}
		if (bd < 3) pairs.emplace_back(best, j);
	}
	if (pairs.empty()) return 0;
	std::printf("revisit pairs %zu: odometry %.3f m, corrected %.3f m\n", pairs.size(),
		loop::test::revisitError(truth, odo, pairs), loop::test::revisitError(truth, cor, pairs));
}
