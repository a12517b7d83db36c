#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/io/frame_observations.h>
#include <vlo/io/kitti_calib.h>

#include <cmath>
#include <sstream>

namespace vlo::io
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
	p.distortion = cam.distortion;
	p.dist = cam.dist;
	return p;
}

PinholeCamera fromTCamera(const mrpt::img::TCamera& params, const std::string& where)
{
	PinholeCamera cam;
	cam.fx = params.fx();
	cam.fy = params.fy();
	cam.cx = params.cx();
	cam.cy = params.cy();
	cam.width = static_cast<int>(params.ncols);
	cam.height = static_cast<int>(params.nrows);
	if (!cam.valid() || !std::isfinite(cam.cx) || !std::isfinite(cam.cy))
		failInput(where, "invalid camera intrinsics (fx, fy and the resolution must be positive)");
	cam.distortion = params.distortion;
	cam.dist = params.dist;
	for (double d : cam.dist)
		if (!std::isfinite(d)) failInput(where, "invalid lens distortion coefficient (not finite)");
	if (cam.distortion != mrpt::img::DistortionModel::none && cam.distortion != mrpt::img::DistortionModel::plumb_bob &&
		cam.distortion != mrpt::img::DistortionModel::kannala_brandt)
		failInput(where, "unknown lens distortion model (known: none, plumb_bob, kannala_brandt)");
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

namespace
{
const std::string kCamera0Key = "vehicle_T_camera0 (row-major 3x4):";
}

CObservationComment::Ptr toCamera0Note(const Eigen::Isometry3d& vehicle_T_camera0, double t)
{
	std::ostringstream text;
	text.precision(17);
	text << kCamera0Key;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) text << ' ' << vehicle_T_camera0.matrix()(r, c);
	auto note = CObservationComment::Create();
	note->timestamp = toTimestamp(t);
	note->text = text.str();
	return note;
}

bool isCamera0Note(const CObservationComment& comment) { return comment.text.rfind(kCamera0Key, 0) == 0; }

Eigen::Isometry3d camera0FromNote(const CObservationComment& note, const std::string& where)
{
	if (!isCamera0Note(note)) failInput(where, "expected '" + kCamera0Key + " 12 numbers'");
	return rigidFromText(note.text.substr(kCamera0Key.size()), where);
}

mrpt::img::CImage toGray(const mrpt::img::CImage& img)
{
	return img.isColor() ? img.grayscale() : img;
}
}  // namespace vlo::io
