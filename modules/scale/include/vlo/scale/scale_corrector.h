#pragma once
// The scale corrector (paper III-B): from images C(i-1), C(i), scan L(i-1) and the VO relative pose,
// the factor s that turns the VO's units into metres. Stateless and deterministic: the same input
// always gives the same estimate, so it can run on any frame pair in any order (a caller that goes
// frame by frame may hand C(i)'s tracking pyramid back for C(i-1) at the next frame: PyramidReuse).
#include <vlo/core/frame.h>
#include <vlo/scale/diagnostics.h>
#include <vlo/scale/options.h>
#include <vlo/scale/tracking.h>

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

namespace vlo::scale
{
/// The last C(i)'s Lucas-Kanade pyramid, which serves as C(i-1)'s when frame `frame` comes again as
/// the previous one (the same image: its pyramid is built once). Kept by the caller.
struct PyramidReuse
{
	std::size_t frame = 0;
	LkPyramid pyramid;  ///< empty: none kept
};

class ScaleCorrector
{
   public:
	/// Throws InputError for invalid options.
	explicit ScaleCorrector(const ScaleOptions& opt = {});
	const ScaleOptions& options() const { return opt_; }

	/// `prev` = C(i-1), `cur` = C(i): 8-bit grey images of the camera's size. `prevScan` = L(i-1)
	/// in the LiDAR frame, `camera_T_lidar` maps it into the camera optical frame. `cur_T_prev` =
	/// T_{C(i-1)}^{C(i)} from the VO (X_i = R X_{i-1} + t, t in VO units). The result's scale s
	/// multiplies VO lengths into metres: if the VO translation is k times too short, s = 1/k.
	/// Throws InputError for images that do not match the camera.
	ScaleEstimate estimate(const cv::Mat& prev, const PointCloud& prevScan, const cv::Mat& cur,
		const PinholeCamera& cam, const Eigen::Isometry3d& camera_T_lidar, const Eigen::Isometry3d& cur_T_prev) const;

	/// Same, from two frames of the pipeline (rig and image of `prev`, image of `cur`). With `reuse`,
	/// prev's pyramid is taken from it when it holds prev's, and cur's is left in it. `prev_scan`, when
	/// given, stands for prev.scan (the sweep moved to the image's time).
	ScaleEstimate estimate(const Frame& prev, const Frame& cur, const Eigen::Isometry3d& cur_T_prev,
		PyramidReuse* reuse = nullptr, const PointCloud* prev_scan = nullptr) const;

   private:
	ScaleEstimate estimate(const cv::Mat& prev, const PointCloud& prevScan, const cv::Mat& cur, const PinholeCamera& cam,
		const Eigen::Isometry3d& camera_T_lidar, const Eigen::Isometry3d& cur_T_prev, const LkPyramid* prev_pyramid,
		LkPyramid* cur_pyramid) const;

	ScaleOptions opt_;
};
}  // namespace vlo::scale
