#pragma once
// Options of the point-to-point ICP odometry (KISS-ICP's method), INI section [icp].
// Every default is the value used when the key is absent; KISS-ICP's defaults serve any spinning
// LiDAR, which is why the shipped sensor INIs need no [icp] section.
#include <vlo/core/option_table.h>

namespace vlo::icp
{
struct IcpOptions : public OptionSet
{
	double min_range = 1.0;  ///< closer returns (vehicle body) are dropped [m]
	double max_range = 100.0;  ///< farther returns are dropped; also the lever of the rotation error [m]
	double voxel_size = 1.0;  ///< edge of the local map's voxels [m]; KISS-ICP: max_range / 100
	int max_points_per_voxel = 20;
	double map_radius = 100.0;  ///< voxels farther from the sensor are dropped [m]
	double initial_threshold = 2.0;  ///< correspondence scale sigma before any motion was seen [m]
	double min_motion = 0.1;  ///< model deviations smaller than this do not update sigma [m]
	int max_iterations = 500;  ///< Gauss-Newton iterations per frame
	double convergence = 1e-4;  ///< an update smaller than this (norm of the 6-vector) ends them
	double max_guess_translation = 5.0;  ///< an external motion guess longer than this is ignored [m]
	double max_guess_rotation_deg = 30.0;  ///< ... or turning more than this [deg]

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};
}  // namespace vlo::icp
