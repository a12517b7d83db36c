#pragma once
// The errors of a real spinning LiDAR and camera, each a named parameter with its source
// (doc/SIMULATOR.md, "Realism"). Off (`enabled = false`, SimConfig's default) the sensors are exact:
// what the unit tests need. vlo-sim turns it on unless --no-realism.
#include <string>

namespace vlo::sim
{
struct LidarModel;

/// Per-beam errors of the LiDAR.
struct LidarRealism
{
	// Per-laser calibration left over after the factory's: each laser fires along its nominal
	// elevation and azimuth plus a fixed offset, and adds a fixed range offset; the points are
	// computed with the nominal angles, as a driver with the shipped calibration does.
	double elevation_error_deg = 0.06;  ///< 1 sigma of each laser's elevation offset
	/// ... plus an offset common to every laser (0 in the preset; KITTI's HDL-64 fires 0.22 deg higher
	/// than its shipped calibration says, doc/LOAM.md "A common elevation error")
	double common_elevation_error_deg = 0;
	double azimuth_error_deg = 0.06;  ///< 1 sigma of each laser's azimuth offset
	double range_offset_m = 0.015;  ///< 1 sigma of each laser's range offset

	// Range noise: sigma = base_sigma (1 + (r / R_max)^2) (doubles at the detection limit R_max, a
	// weak echo), combined with the spread of the beam's footprint over a tilted surface,
	// r * divergence / 2 * tan(incidence).
	double base_sigma = 0.02;  ///< m, 1 sigma on a strong echo (HDL-64E S2: < 2 cm 1 sigma)
	double divergence_mrad = 2.0;  ///< full beam divergence

	// Detection: the echo's power goes with reflectivity * cos(incidence)^incidence_exponent / r^2, so
	// the largest range is R_max = range_at_10_percent * sqrt(rho cos^k / 0.1) (a logistic edge of
	// relative width detection_softness around it). rho from the surface's grey: rho_dark + (rho_bright -
	// rho_dark) grey / 255.
	double range_at_10_percent = 50.0;  ///< m (HDL-64E S2: 50 m on pavement, 10 %; 120 m on cars, 80 %)
	double incidence_exponent = 0.5;  ///< asphalt and walls scatter more than Lambertian toward the sensor
	double detection_softness = 0.08;
	double rho_dark = 0.05, rho_bright = 0.8;
	double dropout = 0.005;  ///< lost returns regardless (as the exact sensor's)

	// Mixed returns: where the footprint straddles a depth edge (gap above edge_min_gap), the echoes of
	// both surfaces merge into one range between them with this probability, if they are closer than
	// mixed_max_gap (farther apart the sensor separates them and reports the nearer surface's).
	double mixed_probability = 0.5;
	double edge_min_gap = 0.15, mixed_max_gap = 3.0;  ///< m

	// Intensity (reflectivity as the sensor reports it, 0..1): per-laser gain error and noise.
	double intensity_gain_error = 0.1;  ///< 1 sigma, relative, per laser
	double intensity_noise = 0.03;  ///< 1 sigma, of full scale
};

/// Errors of the camera image.
struct CameraRealism
{
	double blur_sigma_px = 0.6;  ///< Gaussian point spread of lens and focus, output pixels
	double read_noise = 2.0;  ///< grey levels, 1 sigma (dark noise)
	double shot_noise_gain = 0.04;  ///< grey levels per electron: shot-noise variance = gain * level
	// Auto-exposure: the log gain follows an AR(1) process from frame to frame, x_k = a x_{k-1} + e_k.
	double exposure_ar = 0.9;
	double exposure_step = 0.02;  ///< 1 sigma of e_k: stationary spread 0.02 / sqrt(1 - 0.81) = 4.6 %
};

struct SensorRealism
{
	bool enabled = false;
	LidarRealism lidar;
	CameraRealism camera;
};

/// The preset for a LiDAR model: the HDL-64E S2's values, the VLP-16's where its datasheet differs
/// (range accuracy +-3 cm, divergence 3 mrad).
SensorRealism realisticSensors(const LidarModel& lidar);
}  // namespace vlo::sim
