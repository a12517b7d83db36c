#pragma once
// Runs the VO over a synthetic drive or a rawlog and scores it with the eval library.
#include <vlo/eval/ate.h>
#include <vlo/io/trajectory.h>
#include <vlo/vo/visual_odometry.h>

#include <map>
#include <string>
#include <vector>

#include "synthetic_scene.h"

namespace vlo::vo::test
{
struct Run
{
	std::vector<VoFrameInfo> infos;
	Trajectory estimate;  ///< tracked frames only
	Trajectory truth;  ///< all frames
	int tracked = 0, lost = 0;
};

/// A camera pose or motion in vehicle axes: Tvc * C * Tvc^-1 in a metric map; in an unscaled one the
/// (metric) lever arm is left out, as the pipeline adapter does.
inline Eigen::Isometry3d toVehicle(const SensorRig& rig, const Eigen::Isometry3d& C, bool metric)
{
	Eigen::Isometry3d T = rig.vehicle_T_camera;
	if (!metric) T.translation().setZero();
	return T * C * T.inverse();
}

/// Drives `frames` frames along drivePose(); frames in [blank_from, blank_to) are uniform gray.
inline Run runStreet(const PinholeCamera& cam, int frames, const VoOptions& opt, int blank_from = -1, int blank_to = -1,
	bool mapping_thread = false)
{
	StreetRenderer renderer(StreetScene(), cam);
	VisualOdometry vo(cam, opt);
	vo.useMappingThread(mapping_thread);
	Run r;
	for (int k = 0; k < frames; ++k)
	{
		const double t = 0.1 * k;
		const Eigen::Isometry3d T = drivePose(k);
		const cv::Mat img = (k >= blank_from && k < blank_to) ? cv::Mat(cam.height, cam.width, CV_8U, cv::Scalar(90)) : renderer.render(T);
		const VoFrameInfo info = vo.process(img, t);
		r.infos.push_back(info);
		r.truth.push_back({t, T});
		if (info.pose)
		{
			r.estimate.push_back({t, *info.pose});
			++r.tracked;
		}
		if (info.state == VoState::Lost) ++r.lost;
	}
	return r;
}

/// Sim(3) ATE of the estimate against the truth at the same times.
inline eval::AteResult ateSim3(const Trajectory& truth, const Trajectory& est)
{
	std::map<long, Eigen::Isometry3d> gt;
	for (const auto& p : truth) gt[std::lround(p.t * 1e6)] = p.pose;
	Trajectory g, e;
	for (const auto& p : est)
	{
		const auto it = gt.find(std::lround(p.t * 1e6));
		if (it == gt.end()) continue;
		g.push_back({p.t, it->second});
		e.push_back(p);
	}
	return eval::computeAte(g, e, eval::Alignment::Sim3);
}
}  // namespace vlo::vo::test
