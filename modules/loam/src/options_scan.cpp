// [loam.scan] and [loam.features].
#include "option_checks.h"
#include "vlo/loam/options.h"

#include <cmath>
#include <sstream>

namespace vlo::loam
{
using detail::require;

void ScanOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	ring_model = c.read_string_first_word(s, "ring_model", ring_model);
	VLO_NUM(n_rings, int);
	VLO_NUM(vfov_min_deg, double);
	VLO_NUM(vfov_max_deg, double);
	try
	{
		c.read_vector(s, "elevation_table_deg", elevation_table_deg, elevation_table_deg);
	}
	catch (const std::exception&)
	{
		failInput("[" + s + "] elevation_table_deg", "not a list of numbers");
	}
	VLO_NUM(fov_margin_deg, double);
	VLO_NUM(min_range, double);
	VLO_NUM(max_range, double);
	VLO_NUM(scan_period, double);
	VLO_BOOL(clockwise);
	VLO_BOOL(time_from_first_point);
	VLO_NUM(sweep_start_azimuth_deg, double);
	VLO_BOOL(deskew);
	VLO_BOOL(point_times);
	VLO_NUM(deskew_reference, double);
	VLO_NUM(max_deskew_passes, int);
	VLO_NUM(deskew_tolerance, double);
	VLO_NUM(deskew_tolerance_deg, double);
}

void ScanOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(ring_model, "uniform | hdl64 (two-block HDL-64E) | table");
	MRPT_SAVE_CONFIG_VAR_COMMENT(n_rings, "beams of the uniform model");
	MRPT_SAVE_CONFIG_VAR_COMMENT(vfov_min_deg, "lowest beam elevation (uniform) [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(vfov_max_deg, "highest beam elevation (uniform) [deg]");
	std::ostringstream tab;
	tab << "[";
	for (std::size_t i = 0; i < elevation_table_deg.size(); ++i)
		tab << (i ? " " : "") << elevation_table_deg[i];
	tab << "]";
	c.write(s, "elevation_table_deg", tab.str(), mrpt::config::MRPT_SAVE_NAME_PADDING(),
		mrpt::config::MRPT_SAVE_VALUE_PADDING(), "beam elevations (table model) [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fov_margin_deg, "accepted beyond the extreme beams [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_range, "closer returns are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_range, "farther returns are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(scan_period, "seconds per sweep");
	MRPT_SAVE_CONFIG_VAR_COMMENT(clockwise, "sensor spins clockwise seen from above (Velodyne)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(time_from_first_point, "sweep starts at the first point's azimuth");
	MRPT_SAVE_CONFIG_VAR_COMMENT(sweep_start_azimuth_deg, "sweep start when not from the first point [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew, "undistort features with the initial-guess motion (times from the azimuth)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(point_times, "scans with per-point times: deskew with them to the frame's time");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew_reference, "sweep fraction [0,1] the scan pose refers to");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_deskew_passes, "deskew + register again while the motion found changes");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew_tolerance, "... by more than this [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew_tolerance_deg, "... or this [deg]");
}

void ScanOptions::validate() const
{
	const std::string s = "loam.scan";
	require(ring_model == "uniform" || ring_model == "hdl64" || ring_model == "table", s, "ring_model",
		"'" + ring_model + "' is not one of uniform, hdl64, table");
	if (ring_model == "uniform")
	{
		require(n_rings >= 2 && n_rings <= 256, s, "n_rings", "must be in [2, 256]");
		require(vfov_max_deg > vfov_min_deg, s, "vfov_max_deg", "must exceed vfov_min_deg");
		require(vfov_min_deg > -90 && vfov_max_deg < 90, s, "vfov_min_deg", "elevations must be within (-90, 90)");
	}
	if (ring_model == "table")
	{
		require(elevation_table_deg.size() >= 2, s, "elevation_table_deg", "needs at least 2 beams");
		for (double e : elevation_table_deg)
			require(std::isfinite(e) && e > -90 && e < 90, s, "elevation_table_deg", "elevations must be within (-90, 90)");
	}
	require(fov_margin_deg >= 0, s, "fov_margin_deg", "must be >= 0");
	require(min_range >= 0, s, "min_range", "must be >= 0");
	require(max_range > min_range, s, "max_range", "must exceed min_range");
	require(scan_period > 0, s, "scan_period", "must be > 0");
	require(deskew_reference >= 0 && deskew_reference <= 1, s, "deskew_reference", "must be in [0, 1]");
	require(max_deskew_passes >= 1 && max_deskew_passes <= 10, s, "max_deskew_passes", "must be in [1, 10]");
	require(deskew_tolerance >= 0, s, "deskew_tolerance", "must be >= 0");
	require(deskew_tolerance_deg >= 0, s, "deskew_tolerance_deg", "must be >= 0");
}

void FeatureOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_NUM(curvature_half_window, int);
	VLO_NUM(n_sectors, int);
	VLO_NUM(max_sharp, int);
	VLO_NUM(max_less_sharp, int);
	VLO_NUM(max_flat, int);
	VLO_NUM(sharp_threshold, double);
	VLO_NUM(flat_threshold, double);
	VLO_NUM(suppress_gap_sq, double);
	VLO_BOOL(sharp_local_max);
	VLO_NUM(less_flat_leaf, double);
	VLO_NUM(less_flat_threshold, double);
	VLO_BOOL(reject_occluded);
	VLO_NUM(occlusion_gap_sq, double);
	VLO_NUM(occlusion_angle, double);
	VLO_BOOL(reject_parallel);
	VLO_NUM(parallel_ratio, double);
	VLO_NUM(min_rings, int);
	VLO_NUM(min_sharp, int);
	VLO_NUM(min_flat, int);
}

void FeatureOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(curvature_half_window, "neighbours per side for the curvature");
	MRPT_SAVE_CONFIG_VAR_COMMENT(n_sectors, "sectors per ring");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_sharp, "sharp (edge) points per sector");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_less_sharp, "less-sharp points per sector (sharp included)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_flat, "flat (plane) points per sector");
	MRPT_SAVE_CONFIG_VAR_COMMENT(sharp_threshold, "curvature above: edge candidate [m^2]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(flat_threshold, "curvature below: plane candidate [m^2]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(suppress_gap_sq, "neighbour suppression stops at this gap [m^2]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(sharp_local_max, "edges only at curvature peaks (sparse rings smear edges otherwise)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(less_flat_leaf, "voxel size of the less-flat downsampling [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(less_flat_threshold, "less-flat (plane) points: curvature below [m^2] (A-LOAM: no limit)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reject_occluded, "drop points next to occlusion boundaries");
	MRPT_SAVE_CONFIG_VAR_COMMENT(occlusion_gap_sq, "gap between neighbours that may be an occlusion [m^2]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(occlusion_angle, "... when their beams are closer than this [rad]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reject_parallel, "drop points on surfaces nearly parallel to the beam");
	MRPT_SAVE_CONFIG_VAR_COMMENT(parallel_ratio, "both gaps^2 > ratio * range^2: parallel");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_rings, "fewer populated rings: frame skipped");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_sharp, "fewer sharp points: frame skipped");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_flat, "fewer flat points: frame skipped");
}

