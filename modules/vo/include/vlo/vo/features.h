#pragma once
// ORB features of one image: keypoints (level-0 pixels, octave = pyramid level, angle in degrees),
// 32-byte descriptors, the scale pyramid they came from, and a grid for window queries.
#include <opencv2/core.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

namespace vlo::vo
{
/// Scale of every pyramid level and the matching keypoint variances (sigma = scale).
struct ScalePyramid
{
	explicit ScalePyramid(int levels = 8, double factor = 1.2);
	int levels;
	double factor, log_factor;
	std::vector<double> scale, inv_scale, sigma2, inv_sigma2;
	/// Level at which a point whose scale-invariance range ends at max_dist is seen from dist.
	int predictLevel(double max_dist, double dist) const;
};

/// Buckets keypoint indices by cell for radius queries.
class FeatureGrid
{
   public:
	void build(const std::vector<cv::KeyPoint>& keys, int width, int height, int cell = 16);
	/// Keypoints within the square of half size r around (x, y) and within the level range
	/// (max_level < 0: any level), in a fixed (cell by cell) order.
	std::vector<int> inArea(double x, double y, double r, int min_level = 0, int max_level = -1) const;

   private:
	int cell_ = 16, cols_ = 0, rows_ = 0;
	std::vector<std::vector<int>> cells_;
	std::vector<cv::Point2f> pts_;
	std::vector<int> levels_;
};

struct Features
{
	std::vector<cv::KeyPoint> keys;
	cv::Mat descriptors;  ///< N x 32, CV_8U
	FeatureGrid grid;
	int width = 0, height = 0;

	std::size_t size() const { return keys.size(); }
	const uint8_t* descriptor(std::size_t i) const { return descriptors.ptr<uint8_t>(static_cast<int>(i)); }
};

/// Hamming distance of two 256-bit descriptors. The bits are counted in parallel within each word
/// (without -mpopcnt, __builtin_popcountll is a call into libgcc's table lookup).
inline int hamming(const uint8_t* a, const uint8_t* b)
{
	uint64_t bytes = 0;  // per byte: the set bits of that byte in the four words (<= 32)
	for (int i = 0; i < 32; i += 8)
	{
		uint64_t x, y;
		std::memcpy(&x, a + i, 8);
		std::memcpy(&y, b + i, 8);
		x ^= y;
		x -= (x >> 1) & 0x5555555555555555ULL;
		x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
		bytes += (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
	}
	const uint64_t pairs = (bytes & 0x00ff00ff00ff00ffULL) + ((bytes >> 8) & 0x00ff00ff00ff00ffULL);  // <= 64 each
	return static_cast<int>((pairs * 0x0001000100010001ULL) >> 48);  // <= 256: fits the top 16 bits
}
}  // namespace vlo::vo
