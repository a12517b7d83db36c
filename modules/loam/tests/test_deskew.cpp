// Deskew of points whose times lie anywhere around the sweep (the sensor's per-point times).
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <vlo/core/se3_twist.h>
#include <vlo/loam/deskew.h>

namespace vlo::loam::test
{
TEST(Deskew, TimesBeyondTheSweepTakeTheirFractionOfTheMotion)
{
	// 1 m forward and 6 deg of yaw in 0.1 s. A point seen at time s lies in the frame at s; moved to
	// the frame's time 0 it must be motion^(s / 0.1) of it (constant twist), also beyond one frame.
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
	motion.linear() = Eigen::AngleAxisd(6 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	motion.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
	ScanPoints pts;
	for (double s : {-0.13, -0.08, -0.05, 0.0, 0.05, 0.09})
	{
		ScanPoint p;
		p.p = Eigen::Vector3f(10.0f, 2.0f, -1.0f);
		p.time = static_cast<float>(s);
		pts.push_back(p);
	}
	ScanPoints moved = pts;
	deskewTabulated(moved, motion, 0.1);
	for (std::size_t i = 0; i < pts.size(); ++i)
	{
		const Eigen::Vector3d want = expTwist(pts[i].time / 0.1 * logTwist(motion)) * pts[i].p.cast<double>();
		EXPECT_LT((moved[i].p.cast<double>() - want).norm(), 1e-4) << "time " << pts[i].time;
	}
}

TEST(Deskew, RollingSweepWithTheTrueMotionGivesTheStaticScene)
{
	// vlo-sim's rolling sweep (doc/SIMULATOR.md): the firing at azimuth phi happens tau = -phi / (2 pi)
	// sweeps from the frame's instant and sees the scene in the sensor frame of that instant. At 35 m/s and 20 deg/s the sensor moves 3.5 m and
	// 2 deg within the sweep, 50 firings per degree: deskewed with the true motion, every point must
	// be back where the frame sees it at its time, to float precision (a transform looked up
	// at the nearest of 1024 steps was off by up to 1/2048 of the span's motion, 2.6 mm here).
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
	motion.linear() = Eigen::AngleAxisd(2 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	motion.translation() = Eigen::Vector3d(3.5, 0.1, 0.02);
	const Vector6d xi = logTwist(motion);
	ScanPoints scene, sweep;
	for (int c = 0; c < 18000; ++c)
	{
		const double phi = M_PI - (c + 0.5) * 2 * M_PI / 18000, tau = -phi / (2 * M_PI);
		const double range = 8.0 + 4.0 * std::cos(3 * phi);  // a wavy wall around the sensor
		ScanPoint p;
		p.p = Eigen::Vector3d(range * std::cos(phi), range * std::sin(phi), -1.7 + 0.01 * (c % 7)).cast<float>();
		p.time = static_cast<float>(0.1 * tau);  // seconds
		scene.push_back(p);
		p.p = (expTwist(-tau * xi) * p.p.cast<double>()).cast<float>();  // seen from the sensor at its firing
		sweep.push_back(p);
	}
	deskewTabulated(sweep, motion, 0.1);
	double worst = 0;
	for (std::size_t i = 0; i < scene.size(); ++i) worst = std::max(worst, (sweep[i].p - scene[i].p).cast<double>().norm());
	EXPECT_LT(worst, 5e-5);
}
}  // namespace vlo::loam::test
