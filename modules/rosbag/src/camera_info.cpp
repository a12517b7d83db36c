#include <vlo/core/error.h>
#include <vlo/rosbag/camera_info.h>

#include <algorithm>
#include <cmath>

namespace vlo::rosbag_io
{
bool isRectifiedTopic(const std::string& image_topic) { return image_topic.find("image_rect") != std::string::npos; }

PinholeCamera fromCameraInfo(const sensor_msgs::CameraInfo& msg, const std::string& image_topic, const std::string& where)
{
	const auto& D = msg.D;
	const std::string& model = msg.distortion_model;
	const auto bad = [&](const std::string& problem) { failInput(where, "CameraInfo: " + problem); };
	if (msg.binning_x > 1 || msg.binning_y > 1) bad("binning is not supported");
	if (msg.roi.width != 0 && (msg.roi.width != msg.width || msg.roi.height != msg.height))
		bad("a region of interest is not supported");

	PinholeCamera cam;
	cam.width = static_cast<int>(msg.width);
	cam.height = static_cast<int>(msg.height);
	const bool zero_d = std::all_of(D.begin(), D.end(), [](double d) { return d == 0; });
	const bool has_p = msg.P[0] > 0 && msg.P[5] > 0;
	if (isRectifiedTopic(image_topic) || zero_d)
	{
		// A rectified (or ideal) image: P holds its intrinsics (equal to K for an undistorted camera).
		const bool p = has_p;
		cam.fx = p ? msg.P[0] : msg.K[0];
		cam.cx = p ? msg.P[2] : msg.K[2];
		cam.fy = p ? msg.P[5] : msg.K[4];
		cam.cy = p ? msg.P[6] : msg.K[5];
		if (!(model.empty() || model == "plumb_bob" || model == "rational_polynomial" || model == "equidistant"))
			bad("unknown distortion_model '" + model + "' (plumb_bob, rational_polynomial, equidistant)");
	}
	else
	{
		cam.fx = msg.K[0];
		cam.cx = msg.K[2];
		cam.fy = msg.K[4];
		cam.cy = msg.K[5];
		const auto need = [&](std::size_t n) {
			if (D.size() != n)
				bad("distortion_model " + model + " needs " + std::to_string(n) + " coefficients in D, it has " +
					std::to_string(D.size()));
		};
		if (model == "plumb_bob")
		{
			need(5);
			cam.distortion = mrpt::img::DistortionModel::plumb_bob;
			std::copy(D.begin(), D.end(), cam.dist.begin());
		}
		else if (model == "rational_polynomial")
		{
			need(8);
			cam.distortion = mrpt::img::DistortionModel::plumb_bob;  // MRPT's plumb_bob has k4..k6 too
			std::copy(D.begin(), D.end(), cam.dist.begin());
		}
		else if (model == "equidistant")
		{
			need(4);
			cam.distortion = mrpt::img::DistortionModel::kannala_brandt;
			cam.dist = {D[0], D[1], 0, 0, D[2], D[3], 0, 0};
		}
		else
			bad("unknown distortion_model '" + model + "' (plumb_bob, rational_polynomial, equidistant)");
		for (double d : D)
			if (!std::isfinite(d)) bad("non-finite coefficient in D");
	}
	if (!(cam.fx > 0 && cam.fy > 0 && std::isfinite(cam.cx) && std::isfinite(cam.cy)))
		bad("no focal length in K / P");
	return cam;
}
}  // namespace vlo::rosbag_io
