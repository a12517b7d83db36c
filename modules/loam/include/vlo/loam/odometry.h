#pragma once
// Scan-to-scan odometry (A-LOAM laserOdometry): the sharp and flat points of the new scan are
// matched to lines and planes through the previous scan's less-sharp and less-flat points and the
// relative motion is solved for, alternating matching and solving.
//
// Neighbours: the first one is the closest reference point, searched on the rings within
// nearby_rings of the query's elevation seen from the reference pose (with ring ids: the reference
// ring of the nearest mean elevation) (or, with use_kdtree, in a kd-tree over the whole scan as
// A-LOAM does: the same point in practice, but the tree costs milliseconds to build every frame);
// the line's second point is the closest on a nearby ring, the plane's second the closest on the
// first one's ring and its third the closest on a nearby ring.
#include <vlo/loam/degeneracy.h>
#include <vlo/loam/kdtree.h>
#include <vlo/loam/options.h>
#include <vlo/loam/pose_solver.h>
#include <vlo/loam/ring_search.h>
#include <vlo/loam/rings.h>
#include <vlo/loam/types.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace vlo::loam
{
class ScanToScanOdometry
{
   public:
	struct Result
	{
		Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();  ///< current scan in the previous
		bool ok = false;  ///< false: T_prev_curr is the initial guess
		std::string reason;  ///< why not ok
		int rounds = 0;  ///< correspondence + solve rounds run
		int iterations = 0;  ///< solver iterations over all rounds
		int n_edges = 0, n_planes = 0;  ///< matches of the last round
		double rms = 0;  ///< distance RMS at the solution [m]
		Degeneracy degeneracy;  ///< of the last round's J^T J at the solution
	};

	ScanToScanOdometry(const OdometryOptions& o, const RingModel& rings);

	/// Makes `f` the scan the next one is matched against (keeps a copy).
	void setReference(const FeatureSet& f);
	bool hasReference() const { return has_ref_; }
	void clearReference() { has_ref_ = false; }

	/// Motion of `curr` relative to the reference, starting from `guess`.
	Result match(const FeatureSet& curr, const Eigen::Isometry3d& guess) const;

	/// Line/plane matches for `curr` transformed by T (one round's correspondence search).
	void findMatches(const FeatureSet& curr, const Eigen::Isometry3d& T, Matches& out) const;

   private:
	struct Set
	{
		ScanPoints points;
		RingSearch rings;
		PointKdTree tree;
	};
	int queryRing(const FeatureSet& curr, const RingSearch::Query& q) const;
	int firstNeighbour(const Set& s, const RingSearch::Query& q, int r) const;
	int closestOnNearbyRings(const Set& s, int ring, const RingSearch::Query& q) const;
	bool confirmsPlane(int m, const RingSearch::Query& q, const Eigen::Vector3d& n, double d) const;

	OdometryOptions opt_;
	RingModel model_;
	float max2_;
	bool has_ref_ = false;
	bool ref_rings_from_data_ = false;
	/// With the sensor's ring ids: each ring's mean elevation slope z / rho in the reference (NaN if
	/// empty), the beam table the data implies.
	std::vector<float> ref_ring_slope_;
	Set edges_, planes_;
};
}  // namespace vlo::loam
