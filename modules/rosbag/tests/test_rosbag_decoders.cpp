// Message decoders on hand-made messages with known answers: driver field layouts, CameraInfo rules,
// transform chains, the stamp-order buffer.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/rosbag/camera_info.h>
#include <vlo/rosbag/extrinsics_file.h>
#include <vlo/rosbag/pointcloud2.h>
#include <vlo/rosbag/stamp_order.h>
#include <vlo/rosbag/transform_tree.h>

#include <cstring>
#include <limits>

namespace vlo::rosbag_io
{
namespace
{
using sensor_msgs::PointField;

/// A field's name, offset and type.
using Fields = std::vector<std::tuple<std::string, std::uint32_t, std::uint8_t>>;

/// A cloud of `n` points with the given fields, filled by put(point, field, bytes).
sensor_msgs::PointCloud2 cloud(std::size_t n, std::uint32_t step, const Fields& fields)
{
	sensor_msgs::PointCloud2 pc;
	pc.header.stamp = ros::Time(1000.5);
	for (const auto& [name, off, type] : fields)
	{
		PointField f;
		f.name = name, f.offset = off, f.datatype = type, f.count = 1;
		pc.fields.push_back(f);
	}
	pc.height = 1, pc.width = static_cast<std::uint32_t>(n), pc.point_step = step, pc.row_step = step * pc.width;
	pc.data.assign(pc.row_step, 0);
	return pc;
}
template <class V>
void put(sensor_msgs::PointCloud2& pc, std::size_t i, std::uint32_t off, V v)
{
	std::memcpy(pc.data.data() + i * pc.point_step + off, &v, sizeof(V));
}

TEST(PointCloud2, OusterLayoutRingAndNanosecondTime)
{
	// Ouster: x y z (float32) at 0 4 8, intensity float32 at 16, t uint32 ns at 20, reflectivity uint16 at 24, ring uint16 at 26.
	const Fields fields{{"x", 0, PointField::FLOAT32}, {"y", 4, PointField::FLOAT32},
		{"z", 8, PointField::FLOAT32}, {"intensity", 16, PointField::FLOAT32}, {"t", 20, PointField::UINT32},
		{"reflectivity", 24, PointField::UINT16}, {"ring", 26, PointField::UINT16}};
	auto pc = cloud(3, 48, fields);
	// Top-down rings (Ouster's 0 is the highest beam): point i has elevation going down with i.
	for (std::size_t i = 0; i < 3; ++i)
	{
		put(pc, i, 0, 10.0f), put(pc, i, 4, 0.0f), put(pc, i, 8, 2.0f - 2.0f * i);
		put(pc, i, 16, 7.0f * i), put(pc, i, 20, std::uint32_t(25000000 * i)), put(pc, i, 26, std::uint16_t(i));
	}
	put(pc, 1, 4, std::numeric_limits<float>::quiet_NaN());
	const auto r = decodePointCloud2(pc, "x.bag: /os/points");
	EXPECT_EQ(r.dropped, 1u);
	ASSERT_EQ(r.points.size(), 2u);
	EXPECT_TRUE(r.points.has_ring && r.points.has_time);
	EXPECT_FLOAT_EQ(r.points[1].time, 0.05f);
	EXPECT_EQ(r.points[1].intensity, 14.0f);
	EXPECT_EQ(r.points[0].ring, 2u);  // flipped: the highest beam gets the top index
	EXPECT_EQ(r.points[1].ring, 0u);
}

TEST(PointCloud2, AbsoluteTimestampDoubleAndReflectivity)
{
	// Hesai-like: x y z float64, reflectivity uint8, timestamp float64 absolute seconds.
	const Fields fields{{"x", 0, PointField::FLOAT64}, {"y", 8, PointField::FLOAT64},
		{"z", 16, PointField::FLOAT64}, {"reflectivity", 24, PointField::UINT8}, {"timestamp", 32, PointField::FLOAT64}};
	auto pc = cloud(2, 40, fields);
	for (std::size_t i = 0; i < 2; ++i)
		put(pc, i, 0, 1.5 * i), put(pc, i, 8, -2.0), put(pc, i, 16, 0.25), put(pc, i, 24, std::uint8_t(200)),
			put(pc, i, 32, 1000.5 - 0.1 + 0.06 * i);
	const auto r = decodePointCloud2(pc, "x.bag: /hesai");
	ASSERT_EQ(r.points.size(), 2u);
	EXPECT_FALSE(r.points.has_ring);
	EXPECT_NEAR(r.points[0].time, -0.1, 1e-6);
	EXPECT_NEAR(r.points[1].time, -0.04, 1e-6);
	EXPECT_EQ(r.points[1].x, 1.5f);
	EXPECT_EQ(r.points[0].intensity, 200.0f);
}

TEST(PointCloud2, LayoutThatDoesNotFitIsRefused)
{
	auto pc = cloud(2, 12, {{"x", 0, PointField::FLOAT32}, {"y", 4, PointField::FLOAT32}, {"z", 10, PointField::FLOAT32}});
	EXPECT_THROW(decodePointCloud2(pc, "x.bag"), InputError);  // z overruns point_step
	pc = cloud(2, 12, {{"x", 0, PointField::FLOAT32}, {"y", 4, PointField::FLOAT32}, {"z", 8, PointField::FLOAT32}});
	pc.data.resize(20);
	EXPECT_THROW(decodePointCloud2(pc, "x.bag"), InputError);  // fewer bytes than points
}

TEST(CameraInfo, RectifiedStreamUsesP)
{
	sensor_msgs::CameraInfo ci;
	ci.width = 640, ci.height = 480;
	ci.K = {500, 0, 320, 0, 505, 240, 0, 0, 1};
	ci.P = {480, 0, 318, -48, 0, 480, 236, 0, 0, 0, 1, 0};
	ci.distortion_model = "plumb_bob";
	ci.D = {-0.3, 0.1, 0.001, 0.002, 0};
	const auto raw = fromCameraInfo(ci, "/cam/image_raw", "x.bag");
	EXPECT_EQ(raw.fx, 500);
	EXPECT_EQ(raw.fy, 505);
	EXPECT_EQ(raw.distortion, mrpt::img::DistortionModel::plumb_bob);
	EXPECT_EQ(raw.dist[3], 0.002);
	const auto rect = fromCameraInfo(ci, "/cam/image_rect/compressed", "x.bag");
	EXPECT_EQ(rect.fx, 480);
	EXPECT_EQ(rect.cx, 318);
	EXPECT_EQ(rect.cy, 236);
	EXPECT_EQ(rect.distortion, mrpt::img::DistortionModel::none);
	ci.D = {0, 0, 0, 0, 0};  // no distortion: the image is P's
	EXPECT_EQ(fromCameraInfo(ci, "/cam/image_raw", "x.bag").fx, 480);
	ci.D = {0.1, 0.2, 0.3};
	EXPECT_THROW(fromCameraInfo(ci, "/cam/image_raw", "x.bag"), InputError);  // plumb_bob needs 5
}

TEST(TransformTree, ChainsComposeThroughTheTree)
{
	Eigen::Isometry3d b_T_l = Eigen::Isometry3d::Identity(), b_T_m = b_T_l, m_T_c = b_T_l;
	b_T_l.translate(Eigen::Vector3d(0.5, 0, 1.8)).rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
	b_T_m.translate(Eigen::Vector3d(1.0, 0.2, 1.2));
	m_T_c.rotate(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX())).translate(Eigen::Vector3d(0.1, 0, 0));
	TransformTree tree;
	tree.add("/base_link", "velodyne", b_T_l);
	tree.add("base_link", "camera_link", b_T_m);
	tree.add("camera_link", "camera_optical", m_T_c);
	const auto l_T_c = tree.lookup("velodyne", "camera_optical");
	ASSERT_TRUE(l_T_c);
	EXPECT_TRUE(l_T_c->isApprox(b_T_l.inverse() * b_T_m * m_T_c, 1e-12));
	EXPECT_FALSE(tree.lookup("velodyne", "imu"));

