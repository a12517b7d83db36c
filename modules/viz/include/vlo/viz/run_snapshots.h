#pragma once
// The pictures of a vlo-run folder (snapshots/): its trajectories from above and over the map, beside the
// ground truth of the time the run covered, and sample frames with their scan projected into the image.
#include <vlo/core/frame.h>
#include <vlo/viz/topdown.h>

#include <string>
#include <vector>

namespace vlo::viz
{
struct RunSnapshots
{
	std::string mode;  ///< [pipeline] mode; in "vo" the last trajectory is the VO's, in map units
	std::size_t frames = 0;  ///< rows of frames.csv, for the title
	/// The loop-closed one (with loop closure), the LiDAR odometry's, then the motion source's, each in the
	/// vehicle frame of the first frame.
	std::vector<NamedTrajectory> trajectories;
	/// Accepted loop closures: the positions of the two visits on the LiDAR odometry's path.
	std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> loops;
	std::string gt_path;  ///< TUM file, or empty
	double t_first = 0, t_last = 0;  ///< the run's first and last frame times: the ground truth drawn
};

/// topdown.png, map3d.png (when `map` has points) and frame_<index>.png per sample frame with image and
/// scan, into `dir`. Nothing when there is no trajectory. In mode vo the VO's path is Sim(3)-aligned to
/// the ground truth when there is one, and says so; without one, the legend and title say "unscaled" and
/// lengths and axes are in map units. Throws InputError for a bad gt_path.
void renderRunSnapshots(const std::string& dir, RunSnapshots run, const PointCloud& map, const std::vector<Frame>& samples);
}  // namespace vlo::viz
