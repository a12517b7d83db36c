#include <gtest/gtest.h>
#include <vlo/core/atomic_file.h>
#include <vlo/core/cli.h>
#include <vlo/core/error.h>
#include <vlo/core/se3.h>

#include <cmath>
#include <fstream>

using namespace vlo;

TEST(Se3, IsometryRoundTripThroughCPose3D)
{
	const mrpt::poses::CPose3D p(1.0, -2.0, 0.5, 0.3, -0.2, 0.1);
	const Eigen::Isometry3d T = toIsometry(p);
	const mrpt::poses::CPose3D q = toCPose3D(T);
	EXPECT_NEAR(q.x(), 1.0, 1e-12);
	EXPECT_NEAR(q.yaw(), 0.3, 1e-12);
	EXPECT_NEAR(q.pitch(), -0.2, 1e-12);
	EXPECT_NEAR(q.roll(), 0.1, 1e-12);
	// Composition agrees with MRPT's.
	const mrpt::poses::CPose3D r(0.2, 0.1, 0, -0.5, 0, 0.05);
	const Eigen::Isometry3d TR = toIsometry(p + r);
	EXPECT_TRUE(TR.isApprox(T * toIsometry(r), 1e-12));
}

TEST(Se3, RotationAngleIsAccurateForSmallAndLargeAngles)
{
	for (double a : {1e-7, 1e-3, 0.5, 3.0})
	{
		const Eigen::Matrix3d R = Eigen::AngleAxisd(a, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
		EXPECT_NEAR(rotationAngle(R), a, 1e-12 + 1e-9 * a);
	}
}

TEST(Se3, Sim3InverseAndComposition)
{
	Sim3 S;
	S.s = 2.5;
	S.R = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	S.t = Eigen::Vector3d(1, 2, 3);
	const Eigen::Vector3d x(0.3, -4, 2);
	EXPECT_TRUE((S.inverse() * (S * x)).isApprox(x, 1e-12));
	EXPECT_TRUE(((S * S.inverse()) * x).isApprox(x, 1e-12));
}

TEST(Se3, InterpolateHalfway)
{
	Eigen::Isometry3d A = Eigen::Isometry3d::Identity(), B = Eigen::Isometry3d::Identity();
	B.translate(Eigen::Vector3d(2, 0, 0));
	B.rotate(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
	const Eigen::Isometry3d M = interpolate(A, B, 0.5);
	EXPECT_NEAR(M.translation().x(), 1.0, 1e-12);
	EXPECT_NEAR(rotationAngle(M.rotation()), 0.2, 1e-12);
}

TEST(Cli, ParsesValuesSwitchesAndRejectsUnknown)
{
	const char* argv[] = {"app", "--in", "a.rawlog", "--set", "x=1", "--set=y=2", "--fast"};
	CommandLine cl(7, const_cast<char**>(argv), 1,
		{{"in", "FILE", "input", true, false}, {"set", "K=V", "override", false, true}, {"fast", "", "go", false, false}});
	EXPECT_EQ(cl.get("in"), "a.rawlog");
	ASSERT_EQ(cl.getAll("set").size(), 2u);
	EXPECT_EQ(cl.getAll("set")[1], "y=2");
	EXPECT_TRUE(cl.has("fast"));

	const char* bad[] = {"app", "--in", "a", "--what"};
	EXPECT_THROW(CommandLine(4, const_cast<char**>(bad), 1, {{"in", "FILE", "", true, false}}), InputError);
	const char* missing[] = {"app"};
	EXPECT_THROW(CommandLine(1, const_cast<char**>(missing), 1, {{"in", "FILE", "", true, false}}), InputError);
	const char* nonum[] = {"app", "--n", "12x"};
	CommandLine n(3, const_cast<char**>(nonum), 1, {{"n", "N", "", false, false}});
	EXPECT_THROW(n.getInt("n", 0), InputError);
}

TEST(AtomicFile, UncommittedOutputLeavesNothing)
{
	const std::string path = "atomic_test.txt";
	std::remove(path.c_str());
	{
		AtomicOutputFile f(path);
		f.stream() << "half";
	}
	EXPECT_FALSE(std::ifstream(path).good());
	EXPECT_FALSE(std::ifstream(path + ".partial").good());
	{
		AtomicOutputFile f(path);
		f.stream() << "whole";
		f.commit();
	}
	std::ifstream in(path);
	std::string s;
	in >> s;
	EXPECT_EQ(s, "whole");
	std::remove(path.c_str());
}
