#pragma once
// The first motion of a drive, before any velocity is known. A vehicle may start at speed: at
// 12 m/s the first sweep is 1.2 m from the previous one, beyond the reach of scan-to-scan's nearest
// neighbours from a zero guess (on the real KITTI drive 2011_09_26_0013 it closed 0.18 m of 1.18).
// Scan-to-scan runs from several translations instead, and the motion that fits most features wins:
// counted along the way the results disagree, where the ground, walls and curbs parallel to the road
// fit every result alike and only poles and corners tell them apart.
#include <vlo/loam/odometry.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
struct ColdStart
{
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  ///< the winner's result
	int hypotheses = 0;  ///< starting translations tried
	int inliers = 0;  ///< the winner's features within the inlier distance of their line or plane
};

/// Features of `curr` whose line or plane match at T lies within `tolerance` [m].
int countInliers(const Matches& m, const Eigen::Isometry3d& T, double tolerance);
/// The same inliers, each weighed by how much it fixes a translation along the unit vector d: a plane
/// by (n.d)^2, a line by |d across it|^2 (a pole 1 for any level d, a curb along d 0).
double inliersAlong(const Matches& m, const Eigen::Isometry3d& T, double tolerance, const Eigen::Vector3d& d);

/// Scan-to-scan from the zero motion and from translations of k * `step` (k = 1..n, step * n <=
/// `range`) along +-x and +-y of the LiDAR; the result with the most inliers along the level direction
/// in which the results spread most (all within 5 cm: the most inliers).
ColdStart searchFirstMotion(const ScanToScanOdometry& odometry, const FeatureSet& curr, double range, double step);
}  // namespace vlo::loam
