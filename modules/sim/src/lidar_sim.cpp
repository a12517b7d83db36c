#include "depth_lookup.h"

#include <vlo/core/units.h>
#include <vlo/sim/lidar_errors.h>
#include <vlo/sim/lidar_sim.h>
#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kHalfSector = 22.5 * kRadPerDeg;
constexpr double kMargin = 1.5 * kRadPerDeg;

Eigen::Matrix3d opticalAlong(double yaw)
{
	Eigen::Matrix3d optical;  // optical axes in a frame with x forward, y left, z up
	optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * optical;
}

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

LidarSim::LidarSim(const LidarModel& model, bool distortion, bool ideal_deskew)
	: model_(model), distortion_(distortion), ideal_deskew_(distortion && ideal_deskew)
{
	// Square pixels 0.8x the azimuth step at the view centre; tall enough for all beams at the edges.
	const double step = 2 * M_PI / model_.azimuth_steps, f = 1.0 / (0.8 * step);
	const double a = kHalfSector + kMargin;
	const double top = *std::max_element(model_.elevations_deg.begin(), model_.elevations_deg.end()) * kRadPerDeg + kMargin;
	const double bot = *std::min_element(model_.elevations_deg.begin(), model_.elevations_deg.end()) * kRadPerDeg - kMargin;
	const double yTop = std::min(-f * std::tan(top), -f * std::tan(top) / std::cos(a));
	const double yBot = std::max(-f * std::tan(bot), -f * std::tan(bot) / std::cos(a));
	K_.fx = K_.fy = f;
	K_.width = 2 * static_cast<int>(std::ceil(f * std::tan(a))) + 4;
	K_.cx = (K_.width - 1) / 2.0;
	K_.cy = std::ceil(-yTop) + 2;
	K_.height = static_cast<int>(std::ceil(yBot - yTop)) + 5;
	for (int i = 0; i < 8; ++i)
	{
		const double yaw = wrap(i * 2 * kHalfSector);
		views_.push_back({yaw, distortion_ ? firingTime(yaw) : 0.0, opticalAlong(yaw)});
	}
	if (distortion_)  // the sector behind: view 4 at the start of the sweep, view 8 at its end
		views_[4].tau = -model_.period / 2, views_.push_back({M_PI, model_.period / 2, opticalAlong(M_PI)});
	for (int c = 0; c < model_.azimuth_steps; ++c)
	{
		const double phi = azimuthOf(c);
		for (double el : model_.elevations_deg)
			dirs_.emplace_back(std::cos(el * kRadPerDeg) * std::cos(phi), std::cos(el * kRadPerDeg) * std::sin(phi),
				std::sin(el * kRadPerDeg));
		int v = static_cast<int>(std::lround((phi < 0 ? phi + 2 * M_PI : phi) / (2 * kHalfSector))) % 8;
		if (distortion_ && v == 4 && phi < 0) v = 8;
		viewOf_.push_back(v);
	}
	const auto& el = model_.elevations_deg;
	for (double e : el)
		ringOf_.push_back(static_cast<std::uint16_t>(std::count_if(el.begin(), el.end(), [e](double o) { return o < e; })));
}

Eigen::Vector3d LidarSim::firedDirection(const LidarErrors& e, int column, int laser) const
{
	const double el = model_.elevations_deg[static_cast<std::size_t>(laser)] * kRadPerDeg + e.elevationOffset(laser);
	const double phi = azimuthOf(column) + e.azimuthOffset(laser);
	return {std::cos(el) * std::cos(phi), std::cos(el) * std::sin(phi), std::sin(el)};
}

double LidarSim::azimuthOf(int column) const { return M_PI - (column + 0.5) * 2 * M_PI / model_.azimuth_steps; }

double LidarSim::firingTime(double azimuth) const { return -wrap(azimuth) / (2 * M_PI) * model_.period; }

std::vector<View> LidarSim::views(const PoseAt& world_T_lidar) const
{
	std::vector<View> out;
	for (const ViewDef& d : views_)
	{
		View v;
		v.world_T_cam = world_T_lidar(d.tau);
		v.world_T_cam.linear() = v.world_T_cam.linear() * d.R;
		v.K = K_;
		v.znear = 1.0, v.zfar = model_.max_range + 10;
		v.moving = false;
		out.push_back(v);
	}
	return out;
}