void FeatureOptions::validate() const
{
	const std::string s = "loam.features";
	require(curvature_half_window >= 1 && curvature_half_window <= 50, s, "curvature_half_window", "must be in [1, 50]");
	require(n_sectors >= 1, s, "n_sectors", "must be >= 1");
	require(max_sharp >= 0, s, "max_sharp", "must be >= 0");
	require(max_less_sharp >= max_sharp, s, "max_less_sharp", "must be >= max_sharp");
	require(max_flat >= 0, s, "max_flat", "must be >= 0");
	require(sharp_threshold >= 0, s, "sharp_threshold", "must be >= 0");
	require(flat_threshold >= 0, s, "flat_threshold", "must be >= 0");
	require(suppress_gap_sq >= 0, s, "suppress_gap_sq", "must be >= 0");
	require(less_flat_leaf > 0, s, "less_flat_leaf", "must be > 0");
	require(less_flat_threshold > 0, s, "less_flat_threshold", "must be > 0");
	require(occlusion_gap_sq >= 0, s, "occlusion_gap_sq", "must be >= 0");
	require(occlusion_angle >= 0, s, "occlusion_angle", "must be >= 0");
	require(parallel_ratio >= 0, s, "parallel_ratio", "must be >= 0");
	require(min_rings >= 1, s, "min_rings", "must be >= 1");
	require(min_sharp >= 0, s, "min_sharp", "must be >= 0");
	require(min_flat >= 0, s, "min_flat", "must be >= 0");
}

}  // namespace vlo::loam
