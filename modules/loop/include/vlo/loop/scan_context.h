#pragma once
// Scan Context (Kim & Kim, "Scan Context: Egocentric Spatial Descriptor for Place Recognition within 3D
// Point Cloud Map", IROS 2018): the points around the vehicle binned into rings (range) x sectors
// (azimuth), each bin the highest point's height. The ring key (each ring's mean) does not change
// when the vehicle turns on the spot, so it finds candidates; the full descriptor, compared over
// every column shift, gives their distance and the yaw between the two scans.
#include <Eigen/Core>
#include <vector>

namespace vlo::loop
{
struct ScanContextParams
{
	double range = 80.0;  ///< [m] radius of the outermost ring
	int rings = 20;
	int sectors = 60;
	double sensor_height = 2.0;  ///< [m] added to heights, so that the ground is not an empty bin
};

/// rings x sectors; sector j covers azimuths [-pi + j * 2pi / sectors, ...), x forward, y left.
using ScanContext = Eigen::MatrixXd;

/// The descriptor of points in the vehicle frame (x forward, z up), seen from `viewpoint_y` [m] to the
/// vehicle's left (a virtual viewpoint in another lane, axes as the vehicle's).
ScanContext makeScanContext(
	const std::vector<Eigen::Vector3f>& points, const ScanContextParams& params, double viewpoint_y = 0);

/// Each ring's mean height: invariant to the vehicle's yaw.
Eigen::VectorXd ringKey(const ScanContext& sc);

struct DescriptorMatch
{
	double distance = 1.0;  ///< 0 = the same, 1 = unrelated
	int shift = 0;  ///< columns
	double yaw = 0;  ///< [rad] rotation of the query's frame in the candidate's (about z)
	double viewpoint_y = 0;  ///< [m] the query's descriptor was seen from this far to its vehicle's left
};

/// The mean cosine distance of the columns that hold points in both, at the best of all column shifts
/// (every shift is tried: 60 x 1200 products, cheaper than a wrong coarse alignment by the sector key).
DescriptorMatch compareScanContexts(const ScanContext& query, const ScanContext& candidate);
}  // namespace vlo::loop
