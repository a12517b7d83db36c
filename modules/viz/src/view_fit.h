#pragma once
// Internal: an oblique pinhole view that frames a set of 3D points, used by the 3D map snapshot both
// to set the OpenGL camera and to project overlays (trajectories, markers) with the same model.
#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

#include <optional>
#include <vector>

namespace vlo::viz
{
struct ViewCamera
{
	Eigen::Isometry3d world_T_cam = Eigen::Isometry3d::Identity();  ///< optical frame: z forward, y down
	double f = 1, cx = 0, cy = 0;
	int width = 0, height = 0;
	double near = 0.1, far = 1000;  ///< clip distances that contain every fitted point

	/// Pixel of a world point, or nothing when it is behind the near plane.
	std::optional<cv::Point2d> project(const Eigen::Vector3d& p) const;
};

/// Camera looking at the centre of `pts` from azimuth `az` (radians from +x towards +y) and elevation
/// `el` above the horizon, with vertical field of view `fovy`, at the smallest distance (and shifted
/// principal point) that puts every point inside `content` (a rectangle of a width x height image).
ViewCamera fitView(const std::vector<Eigen::Vector3d>& pts, double az, double el, double fovy, const cv::Rect& content,
	int width, int height);

/// Azimuth that looks across the main horizontal axis of `pts` (from its right-hand side, skewed
/// by 30 degrees) so that a long route fills the image instead of being foreshortened.
double acrossAzimuth(const std::vector<Eigen::Vector3d>& pts);
}  // namespace vlo::viz
