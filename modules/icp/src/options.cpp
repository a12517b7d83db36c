// [icp]: every key with its type, range and help in one declaration list.
#include <vlo/icp/options.h>

namespace vlo::icp
{
void IcpOptions::declare(OptionTable& t)
{
	t.add("min_range", min_range, ">= 0", "closer returns are dropped [m]");
	t.add("max_range", max_range, "> 0", "farther returns are dropped [m]");
	t.add("voxel_size", voxel_size, "> 0", "local map voxel edge [m] (scan kept at 0.5x, registered at 1.5x)");
	t.add("max_points_per_voxel", max_points_per_voxel, ">= 1", "points a map voxel keeps");
	t.add("map_radius", map_radius, "> 0", "map voxels farther from the sensor are dropped [m]");
	t.add("initial_threshold", initial_threshold, "> 0", "correspondence scale before any motion [m]");
	t.add("min_motion", min_motion, ">= 0", "smaller model deviations do not update the threshold [m]");
	t.add("max_iterations", max_iterations, ">= 1", "Gauss-Newton iterations per frame");
	t.add("convergence", convergence, "> 0", "update norm that ends the iterations");
	t.add("max_guess_translation", max_guess_translation, "> 0", "longer external motion guesses are ignored [m]");
	t.add("max_guess_rotation_deg", max_guess_rotation_deg, "(0, 180]", "external guesses turning more are ignored [deg]");
}

void IcpOptions::checkRelations() const
{
	require(max_range > min_range, "max_range", "must exceed min_range");
	require(map_radius > voxel_size, "map_radius", "must exceed voxel_size");
}
}  // namespace vlo::icp
