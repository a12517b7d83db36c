#pragma once
// One realistic LiDAR unit: its lasers' calibration errors (drawn once from the seed, fixed for the
// drive, as a real unit's are) and what becomes of each echo: range noise, detection, mixed returns,
// intensity (LidarRealism's model, doc/SIMULATOR.md "Realism").
#include <vlo/core/frame.h>
#include <vlo/sim/realism.h>

#include <cstdint>
#include <vector>

namespace vlo::sim
{
class Rng;

/// What a beam met, before the sensor's errors.
struct Echo
{
	double range = 0;  ///< m, along the beam
	double cos_incidence = 1;  ///< between the beam and the surface normal
	double edge_range = 0;  ///< range of the other surface where the footprint straddles a depth edge, else 0
	uint8_t gray = 0;  ///< the surface's grey level
};

class LidarErrors
{
   public:
	/// The unit's calibration errors for `lasers` beams, from `seed`'s own stream.
	LidarErrors(const LidarRealism& p, int lasers, uint64_t seed);
	const LidarRealism& params() const { return p_; }

	double elevationOffset(int laser) const { return elevation_[laser]; }  ///< rad
	double azimuthOffset(int laser) const { return azimuth_[laser]; }  ///< rad
	double rangeOffset(int laser) const { return range_[laser]; }  ///< m

	/// Largest range at which an echo from grey `gray` at this incidence is detected (m).
	double detectionRange(uint8_t gray, double cos_incidence) const;
	/// Range noise, 1 sigma (m).
	double rangeSigma(double range, double cos_incidence, double detection_range) const;

	/// The measured range and intensity (0..1) of laser `laser`'s echo; false if it is lost. Always
	/// draws the same count of random numbers, so one lost echo never changes the others' noise.
	bool measure(int laser, const Echo& e, Rng& rng, double& range, float& intensity) const;

   private:
	LidarRealism p_;
	std::vector<double> elevation_, azimuth_, range_, gain_;
};

/// A raw sweep as KITTI raw's .bin and most recordings give it: no per-point time or ring, intensity
/// 0..1 (a rolling sweep's is the sensor's 8-bit 0..255).
void dropPointTimes(PointCloud& cloud);
}  // namespace vlo::sim
