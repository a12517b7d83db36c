#include <vlo/pipeline/lidar_options.h>

#include <vlo/core/elevation_offset.h>

#include <cmath>

namespace vlo::pipeline
{
void LidarOptions::declare(OptionTable& t)
{
	t.choice("point_times", point_times,
		{{"auto", PointTimes::Auto}, {"sensor", PointTimes::Sensor}, {"azimuth", PointTimes::Azimuth}, {"none", PointTimes::None}},
		"when each return was taken, for the deskew: auto = the sensor's times, else from the azimuth; sensor; azimuth; none");
	t.add("clockwise", clockwise, "true | false", "the laser turns clockwise seen from above (Velodyne)");
	t.add("scan_period", scan_period, "> 0", "[s] per turn of the laser (times from the azimuth)");
	t.add("frame_azimuth_deg", frame_azimuth_deg, "[-180, 180]",
		"[deg] where the laser faces at the frame's time, half-way through its turn (0: forward, KITTI)");
	t.add("elevation_offset_deg", elevation_offset_deg, "[-2, 2]",
		"[deg] added to every ray's elevation: a calibration error common to the lasers (KITTI's HDL-64: 0.22)");
}

SpinningSweep LidarOptions::sweep() const
{
	SpinningSweep s;
	s.clockwise = clockwise;
	s.period = scan_period;
	s.frame_azimuth = frame_azimuth_deg * M_PI / 180.0;
	s.frame_fraction = 0.5;
	return s;
}

void applyLidarOptions(PointCloud& scan, const LidarOptions& options)
{
	if (options.elevation_offset_deg != 0) raiseElevations(scan, options.elevation_offset_deg);
	switch (options.point_times)
	{
		case PointTimes::Sensor: return;
		case PointTimes::None: scan.has_time = scan.time_from_azimuth = false; return;
		case PointTimes::Auto:
			if (scan.has_time) return;
			break;
		case PointTimes::Azimuth: break;
	}
	setTimesFromAzimuth(scan, options.sweep());
}

const char* pointTimeSource(const PointCloud& scan)
{
	if (!scan.has_time) return "none";
	return scan.time_from_azimuth ? "azimuth" : "sensor";
}
}  // namespace vlo::pipeline
