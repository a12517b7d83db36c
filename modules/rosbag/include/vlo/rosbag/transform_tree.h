#pragma once
// Static transforms of a bag (/tf_static, and /tf pairs that never change) as a tree of frames, with
// lookups along any chain through it.
#include <geometry_msgs/TransformStamped.h>

#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>

namespace vlo::rosbag_io
{
Eigen::Isometry3d toIsometry(const geometry_msgs::Transform& t);

class TransformTree
{
   public:
	/// parent_T_child (the child frame's pose in the parent frame); the latest edge to a child wins.
	void add(const std::string& parent, const std::string& child, const Eigen::Isometry3d& parent_T_child);
	void add(const geometry_msgs::TransformStamped& t);
	/// a_T_b: the pose of frame b in frame a, when both hang from the same root; "/" prefixes ignored.
	std::optional<Eigen::Isometry3d> lookup(const std::string& a, const std::string& b) const;
	bool empty() const { return parent_.empty(); }

   private:
	std::map<std::string, std::pair<std::string, Eigen::Isometry3d>> parent_;  // child -> (parent, parent_T_child)
	/// root_T_frame and the root's name.
	std::pair<std::string, Eigen::Isometry3d> fromRoot(const std::string& frame) const;
};

/// Collects /tf transforms and keeps those whose value never changes (within 1e-9).
class StaticTfFilter
{
   public:
	void add(const geometry_msgs::TransformStamped& t);
	/// Adds the unchanging pairs to tree (pairs it has already are left as they are).
	void addStaticTo(TransformTree& tree) const;

   private:
	struct Edge
	{
		std::string parent, child;
		Eigen::Isometry3d T;
		bool changes = false;
	};
	std::map<std::pair<std::string, std::string>, Edge> edges_;
};
}  // namespace vlo::rosbag_io
