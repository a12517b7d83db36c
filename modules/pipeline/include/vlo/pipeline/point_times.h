#pragma once
// The [lidar] section: when each return of a sweep was taken, for every LiDAR odometry alike. A
// spinning LiDAR moves while it turns; the LiDAR odometries undistort ("deskew") a scan whose points
// carry times, and take a scan without times as taken at one instant.
#include <vlo/core/frame.h>
#include <vlo/core/option_table.h>
#include <vlo/core/sweep_times.h>

#include <string>

namespace vlo::pipeline
{
enum class PointTimes
{
	Auto,  ///< the sensor's times when the scan has them, else from the azimuth
	Sensor,  ///< the sensor's times only; a scan without them is not deskewed
	Azimuth,  ///< from the azimuth, whatever the sensor wrote
	None  ///< no times: no scan is deskewed (motion-compensated recordings)
};

struct PointTimeOptions : public OptionSet
{
	PointTimes point_times = PointTimes::Auto;
	bool clockwise = true;  ///< the laser turns clockwise seen from above (Velodyne)
	double scan_period = 0.1;  ///< [s] per turn
	/// [deg] where the laser faces at the frame's time, half-way through its turn (KITTI: forward,
	/// where it triggers the cameras)
	double frame_azimuth_deg = 0.0;

	SpinningSweep sweep() const;

   protected:
	void declare(OptionTable& t) override;
};

/// Gives the scan the times `options` asks for (or takes them away).
void applyPointTimes(PointCloud& scan, const PointTimeOptions& options);
/// "sensor", "azimuth" or "none": where the scan's times came from, for frames.csv.
const char* pointTimeSource(const PointCloud& scan);
}  // namespace vlo::pipeline
