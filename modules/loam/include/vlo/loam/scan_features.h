#pragma once
// What LOAM takes from a scan alone, before any pose: its points grouped by ring (preprocessing)
// and their edge and plane features. It depends on nothing but the options and the scan, so a run
// may compute it ahead, on another thread, and hand it to LidarOdometry::process.
#include <vlo/core/frame.h>
#include <vlo/loam/features.h>
#include <vlo/loam/options.h>
#include <vlo/loam/rings.h>

#include <cstddef>

namespace vlo::loam
{
struct ScanFeatures
{
	std::size_t n_input = 0;  ///< points given
	std::size_t n_valid = 0, n_invalid = 0, n_out_of_range = 0, n_out_of_fov = 0;  ///< kept / dropped by preprocessing
	int n_rings = 0;  ///< populated rings
	bool times_from_data = false;  ///< the points carry the sensor's times
	/// Empty when the scan has no valid point or fewer than features.min_rings populated rings.
	FeatureSet features;
	double ms = 0;  ///< time taken
};

class ScanFeatureExtractor
{
   public:
	/// The options must be valid (LoamOptions::validate).
	explicit ScanFeatureExtractor(const LoamOptions& o);
	/// Not thread-safe (reuses buffers): one extractor per thread.
	ScanFeatures extract(const PointCloud& scan);
	const RingModel& model() const { return pre_.model(); }

   private:
	ScanPreprocessor pre_;
	FeatureExtractor extractor_;
	int min_rings_;
};
}  // namespace vlo::loam
