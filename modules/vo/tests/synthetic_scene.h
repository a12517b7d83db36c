#pragma once
// A small textured world rendered by ray casting, for VO tests and the benchmark: a street of
// ground and two facades with a procedural texture (blobs and boxes, anti-aliased with a mipmap),
// and a camera driving along it. Camera convention: x right, y down, z forward.
#include <vlo/core/frame.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

namespace vlo::vo::test
{
struct StreetScene
{
	double camera_height = 1.65;  ///< ground plane at y = +height in the world (y down)
	double half_width = 8.0;  ///< facades at x = +-half_width
	double far = 150.0;  ///< rays that hit nothing nearer show the (uniform) sky
	unsigned seed = 7;
};

class StreetRenderer
{
   public:
	explicit StreetRenderer(const StreetScene& scene, const PinholeCamera& cam);
	/// Gray image seen by a camera with pose world_T_cam.
	cv::Mat render(const Eigen::Isometry3d& world_T_cam) const;

   private:
	double sample(int plane, double a, double b, double footprint) const;

	StreetScene scene_;
	PinholeCamera cam_;
	std::vector<cv::Mat> mip_;  ///< texture pyramid, CV_32F
	double texel_ = 0.04;  ///< metres per texel at level 0
};

/// KITTI-like camera 0 (718.856 px focal length) at 1241x376 or scaled down by `scale`.
PinholeCamera kittiCamera(double scale = 1.0);

/// world_T_cam of a drive forward at `speed` m per frame with a gentle weave; frame k.
Eigen::Isometry3d drivePose(int k, double speed = 1.0);
}  // namespace vlo::vo::test
