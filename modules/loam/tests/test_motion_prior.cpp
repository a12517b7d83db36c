// Initial-guess providers: constant velocity and an external motion with fallback.
#include <gtest/gtest.h>
#include <vlo/loam/motion_prior.h>

#include <limits>

#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
Eigen::Isometry3d step(double x, double yaw_deg)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation().x() = x;
	return T;
}
}  // namespace

TEST(MotionPrior, ConstantVelocityRepeatsTheLastMotion)
{
	ConstantVelocityPrior p;
	EXPECT_TRUE(p.predict(0.0, std::nullopt).isApprox(Eigen::Isometry3d::Identity()));
	EXPECT_EQ(p.lastSource(), "none");
	p.update(0.0, Eigen::Isometry3d::Identity());
	p.update(0.1, step(1.0, 2.0));
	const Eigen::Isometry3d g = p.predict(0.2, step(9, 9));  // the external motion is ignored
	EXPECT_EQ(p.lastSource(), "constant_velocity");
	EXPECT_TRUE(g.isApprox(step(1.0, 2.0), 1e-9));
	// A dropped frame: twice the time, twice the motion.
	const Eigen::Isometry3d g2 = p.predict(0.3, std::nullopt);
	EXPECT_NEAR(g2.translation().x(), 2.0, 1e-9);
	EXPECT_NEAR(rotationAngle(g2.linear()) * 180 / M_PI, 4.0, 1e-9);
	p.reset();
	EXPECT_TRUE(p.predict(1.0, std::nullopt).isApprox(Eigen::Isometry3d::Identity()));
}

TEST(MotionPrior, ExternalUsedWhenPlausibleElseConstantVelocity)
{
	PriorOptions o;
	o.source = "external";
	auto p = makeMotionPrior(o);
	p->update(0.0, Eigen::Isometry3d::Identity());
	p->update(0.1, step(1.0, 1.0));
	EXPECT_TRUE(p->predict(0.2, step(1.3, -1.0)).isApprox(step(1.3, -1.0), 1e-9));
	EXPECT_EQ(p->lastSource(), "external");
	EXPECT_TRUE(p->predict(0.2, std::nullopt).isApprox(step(1.0, 1.0), 1e-9));
	EXPECT_EQ(p->lastSource(), "constant_velocity");

	Eigen::Isometry3d nan = step(1, 0);
	nan.translation().y() = std::numeric_limits<double>::quiet_NaN();
	Eigen::Isometry3d sheared = step(1, 0);
	sheared.linear()(0, 1) = 0.5;
	for (const Eigen::Isometry3d& bad : {nan, step(50.0, 0.0), step(1.0, 90.0), sheared})
	{
		EXPECT_TRUE(p->predict(0.2, bad).isApprox(step(1.0, 1.0), 1e-9));
		EXPECT_EQ(p->lastSource(), "constant_velocity");
	}
}

TEST(MotionPrior, ExternalFarFromConstantVelocityIsRejected)
{
	PriorOptions o;
	o.source = "external";
	ExternalPrior p(o);
	// Before a velocity is known, any plausible external motion is taken.
	EXPECT_TRUE(p.predict(0.0, step(2.0, 0.0)).isApprox(step(2.0, 0.0), 1e-9));
	EXPECT_EQ(p.lastSource(), "external");
	p.update(0.0, Eigen::Isometry3d::Identity());
	p.update(0.1, step(1.0, 0.0));
	EXPECT_TRUE(p.predict(0.2, step(1.45, 0.0)).isApprox(step(1.45, 0.0), 1e-9));  // 0.45 m off: kept
	EXPECT_EQ(p.lastSource(), "external");
	for (const Eigen::Isometry3d& far : {step(0.4, 0.0), step(1.0, 3.5)})  // 0.6 m, 3.5 deg off
	{
		EXPECT_TRUE(p.predict(0.2, far).isApprox(step(1.0, 0.0), 1e-9));
		EXPECT_EQ(p.lastSource(), "constant_velocity (external rejected)");
	}
}

TEST(MotionPrior, ExternalConsistentWithItselfIsKeptWhenConstantVelocityIsWrong)
{
	PriorOptions o;
	o.source = "external";
	ExternalPrior p(o);
	p.update(0.0, Eigen::Isometry3d::Identity());
	p.update(0.1, Eigen::Isometry3d::Identity());  // LOAM stuck: it found no motion
	EXPECT_TRUE(p.predict(0.2, step(0.9, 0.0)).isApprox(Eigen::Isometry3d::Identity(), 1e-9));  // 0.9 m off, nothing to confirm it
	EXPECT_EQ(p.lastSource(), "constant_velocity (external rejected)");
	p.update(0.2, Eigen::Isometry3d::Identity());
	EXPECT_TRUE(p.predict(0.3, step(0.95, 0.5)).isApprox(step(0.95, 0.5), 1e-9));  // agrees with its last motion
	EXPECT_EQ(p.lastSource(), "external");
	p.update(0.3, step(0.95, 0.5));
	p.predict(0.4, std::nullopt);  // a frame without external motion: the next one has nothing to agree with
	p.update(0.4, step(0.95, 0.5));
	EXPECT_TRUE(p.predict(0.5, step(2.0, 0.0)).isApprox(step(0.95, 0.5), 1e-9));
	EXPECT_EQ(p.lastSource(), "constant_velocity (external rejected)");
	p.reset();
	p.update(0.0, Eigen::Isometry3d::Identity());
	p.update(0.1, Eigen::Isometry3d::Identity());
	p.predict(0.2, step(0.9, 0.0));
	EXPECT_EQ(p.lastSource(), "constant_velocity (external rejected)");  // reset forgets the last external motion
}

TEST(MotionPrior, MadeByName)
{
	PriorOptions o;
	EXPECT_NE(dynamic_cast<ConstantVelocityPrior*>(makeMotionPrior(o).get()), nullptr);
	o.source = "external";
	EXPECT_NE(dynamic_cast<ExternalPrior*>(makeMotionPrior(o).get()), nullptr);
}
}  // namespace vlo::loam::test
