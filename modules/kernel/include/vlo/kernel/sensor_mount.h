#pragma once
// Where a sensor sits on the vehicle, for a module that works in the sensor's frame: taken from the
// first frame the module sees (later frames keep it).
#include <vlo/core/frame.h>

#include <Eigen/Geometry>

namespace vlo::kernel
{
class SensorMount
{
   public:
	/// `placement`: which of the rig's poses, e.g. &SensorRig::vehicle_T_lidar.
	explicit SensorMount(Eigen::Isometry3d SensorRig::*placement) : placement_(placement) {}

	void observe(const Frame& frame)
	{
		if (known_) return;
		vehicle_T_sensor_ = frame.rig.*placement_;
		known_ = true;
	}
	const Eigen::Isometry3d& vehicleTsensor() const { return vehicle_T_sensor_; }

   private:
	Eigen::Isometry3d SensorRig::*placement_;
	Eigen::Isometry3d vehicle_T_sensor_ = Eigen::Isometry3d::Identity();
	bool known_ = false;
};
}  // namespace vlo::kernel
