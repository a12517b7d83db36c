#pragma once
// ORB features over a scale pyramid, spread over the image. Per level: FAST corners (the lower
// threshold only where a cell has no strong corner, as ORB-SLAM), spread by adaptive non-maximal
// suppression ("anms") or by ORB-SLAM's quadtree ("quadtree"), intensity-centroid orientation, and
// OpenCV's rBRIEF descriptor on the level's image. "opencv": cv::ORB as it is (clusters on strong texture).
#include <vlo/vo/features.h>
#include <vlo/vo/options.h>

#include <opencv2/features2d.hpp>

namespace vlo::vo
{
class OrbExtractor
{
   public:
	explicit OrbExtractor(const OrbOptions& opt);
	/// gray: 8-bit single channel. The grid of the result is built.
	Features extract(const cv::Mat& gray) const;
	const ScalePyramid& pyramid() const { return pyramid_; }

   private:
	/// The level's spread corners with their orientation, in the level's coordinates.
	std::vector<cv::KeyPoint> detectSpread(const cv::Mat& level_image, int level) const;

	OrbOptions opt_;
	ScalePyramid pyramid_;
	std::vector<int> per_level_;  ///< features wanted per level
	std::vector<int> umax_;  ///< half widths of the orientation patch rows
	cv::Ptr<cv::ORB> orb_;  ///< detector "opencv"
	cv::Ptr<cv::ORB> orb_level_;  ///< rBRIEF of one level's corners on that level's image
};
}  // namespace vlo::vo
