#pragma once
// The [lidar] section: what every consumer of a scan (the LiDAR odometries, the scale corrector, the
// map) needs to know of the sensor beyond its pose. When each return of a sweep was taken: a spinning
// LiDAR moves while it turns; the LiDAR odometries undistort ("deskew") a scan whose points carry
// times, and take a scan without times as taken at one instant. And an elevation error common to its
// lasers (core/elevation_offset.h).
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

struct LidarOptions : public OptionSet
{
	PointTimes point_times = PointTimes::Auto;
	bool clockwise = true;  ///< the laser turns clockwise seen from above (Velodyne)
	double scan_period = 0.1;  ///< [s] per turn
	/// [deg] where the laser faces at the frame's time, half-way through its turn (KITTI: forward,
	/// where it triggers the cameras)
	double frame_azimuth_deg = 0.0;
	/// [deg] added to every ray's elevation, a calibration error common to the lasers (KITTI's HDL-64:
	/// 0.22, IMLS-SLAM)
	double elevation_offset_deg = 0.0;

	SpinningSweep sweep() const;

   protected:
	void declare(OptionTable& t) override;
};

/// Raises the scan's rays by the elevation offset, then gives it the times `options` asks for (or takes
/// them away).
void applyLidarOptions(PointCloud& scan, const LidarOptions& options);
/// "sensor", "azimuth" or "none": where the scan's times came from, for frames.csv.
const char* pointTimeSource(const PointCloud& scan);
}  // namespace vlo::pipeline
