#pragma once
// Scan preprocessing: which beam (ring) each return came from, when in the sweep it was measured,
// and which returns to drop. The sensor's ring ids and per-point times are used when the scan has
// them; otherwise both come from geometry: the ring from the elevation angle (the ring model), the
// time from the azimuth.
#include <vlo/core/frame.h>
#include <vlo/loam/options.h>
#include <vlo/loam/slice_table.h>
#include <vlo/loam/types.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace vlo::loam
{
/// Ring ids from the data at or above this are dropped (as out of the field of view).
constexpr int kMaxRings = 256;

/// Beam elevations of a spinning LiDAR and the elevation -> ring lookup.
class RingModel
{
   public:
	/// Builds the beam table from the options (validates them; throws InputError).
	explicit RingModel(const ScanOptions& o);

	int numRings() const { return static_cast<int>(elevations_deg_.size()); }
	/// Beam elevations in degrees, ascending: ring 0 is the lowest beam.
	const std::vector<double>& elevationsDeg() const { return elevations_deg_; }

	/// Ring of a return at height z and horizontal distance rho; -1 outside the field of view.
	/// Compares tan(elevation) = z / rho against the table, so no atan per point.
	int ringOf(float z, float rho) const;
	/// The same, but clamped to the first/last ring outside the field of view (-1 for NaN).
	int nearestRing(float z, float rho) const;

	/// The HDL-64E layout: 32 beams from +2 to -8.33 deg in 1/3 deg steps, 32 from -8.83 to
	/// -24.33 deg in 1/2 deg steps (nominal values, as A-LOAM uses them).
	static std::vector<double> hdl64Elevations();

   private:
	std::vector<double> elevations_deg_;
	/// tan of the midpoints between consecutive beams (ringOf runs for every return)
	SliceTable tan_bounds_;
	float tan_lo_ = 0, tan_hi_ = 0;  ///< accepted range, margin included
};

/// atan2 with |error| < 2e-5 rad, a few times faster than std::atan2.
inline float fastAtan2(float y, float x)
{
	const float ax = std::fabs(x), ay = std::fabs(y);
	const float mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
	if (mx == 0.0f) return 0.0f;
	const float a = mn / mx, s = a * a;
	float r = (((((-0.01172120f * s + 0.05265332f) * s - 0.11643287f) * s + 0.19354346f) * s -
				   0.33262347f) *
					  s +
				  0.99997726f) *
		a;
	if (ay > ax) r = 1.57079637f - r;
	if (x < 0) r = 3.14159274f - r;
	return y < 0 ? -r : r;
}

/// Drops invalid, too close/far and out-of-view returns, assigns rings and sweep times, and
/// groups the points by ring in time order. A scan with ring ids keeps them (no elevation table:
/// any beam layout works) and has max(the model's rings, highest id + 1) rings. Never throws on bad
/// data (the counts say what was dropped); an empty or all-invalid scan gives a RingScan without points.
class ScanPreprocessor
{
   public:
	explicit ScanPreprocessor(const ScanOptions& o);
	RingScan process(const PointCloud& scan);
	const RingModel& model() const { return model_; }

   private:
	ScanOptions opt_;
	RingModel model_;
	std::vector<std::int16_t> ring_of_;  ///< per input point: its ring, -1 if dropped (reused between scans)
	std::vector<std::size_t> count_;
};
}  // namespace vlo::loam
