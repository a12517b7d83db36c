#pragma once
// Visual depth v_j of a matched pair by midpoint triangulation with the VO relative pose. v_j is in
// the units of the VO's translation, so s_j = d_j / v_j is the factor that makes the VO metric.
#include <opencv2/core/types.hpp>

#include <Eigen/Geometry>

namespace vlo::scale
{
enum class TriangulationStatus
{
	Ok,
	Behind,  ///< the rays meet behind one of the cameras
	LowParallax  ///< rays closer to parallel than the minimum angle (also: no translation)
};

struct Triangulated
{
	TriangulationStatus status = TriangulationStatus::LowParallax;
	Eigen::Vector3d X = Eigen::Vector3d::Zero();  ///< point in the C(i-1) optical frame
	double depth = 0;  ///< v_j: X.z, depth along the optical axis of C(i-1), like d_j
	double parallax_deg = 0;  ///< angle between the two viewing rays
};

/// Midpoint of the shortest segment between the ray of x_prev from C(i-1) and that of x_cur from C(i).
/// cur_T_prev maps C(i-1) points into C(i). Exact for noise-free correspondences.
Triangulated triangulateMidpoint(const Eigen::Matrix3d& Kinv, const Eigen::Isometry3d& cur_T_prev,
	cv::Point2f x_prev, cv::Point2f x_cur, double min_parallax_deg);
}  // namespace vlo::scale
