// [icp]: values are type-checked by the caller's config loader (RunConfig), ranges here.
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>
#include <vlo/icp/options.h>

namespace vlo::icp
{
void IcpOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	MRPT_LOAD_CONFIG_VAR(min_range, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_range, double, c, s);
	MRPT_LOAD_CONFIG_VAR(voxel_size, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_points_per_voxel, int, c, s);
	MRPT_LOAD_CONFIG_VAR(map_radius, double, c, s);
	MRPT_LOAD_CONFIG_VAR(initial_threshold, double, c, s);
	MRPT_LOAD_CONFIG_VAR(min_motion, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_iterations, int, c, s);
	MRPT_LOAD_CONFIG_VAR(convergence, double, c, s);
	MRPT_LOAD_CONFIG_VAR(deskew, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(deskew_from_azimuth, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(max_guess_translation, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_guess_rotation_deg, double, c, s);
}

void IcpOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_range, "closer returns are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_range, "farther returns are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(voxel_size, "local map voxel edge [m] (scan kept at 0.5x, registered at 1.5x)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_points_per_voxel, "points a map voxel keeps");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_radius, "map voxels farther from the sensor are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(initial_threshold, "correspondence scale before any motion [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_motion, "smaller model deviations do not update the threshold [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_iterations, "Gauss-Newton iterations per frame");
	MRPT_SAVE_CONFIG_VAR_COMMENT(convergence, "update norm that ends the iterations");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew, "undistort with the predicted motion (per-point times)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(deskew_from_azimuth, "scans without times: times from the azimuth (not for motion-compensated scans)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_guess_translation, "longer external motion guesses are ignored [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_guess_rotation_deg, "external guesses turning more are ignored [deg]");
}

void IcpOptions::validate(const std::string& s) const
{
	const auto require = [&s](bool ok, const char* key, const char* problem) {
		if (!ok) failInput("[" + s + "] " + key, problem);
	};
	require(min_range >= 0, "min_range", "must be >= 0");
	require(max_range > min_range, "max_range", "must exceed min_range");
	require(voxel_size > 0, "voxel_size", "must be > 0");
	require(max_points_per_voxel >= 1, "max_points_per_voxel", "must be >= 1");
	require(map_radius > voxel_size, "map_radius", "must exceed voxel_size");
	require(initial_threshold > 0, "initial_threshold", "must be > 0");
	require(min_motion >= 0, "min_motion", "must be >= 0");
	require(max_iterations >= 1, "max_iterations", "must be >= 1");
	require(convergence > 0, "convergence", "must be > 0");
	require(max_guess_translation > 0, "max_guess_translation", "must be > 0");
	require(max_guess_rotation_deg > 0 && max_guess_rotation_deg <= 180, "max_guess_rotation_deg", "must be in (0, 180]");
}
}  // namespace vlo::icp
