// The metric VO path: a fresh map's frames re-expressed when its first scale arrives, later frames
// chained from scaled motions, a new map after LOST continuing where the path left off.
#include <gtest/gtest.h>
#include "metric_vo_path.h"

using namespace vlo;
using namespace vlo::pipeline;

namespace
{
/// Camera looking along the vehicle's x axis (z forward, x right, y down), with a lever arm.
Eigen::Isometry3d vehicleTcamera()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	T.translation() << 1.5, 0.1, 1.6;
	return T;
}

Eigen::Isometry3d forward(double z)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation().z() = z;
	return T;
}

kernel::VisualOdometryStep tracked(double mapZ, std::optional<double> motionZ, bool newMap = false)
{
	kernel::VisualOdometryStep s;
	s.camera_map_pose = forward(mapZ);
	if (motionZ) s.camera_motion = forward(*motionZ);
	s.new_map = newMap;
	return s;
}

kernel::ScaleCorrection initial(double factor) { return {kernel::ScaleCorrection::Kind::Initial, factor, "first"}; }
}  // namespace

TEST(MetricVoPath, NothingUntilTheFirstScaleThenTheWholeMapInMetres)
{
	MetricVoPath path(vehicleTcamera());
	EXPECT_FALSE(path.update(0.0, kernel::VisualOdometryStep{}, {}));  // initialising
	EXPECT_FALSE(path.update(0.1, tracked(1.0, std::nullopt, true), {}));  // map made, scale unknown
	EXPECT_TRUE(path.trajectory().empty());
	// Next frame: the first estimate says VO units are 0.5 m.
	const auto motion = path.update(0.2, tracked(2.0, 1.0), initial(0.5));
	ASSERT_TRUE(motion);
	EXPECT_NEAR(motion->translation().x(), 0.5, 1e-12);  // camera z is vehicle x; the lever arm cancels
	EXPECT_NEAR(motion->translation().norm(), 0.5, 1e-12);
	ASSERT_EQ(path.trajectory().size(), 2u);
	EXPECT_NEAR(path.trajectory()[0].pose.translation().x(), 0.5, 1e-12);
	EXPECT_NEAR(path.trajectory()[1].pose.translation().x(), 1.0, 1e-12);
	EXPECT_TRUE(path.metric());
}

TEST(MetricVoPath, ChainsMotionsAndAppliesACorrectionToItsOwnFrame)
{
	MetricVoPath path(vehicleTcamera());
	path.update(0.0, tracked(1.0, std::nullopt, true), {});
	path.update(0.1, tracked(2.0, 1.0), initial(1.0));  // metres already
	path.update(0.2, tracked(3.0, 1.0), {});  // no correction: 1 m
	const auto m = path.update(0.3, tracked(4.0, 1.0), {kernel::ScaleCorrection::Kind::Drift, 1.1, "drift"});  // VO 10 % short: 1.1 m
	ASSERT_TRUE(m);
	EXPECT_NEAR(m->translation().x(), 1.1, 1e-12);
	ASSERT_EQ(path.trajectory().size(), 4u);
	EXPECT_NEAR(path.trajectory().back().pose.translation().x(), 4.1, 1e-12);
}

TEST(MetricVoPath, LostLeavesAGapAndANewMapContinuesFromTheLastPose)
{
	MetricVoPath path(vehicleTcamera());
	path.update(0.0, tracked(1.0, std::nullopt, true), {});
	path.update(0.1, tracked(2.0, 1.0), initial(1.0));  // at 2 m
	EXPECT_FALSE(path.update(0.2, kernel::VisualOdometryStep{}, {}));  // LOST: no motion for LOAM
	EXPECT_FALSE(path.update(0.3, tracked(0.5, std::nullopt, true), {}));  // new map, unknown scale
	EXPECT_EQ(path.trajectory().size(), 2u);
	const auto m = path.update(0.4, tracked(1.0, 0.5), initial(2.0));  // VO units are 2 m
	ASSERT_TRUE(m);
	EXPECT_NEAR(m->translation().x(), 1.0, 1e-12);
	ASSERT_EQ(path.trajectory().size(), 4u);
	EXPECT_NEAR(path.trajectory()[2].pose.translation().x(), 3.0, 1e-12);  // 2 m + 0.5 * 2
	EXPECT_NEAR(path.trajectory()[3].pose.translation().x(), 4.0, 1e-12);
	EXPECT_NEAR(path.trajectory()[3].t, 0.4, 1e-12);
}

TEST(MetricVoPath, AMapThatNeverGetsAScaleIsNotWritten)
{
	MetricVoPath path(vehicleTcamera());
	path.update(0.0, tracked(1.0, std::nullopt, true), {});
	for (int k = 1; k < 5; ++k) EXPECT_FALSE(path.update(0.1 * k, tracked(1.0 + k, 1.0), {}));
	EXPECT_TRUE(path.trajectory().empty());
	EXPECT_FALSE(path.metric());
}