PointCloud LidarSim::sample(const std::vector<RenderedView>& tiles, const std::vector<View>& views, const PoseAt& world_T_lidar,
	const Foliage& foliage, const LidarNoise& noise, Rng& rng, const MovingObjects* moving) const
{
	PointCloud cloud;
	cloud.reserve(dirs_.size());
	// A rolling sweep says when and by which beam; the exact sensor takes every return at the frame's
	// time (0), which [lidar] point_times = auto then keeps rather than deriving times from the azimuth.
	cloud.has_time = true;
	cloud.has_ring = distortion_;
	const int rings = static_cast<int>(model_.elevations_deg.size());
	// An ideal deskew moves each firing's points into the LiDAR frame at the frame's time (tau = 0).
	const Eigen::Isometry3d frame_T_world = ideal_deskew_ ? Eigen::Isometry3d(world_T_lidar(0).inverse()) : Eigen::Isometry3d::Identity();
	for (int c = 0; c < model_.azimuth_steps; ++c)
	{
		const int vi = viewOf_[c];
		// Beam origin and rotation in the view's optical frame (identity motion without distortion).
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.linear() = views_[vi].R.transpose();
		const double fired = firingTime(azimuthOf(c)), tau = distortion_ ? fired : 0.0;
		const Eigen::Isometry3d fired_pose = distortion_ ? world_T_lidar(tau) : Eigen::Isometry3d::Identity();
		if (distortion_) T = views[vi].world_T_cam.inverse() * fired_pose;
		const DepthLookup look(tiles[vi], K_);
		const Eigen::Isometry3d to_frame = frame_T_world * fired_pose;
		const Eigen::Isometry3d& W = views[vi].world_T_cam;
		const Eigen::Isometry3d L = W * T;  // world_T_lidar of this firing
		const std::vector<Traffic::Placed> movers = moving ? moving->at(fired) : std::vector<Traffic::Placed>{};
		for (int j = 0; j < rings; ++j)
		{
			const Eigen::Vector3d& dL = dirs_[static_cast<std::size_t>(c) * rings + j];
			// A real laser fires along its own (miscalibrated) direction; its point is computed along dL.
			const Eigen::Vector3d dFired = noise.errors ? firedDirection(*noise.errors, c, j) : dL;
			double r = 0;
			uint8_t gray = 0;
			DepthLookup::Footprint fp;
			fp.radius_px = noise.errors ? noise.errors->params().divergence_mrad * 1e-3 / 2 * K_.fx : 0;
			bool hit = look.intersect(T.translation(), T.linear() * dFired, r, gray, &fp);
			const double surface = r;
			hit = hit && foliage.penetrate(W * T.translation(), W.linear() * (T.linear() * dFired), noise.foliage_depth, rng, r);
			double rm = 0;
			const int face = movers.empty() ? -1 : Traffic::raycast(movers, L.translation(), L.linear() * dFired, hit ? r : model_.max_range + 1, rm);
			if (face >= 0) r = rm, gray = moving->gray(face), hit = true;
			if (!hit) continue;
			double measured = 0;
			float reflectance = float(gray / 255.0);
			if (noise.errors)
			{
				// Inside a crown or on a vehicle the rendered surface's incidence and edges do not apply.
				const bool rendered = face < 0 && r == surface;
				const Echo echo{r, rendered ? fp.cos_incidence : 1.0, rendered ? r * fp.edge_depth_ratio : 0.0, gray};
				if (!noise.errors->measure(j, echo, rng, measured, reflectance)) continue;
				if (measured < model_.min_range || measured > model_.max_range) continue;
			}
			else
			{
				measured = r + noise.range_sigma * rng.normal();
				if (rng.uniform() < noise.dropout || measured < model_.min_range || measured > model_.max_range) continue;
			}
			if (face >= 0 && !moving->returns) continue;  // after the draws: the other returns keep their noise
			const Eigen::Vector3d p = ideal_deskew_ ? Eigen::Vector3d(to_frame * (measured * dL)) : Eigen::Vector3d(measured * dL);
			// A scan with times is written as a Velodyne scan, whose intensity is the sensor's 8-bit
			// reflectivity (dropPointTimes scales it back to [0, 1] for a sweep written without times).
			const float intensity = noise.errors ? 255 * reflectance : float(gray);
			cloud.push_back({float(p.x()), float(p.y()), float(p.z()), intensity, ideal_deskew_ ? 0.0f : float(tau), ringOf_[j]});
		}
	}
	return cloud;
}
}  // namespace vlo::sim
