// Accuracy of the LiDAR odometry on one-kilometre synthetic urban drives (doc/LOAM.md, "Measured"): 1.2 m per
// frame, five bends, 1 cm range noise, constant-velocity prior, no deskew; KITTI-style mean translation and
// rotation error over 100-800 m segments, end drift, time per frame. About a minute per drive.
//   build/bin/bench_loam_long_drive [hdl64|vlp16]   (both when no argument)
// Exit code 1 when a drive is worse than 1 % or has a frame that is not ok.
#include <vlo/loam/lidar_odometry.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "synthetic_world.h"
#include "test_helpers.h"

using namespace vlo;
using namespace vlo::loam;
using namespace vlo::loam::test;

namespace
{
Path oneKilometre()
{
	Path p;
	for (auto [len, curv] : std::vector<std::pair<double, double>>{{40, 0.0}, {47, 1.0 / 30}, {60, 0.0}, {63, -1.0 / 40},
			 {80, 0.0}, {40, 1.0 / 25}, {100, 0.0}, {60, -1.0 / 35}, {150, 0.0}, {50, 1.0 / 45}, {120, 0.0},
			 {40, -1.0 / 30}, {160, 0.0}})
		p.add(len, curv);
	return p;
}

/// Runs one drive, prints its figures; true when within the accuracy the doc claims.
bool drive(bool hdl)
{
	const Path p = oneKilometre();
	const World world = urbanWorld(p, 21);
	LidarModel m = hdl ? hdl64() : vlp16();
	m.noise_sigma = 0.01;
	std::mt19937 rng(3);
	LidarOdometry lo(hdl ? hdl64Options() : vlp16Options());
	const double step = 1.2;
	const int n = static_cast<int>(p.length() / step);
	const Eigen::Isometry3d T0 = lidarPoseAt(p, 0);
	std::vector<Eigen::Isometry3d> est, gt;
	double ms = 0, ms_max = 0;
	int bad = 0, degenerate = 0;
	for (int i = 0; i < n; ++i)
	{
		const Eigen::Isometry3d truth = lidarPoseAt(p, i * step);
		const LidarOdometryResult r = lo.process(0.1 * i, scan(world, m, truth, &rng), std::nullopt);
		est.push_back(r.pose);
		gt.push_back(T0.inverse() * truth);
		if (i == 0) continue;
		bad += r.status != LidarFrameStatus::Ok;
		degenerate += r.mapping.degeneracy.degenerate;
		ms += r.ms.total() / (n - 1);
		ms_max = std::max(ms_max, r.ms.total());
	}
	// KITTI odometry metric: mean relative translation error over 100..800 m segments.
	double terr = 0, rerr = 0;
	int segments = 0;
	for (double L = 100; L <= 800; L += 100)
		for (int i = 0; i < n; i += 10)
		{
			const int j = i + static_cast<int>(std::ceil(L / step));
			if (j >= n) break;
			const Eigen::Isometry3d de = est[i].inverse() * est[j], dg = gt[i].inverse() * gt[j];
			terr += translationError(de, dg) / L;
			rerr += rotationErrorDeg(de, dg) / L;
			++segments;
		}
	terr = 100 * terr / segments;
	rerr /= segments;
	std::printf("%s %.0f m: translation error %.3f %%, rotation error %.5f deg/m (%d segments), end drift %.3f m, "
				"%.1f ms/frame (max %.1f), %d frames not ok, %d degenerate\n",
		hdl ? "HDL-64" : "VLP-16", (n - 1) * step, terr, rerr, segments, translationError(est.back(), gt.back()), ms, ms_max,
		bad, degenerate);
	return terr < 1.0 && bad == 0;
}
}  // namespace

int main(int argc, char** argv)
{
	const char* which = argc > 1 ? argv[1] : "";
	if (argc > 2 || (argc == 2 && std::strcmp(which, "hdl64") != 0 && std::strcmp(which, "vlp16") != 0))
	{
		std::fprintf(stderr, "usage: %s [hdl64|vlp16]\n", argv[0]);
		return 2;
	}
	bool ok = true;
	if (std::strcmp(which, "vlp16") != 0) ok &= drive(true);
	if (std::strcmp(which, "hdl64") != 0) ok &= drive(false);
	return ok ? 0 : 1;
}
