// Scan Context: the yaw between two scans of one place, and the distance of the same and another place.
#include <gtest/gtest.h>
#include <vlo/loop/scan_context.h>

#include "synthetic_places.h"

using namespace vlo;
using namespace vlo::loop;
using namespace vlo::loop::test;

namespace
{
World city()
{
	return randomCity(7, -100, 100, -100, 100, 80, [](const Eigen::Vector2d& lo, const Eigen::Vector2d& size) {
		return lo.x() < 6 && lo.x() + size.x() > -6 && lo.y() < 6 && lo.y() + size.y() > -6;
	});
}

std::vector<Eigen::Vector3f> points(const PointCloud& scan)
{
	std::vector<Eigen::Vector3f> out;
	for (const auto& p : scan) out.emplace_back(p.x, p.y, p.z);
	return out;
}

ScanContext contextAt(const World& world, const Eigen::Isometry3d& pose, unsigned seed)
{
	std::mt19937 rng(seed);
	return makeScanContext(points(scanFrom(world, pose, rng)), ScanContextParams{});
}
}  // namespace

TEST(ScanContext, BinsTheHighestPointPerRingAndSector)
{
	// 20 rings of 4 m, 60 sectors of 6 deg from -180 deg: (10, 0.1) is ring 2, sector 30.
	const std::vector<Eigen::Vector3f> pts{{10.f, 0.1f, 1.f}, {10.5f, 0.2f, 3.f}, {-5.f, -0.1f, 0.5f}, {90.f, 0.f, 9.f}};
	const ScanContext sc = makeScanContext(pts, ScanContextParams{});
	EXPECT_DOUBLE_EQ(sc(2, 30), 5.0);  // 3 + sensor height 2
	EXPECT_DOUBLE_EQ(sc(1, 0), 2.5);  // (-5, -0.1): 5 m, azimuth just above -180 deg
	EXPECT_EQ((sc.array() > 0).count(), 2);  // the point beyond 80 m is not binned
}

TEST(ScanContext, FindsTheYawOfARotatedScan)
{
	const World world = city();
	const Eigen::Isometry3d here = pose2d(0, 0, 0);
	const ScanContext reference = contextAt(world, here, 1);
	for (const double yaw_deg : {30.0, 33.0, -100.0, 177.0})
	{
		const ScanContext turned = contextAt(world, here * pose2d(0, 0, yaw_deg * M_PI / 180), 2);
		const DescriptorMatch m = compareScanContexts(turned, reference);
		EXPECT_NEAR(std::remainder(m.yaw * 180 / M_PI - yaw_deg, 360.0), 0.0, 6.0) << yaw_deg;
		EXPECT_LT(m.distance, 0.15) << yaw_deg;  // a candidate is under 0.25
		// The ring key does not change with the yaw.
		EXPECT_LT((ringKey(turned) - ringKey(reference)).norm(), 0.1 * ringKey(reference).norm()) << yaw_deg;
	}
	// A turn by a whole number of sectors: the same bins, shifted.
	const ScanContext exact = contextAt(world, here * pose2d(0, 0, 60 * M_PI / 180), 1);
	const DescriptorMatch m = compareScanContexts(exact, reference);
	EXPECT_NEAR(m.yaw * 180 / M_PI, 60.0, 1e-9);
	EXPECT_LT(m.distance, 0.01);
}

TEST(ScanContext, AnotherPlaceIsFar)
{
	const World world = city();
	const DescriptorMatch m = compareScanContexts(contextAt(world, pose2d(60, 40, 0), 3), contextAt(world, pose2d(0, 0, 0), 1));
	EXPECT_GT(m.distance, 0.25);
}
