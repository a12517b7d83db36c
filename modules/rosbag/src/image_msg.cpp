#include <vlo/core/error.h>
#include <vlo/rosbag/image_msg.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cctype>
#include <map>

namespace vlo::rosbag_io
{
namespace
{
struct Encoding
{
	int cv_type;  ///< of the message's pixels
	int to_gray;  ///< cv::cvtColor code, -1 = already grey
};

const std::map<std::string, Encoding>& encodings()
{
	static const std::map<std::string, Encoding> e = {{"mono8", {CV_8UC1, -1}}, {"8UC1", {CV_8UC1, -1}},
		{"mono16", {CV_16UC1, -1}}, {"16UC1", {CV_16UC1, -1}}, {"rgb8", {CV_8UC3, cv::COLOR_RGB2GRAY}},
		{"bgr8", {CV_8UC3, cv::COLOR_BGR2GRAY}}, {"rgba8", {CV_8UC4, cv::COLOR_RGBA2GRAY}},
		{"bgra8", {CV_8UC4, cv::COLOR_BGRA2GRAY}}};
	return e;
}

mrpt::img::CImage toCImage(cv::Mat gray) { return mrpt::img::CImage(gray, mrpt::img::DEEP_COPY); }
}  // namespace

mrpt::img::CImage decodeImage(const sensor_msgs::Image& msg, const std::string& where)
{
	const auto it = encodings().find(msg.encoding);
	if (it == encodings().end())
		failInput(where, "image encoding '" + msg.encoding + "' is not supported (mono8, mono16, rgb8, bgr8, rgba8, bgra8)");
	const Encoding enc = it->second;
	const int rows = static_cast<int>(msg.height), cols = static_cast<int>(msg.width);
	const std::size_t row_bytes = std::size_t(cols) * CV_ELEM_SIZE(enc.cv_type);
	if (rows <= 0 || cols <= 0 || msg.step < row_bytes || std::size_t(msg.step) * rows > msg.data.size())
		failInput(where,
			"image of " + std::to_string(cols) + "x" + std::to_string(rows) + " " + msg.encoding +
				", step " + std::to_string(msg.step) + " does not fit its " +
				std::to_string(msg.data.size()) + " bytes");
	const cv::Mat in(rows, cols, enc.cv_type, const_cast<std::uint8_t*>(msg.data.data()), msg.step);
	cv::Mat gray;
	if (enc.cv_type == CV_16UC1)
	{
		cv::Mat host = in;
		const bool host_big = cv::Mat_<std::uint16_t>(1, 1, std::uint16_t(1)).data[0] == 0;
		if (bool(msg.is_bigendian) != host_big)  // swap byte order
		{
			host = in.clone();
			for (int r = 0; r < rows; ++r)
				for (auto* p = host.ptr<std::uint16_t>(r); p != host.ptr<std::uint16_t>(r) + cols; ++p)
					*p = static_cast<std::uint16_t>((*p >> 8) | (*p << 8));
		}
		host.convertTo(gray, CV_8U, 255.0 / 65535.0);  // full range to full range, rounded
	}
	else if (enc.to_gray < 0)
		gray = in;
	else
		cv::cvtColor(in, gray, enc.to_gray);
	return toCImage(gray);
}

mrpt::img::CImage decodeCompressedImage(const sensor_msgs::CompressedImage& msg, const std::string& where)
{
	std::string format = msg.format;
	std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return std::tolower(c); });
	const bool known = format.find("compresseddepth") == std::string::npos &&
		(format.find("jpeg") != std::string::npos || format.find("jpg") != std::string::npos ||
			format.find("png") != std::string::npos);
	if (!known) failInput(where, "compressed image format '" + msg.format + "' is not supported (jpeg, png)");
	const cv::Mat gray = cv::imdecode(msg.data, cv::IMREAD_GRAYSCALE);
	if (gray.empty()) failInput(where, "cannot decode a " + msg.format + " image of " + std::to_string(msg.data.size()) + " bytes");
	return toCImage(gray);
}
}  // namespace vlo::rosbag_io
