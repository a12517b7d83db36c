#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/io/frame_observations.h>

#include <mrpt/maps/CPointsMapXYZI.h>

#include <cmath>

namespace vlo
{
using namespace mrpt::obs;

mrpt::Clock::time_point toTimestamp(double seconds)
{
	static const auto epoch = mrpt::Clock::fromDouble(0.0).time_since_epoch().count();
	return mrpt::Clock::time_point(mrpt::Clock::duration(epoch + std::llround(seconds * 1e7)));
}

double toSeconds(const mrpt::Clock::time_point& t) { return mrpt::Clock::toDouble(t); }

mrpt::img::TCamera toTCamera(const PinholeCamera& cam)
{
	mrpt::img::TCamera p;
	p.ncols = static_cast<uint32_t>(cam.width);
	p.nrows = static_cast<uint32_t>(cam.height);
	p.setIntrinsicParamsFromValues(cam.fx, cam.fy, cam.cx, cam.cy);
	p.distortion = mrpt::img::DistortionModel::none;
	p.dist.fill(0.0);
	return p;
}

PinholeCamera fromTCamera(const mrpt::img::TCamera& params, const std::string& where)
{
	for (double d : params.dist)
		if (d != 0.0)
			failInput(where, "camera has lens distortion; vlo needs rectified images (distortion none, dist all 0)");
	PinholeCamera cam;
	cam.fx = params.fx();
	cam.fy = params.fy();
	cam.cx = params.cx();
	cam.cy = params.cy();
	cam.width = static_cast<int>(params.ncols);
	cam.height = static_cast<int>(params.nrows);
	if (!cam.valid() || !std::isfinite(cam.cx) || !std::isfinite(cam.cy))
		failInput(where, "invalid camera intrinsics (fx, fy and the resolution must be positive)");
	return cam;
}

CObservationImage::Ptr toImageObservation(const Frame& frame, const std::string& label)
{
	auto obs = CObservationImage::Create();
	obs->sensorLabel = label;
	obs->timestamp = toTimestamp(frame.t);
	obs->cameraPose = toCPose3D(frame.rig.vehicle_T_camera);
	obs->cameraParams = toTCamera(frame.rig.camera);
	obs->image = frame.image;  // shallow: shares pixels
	return obs;
}

CObservationPointCloud::Ptr toScanObservation(const Frame& frame, const std::string& label)
{
	auto obs = CObservationPointCloud::Create();
	obs->sensorLabel = label;
	obs->timestamp = toTimestamp(frame.t);
	obs->sensorPose = toCPose3D(frame.rig.vehicle_T_lidar);
	auto map = mrpt::maps::CPointsMapXYZI::Create();
	map->reserve(frame.scan.size());
	for (const auto& p : frame.scan) map->insertPointRGB(p.x, p.y, p.z, p.intensity, 0, 0);
	obs->pointcloud = map;
	return obs;
}

std::size_t fromPointsMap(const mrpt::maps::CPointsMap& map, PointCloud& out)
{
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto* xyzi = dynamic_cast<const mrpt::maps::CPointsMapXYZI*>(&map);
	out.clear();
	out.reserve(xs.size());
	for (std::size_t i = 0; i < xs.size(); ++i)
	{
		if (!std::isfinite(xs[i]) || !std::isfinite(ys[i]) || !std::isfinite(zs[i])) continue;
		const float in = xyzi ? xyzi->getPointIntensity_fast(i) : 0.0f;
		out.push_back({xs[i], ys[i], zs[i], std::isfinite(in) ? in : 0.0f});
	}
	return xs.size() - out.size();
}

mrpt::img::CImage toGray(const mrpt::img::CImage& img)
{
	return img.isColor() ? img.grayscale() : img;
}
}  // namespace vlo
