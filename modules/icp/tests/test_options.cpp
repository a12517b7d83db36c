// [icp] options: keys load from an INI, bad values name their key.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/error.h>
#include <vlo/icp/icp_odometry.h>

namespace vlo::icp::test
{
TEST(IcpOptions, LoadsTheGivenKeysAndKeepsTheOtherDefaults)
{
	mrpt::config::CConfigFileMemory ini("[icp]\nvoxel_size = 0.5\nmax_iterations = 30\n");
	IcpOptions back;
	back.loadFromConfigFile(ini, "icp");
	EXPECT_EQ(back.max_points_per_voxel, 20);
	EXPECT_EQ(back.voxel_size, 0.5);
	EXPECT_EQ(back.max_iterations, 30);
	EXPECT_NO_THROW(back.validate());
}

TEST(IcpOptions, ABadValueNamesItsKey)
{
	const auto message = [](auto change) {
		IcpOptions o;
		change(o);
		try
		{
			IcpOdometry odo(o);
		}
		catch (const InputError& e)
		{
			return std::string(e.what());
		}
		return std::string("no error");
	};
	// Options set in code have no section: the key alone.
	EXPECT_EQ(message([](IcpOptions& o) { o.voxel_size = 0; }), "voxel_size: must be > 0");
	EXPECT_EQ(message([](IcpOptions& o) { o.max_range = 0.5; }), "max_range: must exceed min_range");
	EXPECT_EQ(message([](IcpOptions& o) { o.max_points_per_voxel = 0; }), "max_points_per_voxel: must be >= 1");
	EXPECT_EQ(message([](IcpOptions& o) { o.max_guess_rotation_deg = 200; }), "max_guess_rotation_deg: must be in (0, 180]");
	// Read from a section: the section too, whatever it is called.
	IcpOptions o;
	try
	{
		o.loadFromConfigFile(mrpt::config::CConfigFileMemory("[icp2]\nmax_range = 0.5\n"), "icp2");
		ADD_FAILURE() << "no error";
	}
	catch (const InputError& e)
	{
		EXPECT_EQ(std::string(e.what()), "[icp2] max_range: must exceed min_range");
	}
}
}  // namespace vlo::icp::test
