#include <vlo/loam/odometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlo::loam
{
ScanToScanOdometry::ScanToScanOdometry(const OdometryOptions& o, const RingModel& rings)
	: opt_(o), model_(rings), max2_(static_cast<float>(o.max_match_distance * o.max_match_distance))
{
}

void ScanToScanOdometry::setReference(const FeatureSet& f)
{
	for (auto [set, pts] : {std::pair{&edges_, &f.less_sharp}, std::pair{&planes_, &f.less_flat}})
	{
		set->points = *pts;
		set->rings.build(set->points, std::max(model_.numRings(), f.n_rings));
		if (opt_.use_kdtree) set->tree.build(set->points);
	}
	ref_rings_from_data_ = f.rings_from_data;
	ref_ring_slope_.clear();
	if (f.rings_from_data)
	{
		std::vector<double> sum(static_cast<std::size_t>(std::max(0, f.n_rings)), 0.0);
		std::vector<int> count(sum.size(), 0);
		for (const ScanPoints* pts : {&f.less_sharp, &f.less_flat})
			for (const ScanPoint& p : *pts)
				if (p.ring >= 0 && static_cast<std::size_t>(p.ring) < sum.size())
				{
					sum[p.ring] += p.p.z() / std::hypot(p.p.x(), p.p.y());
					++count[p.ring];
				}
		for (std::size_t r = 0; r < sum.size(); ++r)
			ref_ring_slope_.push_back(count[r] ? static_cast<float>(sum[r] / count[r]) : std::nanf(""));
	}
	has_ref_ = true;
}

// The ring whose neighbourhood holds the query's match: the reference ring at the query's elevation
// as seen from the reference pose. With the sensor's ring ids, the ring whose reference points have
// the nearest mean elevation: not the query's own beam, since between two sweeps a point ahead
// drops to a lower beam (at 1.2 m per sweep, a search from its own beam matched ground points a beam
// too far and shortened every motion by ~0.05 %). Else the ring model's.
int ScanToScanOdometry::queryRing(const FeatureSet& curr, const RingSearch::Query& q) const
{
	const float rho = std::hypot(q.p.x(), q.p.y());
	if (!(curr.rings_from_data && ref_rings_from_data_)) return model_.nearestRing(q.p.z(), rho);
	const float slope = q.p.z() / rho;
	int best = -1;
	float gap = std::numeric_limits<float>::infinity();
	for (std::size_t r = 0; r < ref_ring_slope_.size(); ++r)
		if (std::fabs(ref_ring_slope_[r] - slope) < gap) gap = std::fabs(ref_ring_slope_[r] - slope), best = static_cast<int>(r);
	return best;
}

// The closest reference point within max_match_distance, or -1; the search starts on `r`.
int ScanToScanOdometry::firstNeighbour(const Set& s, const RingSearch::Query& q, int r) const
{
	float best = max2_;
	if (opt_.use_kdtree)
	{
		const int j = s.tree.nearest(q.p, &best);
		return (j >= 0 && best < max2_) ? j : -1;
	}
	if (r < 0) return -1;
	int j = s.rings.nearest(r, q, best);
	for (int dr = 1; dr <= opt_.nearby_rings; ++dr)
		for (int rr : {r - dr, r + dr})
		{
			const int k = s.rings.nearest(rr, q, best);
			if (k >= 0) j = k;
		}
	return j;
}

// Closest point to q on the rings within nearby_rings of `ring`, `ring` itself excluded.
int ScanToScanOdometry::closestOnNearbyRings(const Set& s, int ring, const RingSearch::Query& q) const
{
	float best = max2_;
	int j = -1;
	for (int dr = 1; dr <= opt_.nearby_rings; ++dr)
		for (int rr : {ring - dr, ring + dr})
		{
			const int k = s.rings.nearest(rr, q, best);
			if (k >= 0) j = k;
		}
	return j;
}

// Three points always span a plane; the reference point next to the third (on the same ring) must
// lie on it too, or the three were not on one surface (leaves in a crown, a corner). No such point:
// nothing to check against.
bool ScanToScanOdometry::confirmsPlane(int m, const RingSearch::Query& q, const Eigen::Vector3d& n, double d) const
{
	if (opt_.plane_max_distance <= 0) return true;
	float best = max2_;
	const int k = planes_.rings.nearest(planes_.points[m].ring, q, best, m);
	return k < 0 || std::abs(n.dot(planes_.points[k].p.cast<double>()) + d) <= opt_.plane_max_distance;
}

void ScanToScanOdometry::findMatches(const FeatureSet& curr, const Eigen::Isometry3d& T, Matches& out) const
{
	out.clear();
	const Eigen::Matrix3f R = T.linear().cast<float>();
	const Eigen::Vector3f t = T.translation().cast<float>();

	// Edge: the closest reference edge point and the closest one on a nearby ring span a line.
	for (const ScanPoint& sp : curr.sharp)
	{
		const RingSearch::Query q(R * sp.p + t);
		const int j = firstNeighbour(edges_, q, queryRing(curr, q));
		if (j < 0) continue;
		const int l = closestOnNearbyRings(edges_, edges_.points[j].ring, q);
		if (l < 0) continue;
		const Eigen::Vector3d a = edges_.points[j].p.cast<double>(), b = edges_.points[l].p.cast<double>();
		const double len = (b - a).norm();
		if (len < 1e-3) continue;
		out.edges.push_back(EdgeMatch{sp.p.cast<double>(), a, (b - a) / len});
	}
	// Plane: the closest reference plane point, the closest on its ring and the closest on a nearby
	// ring span a plane (two rings keep the three points from being collinear).
	for (const ScanPoint& sp : curr.flat)
	{
		const RingSearch::Query q(R * sp.p + t);
		const int j = firstNeighbour(planes_, q, queryRing(curr, q));
		if (j < 0) continue;
		float best = max2_;
		const int l = planes_.rings.nearest(planes_.points[j].ring, q, best, j);
		if (l < 0) continue;
		const int m = closestOnNearbyRings(planes_, planes_.points[j].ring, q);
		if (m < 0) continue;
		const Eigen::Vector3d pj = planes_.points[j].p.cast<double>();
		Eigen::Vector3d n = (planes_.points[l].p.cast<double>() - pj).cross(planes_.points[m].p.cast<double>() - pj);
		const double nn = n.norm();
		if (nn < 1e-6) continue;
		n /= nn;
		const double d = -n.dot(pj);
		if (!confirmsPlane(m, q, n, d)) continue;
		out.planes.push_back(PlaneMatch{sp.p.cast<double>(), n, d});
	}
}

ScanToScanOdometry::Result ScanToScanOdometry::match(const FeatureSet& curr, const Eigen::Isometry3d& guess) const
{
	Result res;
	res.T_prev_curr = guess;
	if (!has_ref_)
	{
		res.reason = "no reference scan";
		return res;
	}
	Matches m;
	Eigen::Isometry3d T = guess;
	Eigen::Matrix<double, 6, 6> JtJ = Eigen::Matrix<double, 6, 6>::Zero();
	// A-LOAM stops after outer_iterations rounds, which only converges when the guess is close (a
	// known velocity). From a zero guess at 1-3.5 m per frame each round closes part of the gap: the
	// rounds go on while they still move the pose.
	for (int round = 0; round < opt_.max_rounds; ++round)
	{
		findMatches(curr, T, m);
		res.n_edges = static_cast<int>(m.edges.size());
		res.n_planes = static_cast<int>(m.planes.size());
		if (static_cast<int>(m.size()) < opt_.min_correspondences)
		{
			res.reason = "too few scan-to-scan matches (" + std::to_string(m.size()) + ")";
			return res;
		}
		const Eigen::Isometry3d before = T;
		const SolveReport rep = solvePose(m, opt_.solver, T);
		res.iterations += rep.iterations;
		res.rms = rep.rms;
		JtJ = rep.JtJ;
		++res.rounds;
		if (roundConverged(before, T, opt_.solver)) break;  // the matches would not change
	}
	res.degeneracy = analyseDegeneracy(JtJ, 0);  // of the last round (no threshold: the caller decides)
	res.T_prev_curr = T;
	res.ok = true;
	return res;
}
}  // namespace vlo::loam
