#pragma once
// The spinning LiDAR, sampled from rendered depth: 8 pinhole views around the sensor (9 with motion
// distortion: the sector behind is rendered at both the start and the end of the sweep). Each beam
// looks up its pixel, fits the local surface plane from inverse depth (exact for planes, one-sided
// at depth edges so no "flying" points appear between objects) and intersects the beam with it.
//
// Timing: the sweep of a frame at time t spans [t - T/2, t + T/2] (T = 0.1 s), starting and ending
// behind the vehicle and spinning clockwise seen from above, so the forward firing happens at t, when
// the camera is triggered (as in KITTI). A firing at azimuth phi (LiDAR frame, counter-clockwise from
// x, in (-pi, pi]) happens at t + tau(phi), tau = -phi / (2 pi) * T. Without distortion every firing
// uses the pose at t; with it, each point is in the LiDAR frame at its own firing time.
#include <vlo/core/frame.h>
#include <vlo/sim/config.h>
#include <vlo/sim/foliage.h>
#include <vlo/sim/renderer.h>
#include <vlo/sim/traffic.h>

#include <functional>

namespace vlo::sim
{
class Rng;
class LidarErrors;

struct LidarNoise
{
	double range_sigma = 0.02;  ///< m
	double dropout = 0.005;  ///< probability of a lost return
	double foliage_depth = 0;  ///< m, mean depth of a return inside a crown (0: the hull returns)
	/// A realistic unit (lidar_errors.h): its lasers' calibration errors and echo model replace
	/// range_sigma and dropout. Null: the exact sensor.
	const LidarErrors* errors = nullptr;
};

/// Objects that move during the sweep (traffic): every firing sees them at its own time t + tau, also
/// in an ideal (de-skewed) scan, since de-skewing with the sensor's motion cannot undo theirs.
struct MovingObjects
{
	std::function<std::vector<Traffic::Placed>(double tau)> at;  ///< where they are at t + tau
	std::function<uint8_t(int slot)> gray;  ///< grey level (0-255) of a face, by texture slot
	bool returns = true;  ///< false: they block beams but return nothing (SimConfig::traffic_lidar_returns)
};

class LidarSim
{
   public:
	/// `ideal_deskew` (with `distortion`): returns moved to the pose at the frame's time, times 0.
	LidarSim(const LidarModel& model, bool distortion, bool ideal_deskew = false);
	const LidarModel& model() const { return model_; }
	int viewCount() const { return static_cast<int>(views_.size()); }
	std::pair<int, int> tileSize() const { return {K_.width, K_.height}; }
	/// Firing time offset tau(phi) in seconds.
	double firingTime(double azimuth) const;

	using PoseAt = std::function<Eigen::Isometry3d(double tau)>;  ///< world_T_lidar at t + tau
	/// The views to render for one sweep.
	std::vector<View> views(const PoseAt& world_T_lidar) const;
	/// Points (LiDAR frame, firing order: azimuth-major) from the rendered views; beams that hit a crown
	/// of `foliage` return from inside it (LidarNoise::foliage_depth); `moving` objects (not drawn in the
	/// views) are ray-cast where they are at each firing's time.
	PointCloud sample(const std::vector<RenderedView>& tiles, const std::vector<View>& views, const PoseAt& world_T_lidar,
		const Foliage& foliage, const LidarNoise& noise, Rng& rng, const MovingObjects* moving = nullptr) const;

   private:
	struct ViewDef
	{
		double yaw;  // centre azimuth
		double tau;  // render time offset
		Eigen::Matrix3d R;  // LiDAR_R_view (optical frame)
	};
	LidarModel model_;
	bool distortion_, ideal_deskew_;
	PinholeCamera K_;
	std::vector<ViewDef> views_;
	std::vector<Eigen::Vector3d> dirs_;  // per beam (ring-minor), LiDAR frame
	std::vector<int> viewOf_;  // per azimuth column
	std::vector<std::uint16_t> ringOf_;  // per beam: its rank by elevation (0 = lowest)
	double azimuthOf(int column) const;
	/// Where laser `laser` really fires at `column`: its nominal direction turned by its calibration errors.
	Eigen::Vector3d firedDirection(const LidarErrors& e, int column, int laser) const;
};
}  // namespace vlo::sim
