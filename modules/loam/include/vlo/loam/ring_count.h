#pragma once
// How many beams (rings) a spinning LiDAR has, as its scans tell, and the check that refuses a
// ring model that contradicts them (a VLP-16 INI on HDL-64 data runs without a word otherwise).
#include <vlo/core/frame.h>
#include <vlo/loam/options.h>

#include <string>
#include <vector>

namespace vlo::loam
{
/// What one scan tells of its sensor's beams.
struct RingEvidence
{
	int rings = 0;  ///< 0: the scan cannot tell (fewer than 5000 returns beyond 2 m: no full sweep)
	double spacing_deg = 0;  ///< elevation between neighbouring beams (0 with ring ids)
	bool from_ids = false;  ///< counted from the scan's ring field
};

/// The number of distinct ring ids when the scan has_ring. Otherwise the returns of each azimuth
/// column (0.2 deg) are beams where their elevations differ by more than 0.15 deg: the spacing is
/// the median over columns of a column's elevation span over its beams - 1, and the rings are the
/// scan's elevation span over that spacing (beams that see only sky are missing from both), at
/// least the 90th percentile of beams per column.
RingEvidence countRings(const PointCloud& scan);

/// The INI's ring model against the first scans that tell: throws InputError naming the INI and the
/// model that fits when the data has at least 1.5 times the model's rings, or beams at least twice
/// as far apart (with ring ids: at most half the rings). Beams that never return make the data's
/// count a lower bound, so the second test looks at the spacing, which they do not change.
class RingModelCheck
{
   public:
	/// ini: the file named in the error; o: its [loam.scan] options.
	RingModelCheck(std::string ini, const ScanOptions& o, const std::vector<double>& model_elevations_deg);
	/// Looks at scans until three could tell, then judges their median; later scans cost nothing.
	void observe(const PointCloud& scan);
	bool done() const { return done_; }

   private:
	std::string ini_, model_;
	int model_rings_;
	double model_spacing_deg_;
	std::vector<RingEvidence> seen_;
	bool done_ = false;
};

/// What fits a sensor with this many rings, e.g. "ini/kitti-hdl64.ini or ring_model = hdl64".
std::string ringModelAdvice(int rings);
}  // namespace vlo::loam