	StaticTfFilter filter;  // /tf: a moving base is not static, a fixed mount is
	geometry_msgs::TransformStamped moving, mount;
	moving.header.frame_id = "odom", moving.child_frame_id = "base_link", moving.transform.rotation.w = 1;
	mount.header.frame_id = "base_link", mount.child_frame_id = "imu", mount.transform.rotation.w = 1;
	mount.transform.translation.z = 0.3;
	for (int k = 0; k < 3; ++k)
	{
		moving.transform.translation.x = k;
		filter.add(moving), filter.add(mount);
	}
	filter.addStaticTo(tree);
	EXPECT_FALSE(tree.lookup("odom", "velodyne"));
	ASSERT_TRUE(tree.lookup("imu", "velodyne"));
	EXPECT_NEAR(tree.lookup("imu", "velodyne")->translation().z(), 1.5, 1e-12);
}

TEST(StampOrder, ReleasesInStampOrderWithinTheWindow)
{
	std::vector<std::pair<double, int>> out;
	StampOrder<int> order(0.3, 2, [&](double t, int sensor, int&&) { out.push_back({t, sensor}); });
	// Arrival: images on time, scans 0.25 s late.
	EXPECT_TRUE(order.push(0.0, 0, 0));
	EXPECT_TRUE(order.push(0.1, 0, 0));
	EXPECT_TRUE(order.push(0.2, 0, 0));
	EXPECT_TRUE(order.push(0.0, 1, 0));
	EXPECT_TRUE(order.push(0.3, 0, 0));
	EXPECT_TRUE(order.push(0.1, 1, 0));
	EXPECT_TRUE(order.push(0.4, 0, 0));  // releases up to < 0.1
	EXPECT_FALSE(order.push(0.0, 1, 0));  // this sensor is already past it: came too late
	EXPECT_FALSE(order.push(0.3, 0, 0));  // repeated stamp
	order.flush();
	const std::vector<std::pair<double, int>> want = {{0.0, 0}, {0.0, 1}, {0.1, 0}, {0.1, 1}, {0.2, 0}, {0.3, 0}, {0.4, 0}};
	EXPECT_EQ(out, want);
}
}  // namespace
}  // namespace vlo::rosbag_io

