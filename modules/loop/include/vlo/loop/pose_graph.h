#pragma once
// A pose graph over the keyframes, optimised with Ceres (the pattern of Ceres' pose_graph_3d example):
// each node a position and a unit quaternion, each edge a measured relative pose a_T_b with its
// information over the residual [translation of b in a; 2 x vector part of the rotation error], loop
// edges under a Huber loss. The first node is held fixed.
#include <vlo/core/pose_information.h>

#include <Eigen/Geometry>
#include <vector>

namespace vlo::loop
{

class PoseGraph
{
   public:
	/// Returns the node's index; `initial` is its starting estimate.
	std::size_t addNode(const Eigen::Isometry3d& initial);
	/// `huber` [sigmas of the whitened residual], 0 = plain least squares.
	void addEdge(std::size_t a, std::size_t b, const Eigen::Isometry3d& a_T_b, const Matrix6d& information, double huber);

	struct Summary
	{
		double seconds = 0;
		int iterations = 0;
		double initial_cost = 0, final_cost = 0;
		bool usable = true;  ///< Ceres' verdict: false leaves the estimates where they were
	};
	/// Single-threaded (deterministic, and it shares the machine with the odometry).
	Summary optimise(int max_iterations = 100);

	Eigen::Isometry3d pose(std::size_t node) const;
	std::size_t size() const { return nodes_.size(); }
	std::size_t edgeCount() const { return edges_.size(); }

   private:
	struct Node
	{
		Eigen::Vector3d p;
		Eigen::Quaterniond q;
	};
	struct Edge
	{
		std::size_t a, b;
		Eigen::Vector3d p;
		Eigen::Quaterniond q;
		Matrix6d sqrt_information;
		double huber;
	};
	std::vector<Node> nodes_;
	std::vector<Edge> edges_;
};

}  // namespace vlo::loop
