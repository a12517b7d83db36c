#include <vlo/sim/lens.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

namespace vlo::sim
{
LensMaps pinholeLookup(const PinholeCamera& K)
{
	std::vector<cv::Point2f> px;
	px.reserve(static_cast<std::size_t>(K.width) * K.height);
	for (int r = 0; r < K.height; ++r)
		for (int c = 0; c < K.width; ++c) px.emplace_back(float(c), float(r));
	cv::Mat Km;
	cv::eigen2cv(K.K(), Km);
	std::vector<cv::Point2f> rays;
	const auto& d = K.dist;
	if (K.distortion == mrpt::img::DistortionModel::kannala_brandt)
		cv::fisheye::undistortPoints(px, rays, Km, cv::Vec4d(d[0], d[1], d[4], d[5]));
	else
		cv::undistortPoints(px, rays, Km, std::vector<double>(d.begin(), d.end()), cv::noArray(), cv::noArray(),
			cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-9));
	LensMaps maps;
	maps.x.create(K.height, K.width, CV_32F);
	maps.y.create(K.height, K.width, CV_32F);
	for (int r = 0, i = 0; r < K.height; ++r)
		for (int c = 0; c < K.width; ++c, ++i)
		{
			maps.x.at<float>(r, c) = float(K.fx * rays[i].x + K.cx);
			maps.y.at<float>(r, c) = float(K.fy * rays[i].y + K.cy);
		}
	return maps;
}

cv::Mat throughLens(const cv::Mat& pinhole, const LensMaps& maps)
{
	cv::Mat out;
	cv::remap(pinhole, out, maps.x, maps.y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
	return out;
}
}  // namespace vlo::sim
