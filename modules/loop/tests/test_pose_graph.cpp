// The pose graph: a loop edge spreads the odometry's error over the chain, the first node stays.
#include <gtest/gtest.h>
#include <vlo/loop/odometry_chain.h>
#include <vlo/loop/pose_graph.h>

#include "synthetic_places.h"

using namespace vlo::loop;
using namespace vlo::loop::test;
using vlo::invertPositive;
using vlo::Matrix6d;

TEST(PoseGraph, ALoopEdgeClosesADriftingChain)
{
	// Ten 1 m steps along x and back to the start; the odometry says each step is 1.1 m.
	PoseGraph graph;
	std::vector<Eigen::Isometry3d> truth;
	for (int k = 0; k <= 10; ++k) truth.push_back(pose2d(k <= 5 ? k : 10 - k, 0, k <= 5 ? 0 : M_PI));
	Eigen::Isometry3d odometry = truth[0];
	graph.addNode(odometry);
	const Matrix6d step_information = invertPositive(distanceCovariance(1.0, 0.01, 0.001));
	for (int k = 1; k <= 10; ++k)
	{
		Eigen::Isometry3d step = truth[k - 1].inverse() * truth[k];
		step.translation() *= 1.1;
		odometry = odometry * step;
		graph.addNode(odometry);
		graph.addEdge(k - 1, k, step, step_information, 0);
	}
	EXPECT_NEAR(graph.pose(10).translation().x(), 0.0, 1e-9);  // out and back: the scale cancels on x...
	// ... the turn at the end does not: make the measured loop say node 10 is node 0, turned round.
	graph.addEdge(0, 10, truth[0].inverse() * truth[10], Matrix6d::Identity() * 1e6, 0);
	const PoseGraph::Summary s = graph.optimise();
	EXPECT_TRUE(s.usable);
	EXPECT_LT(s.final_cost, s.initial_cost + 1e-12);
	EXPECT_TRUE(graph.pose(0).isApprox(truth[0], 1e-12));  // the first node is fixed
	EXPECT_LT((graph.pose(10).translation() - truth[10].translation()).norm(), 1e-3);
	EXPECT_NEAR(Eigen::AngleAxisd(graph.pose(10).linear().transpose() * truth[10].linear()).angle(), 0.0, 1e-3);
}

TEST(PoseGraph, ALoopAgainstTheOdometryMeetsItInTheMiddle)
{
	// Two nodes 10 m apart by odometry, a loop edge of equal weight saying 12 m: the answer is 11 m.
	PoseGraph graph;
	graph.addNode(pose2d(0, 0, 0));
	graph.addNode(pose2d(10, 0, 0));
	const Matrix6d information = Matrix6d::Identity();
	graph.addEdge(0, 1, pose2d(10, 0, 0), information, 0);
	graph.addEdge(0, 1, pose2d(12, 0, 0), information, 0);
	graph.optimise();
	EXPECT_NEAR(graph.pose(1).translation().x(), 11.0, 1e-3);  // Ceres stops at a relative cost change of 1e-6
	EXPECT_NEAR(graph.pose(1).translation().y(), 0.0, 1e-9);
}

TEST(PoseGraph, DistanceCovarianceGrowsWithTheDistance)
{
	const Matrix6d cov = distanceCovariance(2.0, 0.01, 0.001);
	EXPECT_NEAR(cov(0, 0), 0.02 * 0.02, 1e-12);
	EXPECT_NEAR(cov(5, 5), 0.002 * 0.002, 1e-12);
	// Below the floor distance (0.1 m) it stops shrinking.
	EXPECT_NEAR(distanceCovariance(0.0, 0.01, 0.001)(0, 0), 0.001 * 0.001, 1e-15);
}
