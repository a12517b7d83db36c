// Deskew of points whose times lie anywhere around the sweep (the sensor's per-point times).
#include <gtest/gtest.h>
#include <vlo/core/se3_twist.h>
#include <vlo/loam/deskew.h>

namespace vlo::loam::test
{
TEST(Deskew, TimesBeyondTheSweepTakeTheirFractionOfTheMotion)
{
	// One sweep's motion: 1 m forward and 6 deg of yaw. A point seen at sweep time s lies in the
	// frame at s; moved to the reference 0.5 it must be motion^(s - 0.5) of it (constant twist), also
	// for s < 0 or s > 1.
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
	motion.linear() = Eigen::AngleAxisd(6 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	motion.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
	ScanPoints pts;
	for (double s : {-0.8, -0.3, 0.0, 0.5, 1.0, 1.4})
	{
		ScanPoint p;
		p.p = Eigen::Vector3f(10.0f, 2.0f, -1.0f);
		p.time = static_cast<float>(s);
		pts.push_back(p);
	}
	ScanPoints moved = pts;
	deskew(moved, motion, 0.5);
	for (std::size_t i = 0; i < pts.size(); ++i)
	{
		const Eigen::Vector3d want = expTwist((pts[i].time - 0.5) * logTwist(motion)) * pts[i].p.cast<double>();
		EXPECT_LT((moved[i].p.cast<double>() - want).norm(), 2e-3) << "time " << pts[i].time;  // 1/2048 of a 2.2-sweep span
	}
}
}  // namespace vlo::loam::test
