// INI round trip of every option, strict value checks, validation naming the key.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/error.h>
#include <vlo/loam/lidar_odometry.h>
#include <vlo/loam/options.h>

namespace vlo::loam::test
{
namespace
{
std::string errorOf(const std::string& ini)
{
	mrpt::config::CConfigFileMemory c(ini);
	try
	{
		LoamOptions o;
		o.load(c);
		o.validate();
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(Options, SaveThenLoadRoundTrips)
{
	LoamOptions a;
	a.scan.ring_model = "table";
	a.scan.elevation_table_deg = {-10, -5, 0, 5};
	a.scan.max_deskew_passes = 5;
	a.features.max_flat = 7;
	a.odometry.solver.loss = "cauchy";
	a.odometry.use_kdtree = true;
	a.odometry.max_rounds = 12;
	a.mapping.solver.outer_iterations = 3;
	a.mapping.map_radius = 77.5;
	a.prior.source = "external";
	mrpt::config::CConfigFileMemory saved;
	a.save(saved);
	// Through the text, as run.ini is: MRPT's in-memory writes keep the key padding.
	std::string text;
	saved.getContent(text);
	mrpt::config::CConfigFileMemory c(text);
	LoamOptions b;
	b.load(c);
	EXPECT_EQ(b.scan.ring_model, "table");
	EXPECT_EQ(b.scan.elevation_table_deg, a.scan.elevation_table_deg);
	EXPECT_EQ(b.scan.max_deskew_passes, 5);
	EXPECT_EQ(b.features.max_flat, 7);
	EXPECT_EQ(b.odometry.solver.loss, "cauchy");
	EXPECT_TRUE(b.odometry.use_kdtree);
	EXPECT_EQ(b.odometry.max_rounds, 12);
	EXPECT_EQ(b.mapping.solver.outer_iterations, 3);
	EXPECT_DOUBLE_EQ(b.mapping.map_radius, 77.5);
	EXPECT_EQ(b.prior.source, "external");
	EXPECT_NO_THROW(b.validate());

	// Every section is written, each key with a comment.
	std::vector<std::string> sections;
	c.getAllSections(sections);
	for (const auto& part : a.parts())
		EXPECT_NE(std::find(sections.begin(), sections.end(), part.first), sections.end()) << part.first;
	std::vector<std::string> keys;
	c.getAllKeys("loam.mapping", keys);
	EXPECT_GE(keys.size(), 20u);
}

TEST(Options, DefaultsAreValid)
{
	EXPECT_NO_THROW(LoamOptions().validate());
	EXPECT_EQ(errorOf(""), "");
}

TEST(Options, BadValuesNameSectionAndKey)
{
	EXPECT_NE(errorOf("[loam.scan]\nmin_range = abc\n").find("[loam.scan] min_range"), std::string::npos);
	EXPECT_NE(errorOf("[loam.features]\nn_sectors = 2.5\n").find("n_sectors"), std::string::npos);
	EXPECT_NE(errorOf("[loam.odometry]\nenabled = maybe\n").find("enabled"), std::string::npos);
	EXPECT_NE(errorOf("[loam.odometry]\nmax_rounds = 1\n").find("[loam.odometry] max_rounds: must be >= outer_iterations"),
		std::string::npos);
	EXPECT_NE(errorOf("[loam.odometry]\nmax_rounds = many\n").find("max_rounds"), std::string::npos);
	EXPECT_NE(errorOf("[loam.mapping]\nouter_iterations = 3\nmax_rounds = 2\n").find("[loam.mapping] max_rounds: must be >= outer_iterations"),
		std::string::npos);
	EXPECT_NE(errorOf("[loam.mapping]\nloss = tukey\n").find("[loam.mapping] loss"), std::string::npos);
	EXPECT_NE(errorOf("[loam.mapping]\nvoxel_size = 1.0\n").find("voxel_size"), std::string::npos);
	EXPECT_NE(errorOf("[loam.mapping]\nknn = 17\n").find("[loam.mapping] knn"), std::string::npos);  // plane fits widen to 16
	EXPECT_EQ(errorOf("[loam.mapping]\nknn = 16\n"), "");
	EXPECT_NE(errorOf("[loam.mapping]\nedge_range_ratio = 0.5\n").find("[loam.mapping] edge_range_ratio: must be 0 (off) or >= 1"),
		std::string::npos);
	EXPECT_EQ(errorOf("[loam.mapping]\nedge_range_ratio = 1.1\n"), "");
	EXPECT_NE(errorOf("[loam.mapping]\nedges = auto\nmin_edge_correspondences = 10\n").find("min_edge_correspondences"),
		std::string::npos);
	EXPECT_EQ(errorOf("[loam.mapping]\nedges = on\nmin_edge_correspondences = 10\n"), "");
	EXPECT_NE(errorOf("[loam.mapping]\nedges = sometimes\n").find("[loam.mapping] edges"), std::string::npos);
	EXPECT_NE(errorOf("[loam.scan]\nmax_range = 1\n").find("max_range"), std::string::npos);
	EXPECT_NE(errorOf("[loam.prior]\nsource = imu\n").find("source"), std::string::npos);
	EXPECT_NE(errorOf("[loam.scan]\nelevation_table_deg = [1 x 3]\n").find("elevation_table_deg"), std::string::npos);
}

TEST(Options, LidarOdometryRejectsBadOptions)
{
	LoamOptions o;
	o.features.n_sectors = 0;
	EXPECT_THROW(LidarOdometry{o}, InputError);
}
}  // namespace vlo::loam::test
