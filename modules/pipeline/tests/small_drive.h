#pragma once
// A tiny rawlog for the run loop's tests: 10 Hz frames of a 32x24 grey image (brightness 10 * i at
// frame i) and three LiDAR points (the first at x = 5 + i), with internal images.
#include <vlo/io/rawlog_writer.h>

#include <string>

namespace vlo::test
{
/// Camera looking along the vehicle's x axis (z forward, x right, y down), with a lever arm.
inline SensorRig smallRig()
{
	SensorRig r;
	r.has_camera = r.has_lidar = true;
	r.camera.fx = r.camera.fy = 20;
	r.camera.cx = 16;
	r.camera.cy = 12;
	r.camera.width = 32;
	r.camera.height = 24;
	r.vehicle_T_camera.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	r.vehicle_T_camera.translation() << 1.5, 0.1, 1.6;
	r.vehicle_T_lidar.translation() << 0.3, 0, 1.8;
	return r;
}

/// Frame i at t0 + 0.1 i s.
inline void writeSmallDrive(const std::string& path, int frames, const SensorRig& rig, double t0 = 0)
{
	io::RawlogWriter w(path, false);
	for (int i = 0; i < frames; ++i)
	{
		Frame f;
		f.index = std::size_t(i);
		f.t = t0 + 0.1 * i;
		f.has_image = f.has_scan = true;
		f.image = mrpt::img::CImage(32, 24, mrpt::img::CH_GRAY);
		f.image.filledRectangle(0, 0, 31, 23, mrpt::img::TColor(10 * i, 10 * i, 10 * i));
		f.scan = {{5.f + float(i), 0.f, 0.f, 1.f}, {0.f, 5.f, 0.f, 1.f}, {5.f, 5.f, 1.f, 1.f}};
		f.rig = rig;
		w.writeFrame(f);
	}
	w.commit();
}
}  // namespace vlo::test
