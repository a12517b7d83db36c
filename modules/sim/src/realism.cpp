#include <vlo/sim/config.h>
#include <vlo/sim/realism.h>

namespace vlo::sim
{
SensorRealism realisticSensors(const LidarModel& lidar)
{
	SensorRealism r;
	r.enabled = true;
	// VLP-16 datasheet: range accuracy +-3 cm (taken as 1 sigma), beam divergence 3 mrad.
	if (lidar.name == "vlp16") r.lidar.base_sigma = 0.03, r.lidar.divergence_mrad = 3.0;
	return r;
}
}  // namespace vlo::sim
