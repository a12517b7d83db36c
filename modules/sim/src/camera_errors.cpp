#include <vlo/sim/camera_errors.h>
#include <vlo/sim/rng.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr int kExposureMemory = 80;  // frames: a^80 < 3e-4 for a = 0.9
}  // namespace

double exposureGain(const CameraRealism& p, uint64_t seed, int k)
{
	double x = 0, weight = 1;
	for (int i = 0; i < kExposureMemory; ++i, weight *= p.exposure_ar)
	{
		Rng e = Rng::stream(seed, "exposure", static_cast<uint64_t>(static_cast<int64_t>(k) - i));
		x += weight * p.exposure_step * e.normal();
	}
	return std::exp(x);
}

void applyCameraErrors(cv::Mat& picture, const CameraRealism& p, double gain, Rng& rng)
{
	if (p.blur_sigma_px > 0) cv::GaussianBlur(picture, picture, cv::Size(0, 0), p.blur_sigma_px, p.blur_sigma_px, cv::BORDER_REFLECT);
	for (int r = 0; r < picture.rows; ++r)
	{
		float* row = picture.ptr<float>(r);
		for (int c = 0; c < picture.cols; ++c)
		{
			const double level = std::min(255.0, gain * row[c]);  // the sensor saturates before the noise
			const double sigma = std::sqrt(p.read_noise * p.read_noise + p.shot_noise_gain * level);
			row[c] = static_cast<float>(level + sigma * rng.normal());
		}
	}
}
}  // namespace vlo::sim
