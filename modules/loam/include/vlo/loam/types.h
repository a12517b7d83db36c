#pragma once
// Data passed between the LOAM stages.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vlo::loam
{
/// A preprocessed LiDAR return: position in the LiDAR frame, beam (ring) index counted from the
/// lowest beam, and its time in seconds from the frame's time: the scan's own (RingScan::
/// times_from_data), or else one from the azimuth that only orders the ring.
struct ScanPoint
{
	Eigen::Vector3f p = Eigen::Vector3f::Zero();
	float time = 0;
	int ring = 0;
};
using ScanPoints = std::vector<ScanPoint>;

/// A scan split into rings, each ring ordered by time (azimuth).
struct RingScan
{
	ScanPoints points;  ///< ring 0, then ring 1, ...
	std::vector<std::size_t> ring_begin;  ///< n_rings + 1 offsets into points
	std::size_t n_input = 0;  ///< points given
	std::size_t n_invalid = 0;  ///< NaN / infinite, or a time more than two sweeps from the frame's
	std::size_t n_out_of_range = 0;  ///< closer than min_range or farther than max_range
	std::size_t n_out_of_fov = 0;  ///< elevation outside every beam, or a ring id beyond kMaxRings
	bool rings_from_data = false;  ///< rings are the sensor's ids, not from the elevation table
	bool times_from_data = false;  ///< times are the scan's (and not all the same), not from the azimuth

	int numRings() const { return ring_begin.empty() ? 0 : static_cast<int>(ring_begin.size()) - 1; }
	std::size_t ringSize(int r) const { return ring_begin[r + 1] - ring_begin[r]; }
	int populatedRings(std::size_t min_points) const;
};

/// LOAM features of one scan, in the LiDAR frame. Every set is ordered by ring, then time.
struct FeatureSet
{
	ScanPoints sharp;  ///< strongest edge points: matched against the reference
	ScanPoints less_sharp;  ///< edge points the next scan matches against (sharp included)
	/// Per less_sharp point: 1 where its curvature window spans a jump to a farther surface, i.e.
	/// the point is on an object's outline against what lies behind (a silhouette), not on a crease.
	std::vector<std::uint8_t> less_sharp_silhouette;
	ScanPoints flat;  ///< flattest points: matched against the reference
	ScanPoints less_flat;  ///< plane points the next scan matches against (downsampled)
	int n_rings = 0;  ///< rings of the scan (0: unknown, the ring model's)
	bool rings_from_data = false;  ///< ring ids are the sensor's: a point's own ring is its elevation's

	bool empty() const { return less_sharp.empty() && less_flat.empty(); }
};
}  // namespace vlo::loam
