#include <vlo/loam/scan_features.h>

#include <vlo/core/stopwatch.h>

namespace vlo::loam
{
ScanFeatureExtractor::ScanFeatureExtractor(const LoamOptions& o)
	: pre_(o.scan), extractor_(o.features), min_rings_(o.features.min_rings)
{
}

ScanFeatures ScanFeatureExtractor::extract(const PointCloud& scan)
{
	const auto t0 = SteadyClock::now();
	ScanFeatures s;
	const RingScan rs = pre_.process(scan);
	s.n_input = scan.size();
	s.n_valid = rs.points.size();
	s.n_invalid = rs.n_invalid;
	s.n_out_of_range = rs.n_out_of_range;
	s.n_out_of_fov = rs.n_out_of_fov;
	s.n_rings = rs.populatedRings(1);
	s.times_from_data = rs.times_from_data;
	if (s.n_valid > 0 && s.n_rings >= min_rings_) s.features = extractor_.extract(rs);
	s.ms = msSince(t0);
	return s;
}
}  // namespace vlo::loam