namespace vlo::rosbag_io
{
namespace
{
TEST(CalibrationFiles, ShippedS3eExampleReads)
{
	const std::string dir = std::string(VLO_SOURCE_DIR) + "/doc/examples/";
	const auto cam = fromCameraInfo(readCameraInfoFile(dir + "s3e_alpha_left_camera.yaml"), "/Alpha/left_camera/compressed", "x");
	EXPECT_EQ(cam.width, 1224);
	EXPECT_EQ(cam.height, 1024);
	EXPECT_EQ(cam.fx, 1172.771733138536);
	EXPECT_EQ(cam.cy, 507.672727295385);
	EXPECT_EQ(cam.distortion, mrpt::img::DistortionModel::plumb_bob);
	EXPECT_EQ(cam.dist[0], -0.052628389768906);
	EXPECT_EQ(cam.dist[4], 0.0);
	const Eigen::Isometry3d l_T_c = readExtrinsicsFile(dir + "s3e_alpha_extrinsics.yaml");
	EXPECT_EQ(l_T_c.translation().y(), 0.196875730840019);
	// The camera looks along the LiDAR's x axis (forward): its optical z axis in the LiDAR frame.
	EXPECT_GT(l_T_c.linear().col(2).x(), 0.999);
}
}  // namespace
}  // namespace vlo::rosbag_io
