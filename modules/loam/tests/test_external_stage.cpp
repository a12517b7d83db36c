// [loam.prior] external_stage: where an external motion (the VO's) enters LOAM.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>

#include <cstdio>
#include <cstdlib>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
struct StageRun
{
	int odometry_rounds = 0;  ///< scan-to-scan rounds over all frames after the first
	double final_error = 0;  ///< m
	std::string last_source;
};

// A straight urban street, 1 m per frame, the external motion = the true motion (or none).
StageRun streetDrive(const std::string& stage, bool with_external)
{
	Path path;
	path.add(80, 0.0);
	const World world = urbanWorld(path, 5);
	LoamOptions o = vlp16Options();
	o.prior.source = "external";
	o.prior.external_stage = stage;
	LidarOdometry lo(o);
	auto pose = [&](int i) { return lidarPoseAt(path, 20 + 1.0 * i); };
	StageRun out;
	for (int i = 0; i < 12; ++i)
	{
		std::optional<Eigen::Isometry3d> external;
		if (with_external && i > 0) external = pose(i - 1).inverse() * pose(i);
		const LidarOdometryResult r = lo.process(0.1 * i, scan(world, vlp16(), pose(i)), external);
		if (i > 0) out.odometry_rounds += r.odometry.rounds;
		out.final_error = translationError(r.pose, pose(0).inverse() * pose(i));
		out.last_source = r.prior_source;
		if (std::getenv("VLO_VERBOSE"))
			std::printf("%s %d: err %.3f x %.3f status %s map it %d edges %d planes %d mineig %.1f odo rounds %d\n", stage.c_str(), i,
				out.final_error, r.pose.translation().x(), toString(r.status), r.mapping.iterations, r.mapping.n_edges,
				r.mapping.n_planes, r.mapping.degeneracy.min_eigenvalue, r.odometry.rounds);
	}
	return out;
}
}  // namespace

TEST(ExternalStage, MappingSkipsScanToScanAndRefinesTheExternalMotion)
{
	const StageRun r = streetDrive("mapping", true);
	EXPECT_EQ(r.last_source, "external");
	EXPECT_EQ(r.odometry_rounds, 0);
	EXPECT_LT(r.final_error, 0.05);  // after 11 m
}

TEST(ExternalStage, OdometryStageRunsScanToScanFromTheExternalMotion)
{
	const StageRun r = streetDrive("odometry", true);
	EXPECT_EQ(r.last_source, "external");
	EXPECT_GT(r.odometry_rounds, 0);
}

TEST(ExternalStage, WithoutAnExternalMotionScanToScanRuns)
{
	const StageRun r = streetDrive("mapping", false);
	EXPECT_NE(r.last_source, "external");
	EXPECT_GT(r.odometry_rounds, 0);
}

TEST(ExternalStage, UnknownStageIsRefused)
{
	LoamOptions o;
	o.prior.external_stage = "both";
	EXPECT_ANY_THROW(o.validate());
}
}  // namespace vlo::loam::test
