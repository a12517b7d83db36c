// The "orb" module as the run loop sees it: created by name, configured from an INI, it reports the
// camera's motion in map units until its map is scaled, then in metres; and CameraMount, which turns
// the camera's motion into the vehicle's (V = Tvc C Tvc^-1), leaving the metric lever arm out until
// the map has a metric scale.
#include <gtest/gtest.h>
#include <vlo/kernel/visual_odometry.h>

#include "../vo_test_util.h"

using namespace vlo;

namespace
{
/// Camera looking along the vehicle's x axis (optical z), pitched 5 deg down, 1.2 m ahead and 1.7 m up.
Eigen::Isometry3d vehicleTcamera()
{
	return Eigen::Translation3d(1.2, -0.3, 1.7) * Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()) *
		Eigen::AngleAxisd(-M_PI / 2 - 5 * M_PI / 180, Eigen::Vector3d::UnitX());
}

struct Drive
{
	std::unique_ptr<kernel::MonocularVisualOdometry> vo;
	PinholeCamera cam = vo::test::kittiCamera();
	vo::test::StreetRenderer renderer{vo::test::StreetScene(), cam};
	kernel::FrameTable table;
	int k = 0;

	Drive()
	{
		auto config = kernel::RunConfig::fromString("[vo.orb]\nn_features = 1500\n", "test.ini");
		vo.reset(dynamic_cast<kernel::MonocularVisualOdometry*>(kernel::registry<kernel::VisualOdometryModule>().create("orb", "test").release()));
		vo->configure(config);
		config.checkAllKeysUsed();
	}

	kernel::VisualOdometryStep next()
	{
		Frame f;
		f.index = std::size_t(k);
		f.t = 0.1 * k;
		f.has_image = true;
		f.rig.has_camera = true;
		f.rig.camera = cam;
		f.rig.vehicle_T_camera = vehicleTcamera();
		f.image = mrpt::img::CImage(renderer.render(vo::test::drivePose(k++)), mrpt::img::DEEP_COPY);
		table.newRow();
		return vo->process(f, table);
	}
};

double gap(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) { return (a.matrix() - b.matrix()).norm(); }
}  // namespace

TEST(OrbVoModule, ReportsTheCameraAndIsMetricOnceScaled)
{
	Drive d;
	ASSERT_NE(d.vo, nullptr);  // "orb" is a monocular VO
	EXPECT_FALSE(d.vo->rescale(2.0, true));  // no map yet
	kernel::VisualOdometryStep step;
	for (int i = 0; i < 10 && !step.new_map; ++i) step = d.next();
	ASSERT_TRUE(step.new_map);
	EXPECT_FALSE(step.metric);
	step = d.next();
	ASSERT_TRUE(step.camera_motion && step.camera_pose && step.camera_map_pose);
	EXPECT_FALSE(step.metric);
	EXPECT_EQ(d.table.cell(d.table.rows() - 1, "vo_metric"), "0");

	ASSERT_TRUE(d.vo->rescale(1.0, true));  // the map is metric from now on
	step = d.next();
	ASSERT_TRUE(step.camera_motion);
	EXPECT_TRUE(step.metric);
	EXPECT_EQ(d.table.cell(d.table.rows() - 1, "vo_metric"), "1");
	EXPECT_FALSE(step.new_map);
}

TEST(CameraMount, VehicleMotionIsTheCameraMotionInVehicleAxesWithTheLeverArmOnceMetric)
{
	Frame f;
	f.rig.vehicle_T_camera = vehicleTcamera();
	kernel::CameraMount mount;
	mount.observe(f);
	f.rig.vehicle_T_camera = Eigen::Isometry3d::Identity();
	mount.observe(f);  // the first frame's placement stays
	const Eigen::Isometry3d C = Eigen::Translation3d(0.1, -0.2, 1.3) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY());
	Eigen::Isometry3d R = vehicleTcamera();
	R.translation().setZero();
	EXPECT_LT(gap(mount.vehicle(C, false), R * C * R.inverse()), 1e-9);  // map units: rotation only
	const Eigen::Isometry3d Tvc = vehicleTcamera();
	EXPECT_LT(gap(mount.vehicle(C, true), Tvc * C * Tvc.inverse()), 1e-9);
}
