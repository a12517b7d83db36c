#include <vlo/rosbag/transform_tree.h>

namespace vlo::rosbag_io
{
namespace
{
std::string frameName(const std::string& id) { return !id.empty() && id[0] == '/' ? id.substr(1) : id; }
}  // namespace

Eigen::Isometry3d toIsometry(const geometry_msgs::Transform& t)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized().toRotationMatrix();
	T.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
	return T;
}

void TransformTree::add(const std::string& parent, const std::string& child, const Eigen::Isometry3d& parent_T_child)
{
	parent_[frameName(child)] = {frameName(parent), parent_T_child};
}

void TransformTree::add(const geometry_msgs::TransformStamped& t)
{
	add(t.header.frame_id, t.child_frame_id, toIsometry(t.transform));
}

std::pair<std::string, Eigen::Isometry3d> TransformTree::fromRoot(const std::string& frame) const
{
	std::string f = frameName(frame);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	for (std::size_t hops = 0; hops <= parent_.size(); ++hops)  // a cycle ends the walk
	{
		const auto it = parent_.find(f);
		if (it == parent_.end()) break;
		T = it->second.second * T;
		f = it->second.first;
	}
	return {f, T};
}

std::optional<Eigen::Isometry3d> TransformTree::lookup(const std::string& a, const std::string& b) const
{
	const auto [root_a, root_T_a] = fromRoot(a);
	const auto [root_b, root_T_b] = fromRoot(b);
	if (root_a != root_b) return std::nullopt;
	return root_T_a.inverse() * root_T_b;
}

void StaticTfFilter::add(const geometry_msgs::TransformStamped& t)
{
	const std::string parent = frameName(t.header.frame_id), child = frameName(t.child_frame_id);
	const Eigen::Isometry3d T = toIsometry(t.transform);
	const auto [it, inserted] = edges_.try_emplace({parent, child}, Edge{parent, child, T});
	if (!inserted && !it->second.T.isApprox(T, 1e-9)) it->second.changes = true;
}

void StaticTfFilter::addStaticTo(TransformTree& tree) const
{
	for (const auto& [key, e] : edges_)
		if (!e.changes && !tree.lookup(e.parent, e.child)) tree.add(e.parent, e.child, e.T);
}
}  // namespace vlo::rosbag_io
