#pragma once
// One simulated drive: road, world, vehicle motion and sensors, rendered frame by frame.
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>
#include <vlo/sim/config.h>
#include <vlo/sim/drive.h>
#include <vlo/sim/road.h>
#include <vlo/sim/traffic.h>
#include <vlo/sim/world.h>

#include <memory>
#include <string>

namespace vlo::sim
{
struct RenderedView;

class Simulator
{
   public:
	/// Builds the road (generated, or through the KITTI poses of cfg.kitti_poses), the world, the
	/// vehicle motion and the renderer. Throws InputError for bad configuration or input files.
	explicit Simulator(const SimConfig& cfg);
	~Simulator();
	Simulator(const Simulator&) = delete;
	Simulator& operator=(const Simulator&) = delete;

	const SimConfig& config() const;
	int frameCount() const;
	double frameTime(int k) const;
	/// world_T_vehicle at frame k (the pose every sensor of frame k is rendered from) and at any time.
	Eigen::Isometry3d vehiclePose(int k) const;
	Eigen::Isometry3d vehiclePoseAt(double t) const;
	/// Vehicle poses relative to frame 0, at the frame times: what FILE.gt.tum holds.
	Trajectory groundTruth() const;

	/// Renders frame k. If camera_depth is given it receives the camera's supersampled depth tile.
	Frame frame(int k, RenderedView* camera_depth = nullptr);

	const World& world() const;
	const Road& road() const;
	/// The moving vehicles (none unless SimConfig::traffic > 0), and how many are within `radius` of
	/// the ego vehicle at frame k.
	const Traffic& traffic() const;
	int vehiclesWithin(int k, double radius) const;
	/// One line about the world (size, triangles, path length) for logs.
	std::string summary() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::sim
