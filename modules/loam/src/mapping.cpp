#include <vlo/loam/mapping.h>

#include <vlo/loam/features.h>
#include <vlo/loam/near_points.h>
#include <vlo/loam/voxel_filter.h>

#include <vlo/core/units.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace vlo::loam
{
ScanToMap::ScanToMap(const MappingOptions& o)
	: opt_(o),
	  edge_map_(o.voxel_size, o.map_edge_resolution, o.max_points_per_voxel),
	  plane_map_(o.voxel_size, o.map_plane_resolution, o.max_points_per_voxel)
{
}

std::size_t ScanToMap::downsampledEdges(const FeatureSet& f, double leaf, std::vector<Eigen::Vector3f>& out) const
{
	ScanPoints creases, silhouettes;
	for (std::size_t i = 0; i < f.less_sharp.size(); ++i)
		(i < f.less_sharp_silhouette.size() && f.less_sharp_silhouette[i] ? silhouettes : creases).push_back(f.less_sharp[i]);
	out = voxelDownsample(creases, static_cast<float>(leaf));
	const std::size_t n_creases = out.size();
	const std::vector<Eigen::Vector3f> s = voxelDownsample(silhouettes, static_cast<float>(leaf));
	out.insert(out.end(), s.begin(), s.end());
	return n_creases;
}

ScanToMap::Input ScanToMap::prepare(const FeatureSet& f) const
{
	Input in;
	if (opt_.edges != "off")
	{
		const std::size_t n_creases = downsampledEdges(f, opt_.edge_leaf, in.edges);
		in.edge_silhouette.assign(in.edges.size(), 1);
		std::fill(in.edge_silhouette.begin(), in.edge_silhouette.begin() + n_creases, 0);
	}
	in.planes = voxelDownsample(f.less_flat, static_cast<float>(opt_.plane_leaf));
	return in;
}

namespace
{
// Centroid and scatter of pts[0..n); the eigen-decomposition tells lines from planes.
void fit(const Eigen::Vector3f* pts, int n, Eigen::Vector3d& c, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& es)
{
	c.setZero();
	for (int i = 0; i < n; ++i) c += pts[i].cast<double>();
	c /= n;
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (int i = 0; i < n; ++i)
	{
		const Eigen::Vector3d d = pts[i].cast<double>() - c;
		C += d * d.transpose();
	}
	es.computeDirect(C / n);
}

bool lineLike(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& es, double ratio)
{
	return es.eigenvalues()(2) > ratio * es.eigenvalues()(1);
}

// A line's points are thin across it in every direction. Points strewn over a surface (edge points
// that a wall's range noise or a road's texture made, the nearest few of which pass A-LOAM's test by
// chance) spread across the "line" within the surface, far more than out of it: such a line says
// nothing about where along the surface the scan lies, yet its matches weigh as if it did (along a
// corridor's smooth walls they outweighed the VO's motion). Spreads below a sensor's noise count as
// that noise, so that exact points on a line stay a line.
bool flatAcross(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& es, double ratio)
{
	constexpr double kNoiseFloorSq = 0.01 * 0.01;  // [m^2] 1 cm
	return ratio > 0 && es.eigenvalues()(1) > ratio * std::max(es.eigenvalues()(0), kNoiseFloorSq);
}
}  // namespace

// A plane through the k nearest map points, if they spread in two dimensions and all lie close
// to it. Points of one scan line (one ring of one scan) cannot tell a plane: along a ring they are
// collinear, and around a corner they fit a level plane that is not there. So at least two
// neighbours must come from other scan lines (A-LOAM's scan-to-scan planes likewise take a point
// from another ring); on dense sensors they nearly always do.
bool ScanToMap::fitPlane(const Eigen::Vector3f& q, double max_distance, Eigen::Vector3f* nn, PlaneMatch& out) const
{
	constexpr int kWide = 16;  // >= knn (options)
	const int k = opt_.knn;
	const float max_d = static_cast<float>(opt_.max_nn_distance);
	std::uint32_t tag[32];
	if (plane_map_.knn(q, k, max_d, nn, tag) < k) return false;
	const auto others = [&](int n) {
		int c = 0;
		for (int i = 1; i < n; ++i) c += tag[i] != tag[0] ? 1 : 0;
		return c;
	};
	if (others(k) < 2)
	{
		// Keep the nearest points of other lines and fill up with the nearest of the first line.
		const int m = plane_map_.knn(q, kWide, max_d, nn, tag);
		if (others(m) < 2) return false;
		Eigen::Vector3f sel[32];

		int n = 0, n_other = 0;
		for (int i = 0; i < m && n_other < k / 2; ++i)
			if (tag[i] != tag[0]) sel[n++] = nn[i], ++n_other;
		for (int i = 0; i < m && n < k; ++i)
			if (tag[i] == tag[0]) sel[n++] = nn[i];
		std::copy(sel, sel + k, nn);
	}
	Eigen::Vector3d c;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
	fit(nn, k, c, es);
	if (lineLike(es, opt_.plane_line_ratio)) return false;
	const Eigen::Vector3d normal = es.eigenvectors().col(0);
	const double d = -normal.dot(c);
	for (int i = 0; i < k; ++i)
		if (std::abs(normal.dot(nn[i].cast<double>()) + d) > max_distance) return false;
	out.n = normal;
	out.d = d;
	return true;
}

bool ScanToMap::seenFromTooFar(const Eigen::Vector3d& u, const std::uint32_t* tags, int k, const Eigen::Isometry3d& T) const
{
	if (opt_.view_dependent_reach <= 0) return false;
	// The LiDAR's spin axis in the map; a line's elevation is its angle out of the plane normal to it.
	if (std::abs(u.dot(T.linear().col(2))) >= std::sin(opt_.min_line_elevation_deg * kRadPerDeg)) return false;
	const Eigen::Vector3f here = T.translation().cast<float>();
	const float reach2 = static_cast<float>(opt_.view_dependent_reach * opt_.view_dependent_reach);
	for (int i = 0; i < k; ++i)
		if ((scan_origins_[tags[i] >> 1] - here).squaredNorm() > reach2) return true;
	return false;
}

int ScanToMap::keepSimilarViews(const Eigen::Vector3f& q, const Eigen::Vector3f& here, Eigen::Vector3f* nn, std::uint32_t* tags, int n) const
{
	const float cos_max = static_cast<float>(std::cos(opt_.outline_view_change_deg * kRadPerDeg));
	const Eigen::Vector2f now = (q - here).head<2>().normalized();
	int kept = 0;
	for (int i = 0; i < n; ++i)
		if (now.dot((nn[i] - scan_origins_[tags[i] >> 1]).head<2>().normalized()) >= cos_max)
			nn[kept] = nn[i], tags[kept] = tags[i], ++kept;
	return kept;
}

bool ScanToMap::seenFromOtherRange(const Eigen::Vector3f& p, const Eigen::Vector3f* nn, const std::uint32_t* tags, int k) const
{
	if (opt_.edge_range_ratio <= 0) return false;
	const float ratio = static_cast<float>(opt_.edge_range_ratio), range = p.norm();
	for (int i = 0; i < k; ++i)
	{
		const float then = (nn[i] - scan_origins_[tags[i] >> 1]).norm();
		if (then > ratio * range || range > ratio * then) return true;
	}
	return false;
}

void ScanToMap::findEdgeMatches(const Input& in, const Eigen::Isometry3d& T, Matches& out) const
{
	const Eigen::Matrix3f R = T.linear().cast<float>();
	const Eigen::Vector3f t = T.translation().cast<float>();
	const int k = opt_.knn;
	// Where outlines need views like the current one, the nearest points of other views give way
	// to those of similar views a little farther (within max_nn_distance).
	const bool by_view = opt_.outline_view_change_deg > 0;
	constexpr int kMaxCandidates = 32;
	const int candidates = by_view ? std::min(3 * k, kMaxCandidates) : k;
	const float reach = static_cast<float>(opt_.max_nn_distance);
	Eigen::Vector3f nn[kMaxCandidates];
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
	Eigen::Vector3d c;
	std::uint32_t tags[kMaxCandidates];
	for (std::size_t e = 0; e < in.edges.size(); ++e)
	{
		const Eigen::Vector3f& p = in.edges[e];
		const Eigen::Vector3f q = R * p + t;
		if (edge_map_.knn(q, k, reach, nn, tags) < k) continue;
		if (by_view)
		{
			bool outline = e < in.edge_silhouette.size() && in.edge_silhouette[e];
			for (int i = 0; i < k && !outline; ++i) outline = tags[i] & 1u;
			if (outline && keepSimilarViews(q, t, nn, tags, edge_map_.knn(q, candidates, reach, nn, tags)) < k) continue;
		}
		if (seenFromOtherRange(p, nn, tags, k)) continue;
		fit(nn, k, c, es);
		if (!lineLike(es, opt_.edge_eigen_ratio) || flatAcross(es, opt_.edge_flatness_ratio)) continue;
		const Eigen::Vector3d u = es.eigenvectors().col(2);
		if (seenFromTooFar(u, tags, k, T)) continue;
		out.edges.push_back(EdgeMatch{p.cast<double>(), c, u});
	}
}

void ScanToMap::findPlaneMatches(const Input& in, const Eigen::Isometry3d& T, double max_distance, Matches& out) const
{
	const Eigen::Matrix3f R = T.linear().cast<float>();
	const Eigen::Vector3f t = T.translation().cast<float>();
	Eigen::Vector3f nn[32];
	PlaneMatch pm;
	for (const Eigen::Vector3f& p : in.planes)
		if (fitPlane(R * p + t, max_distance, nn, pm))
		{
			pm.p = p.cast<double>();
			out.planes.push_back(pm);
		}
}

void ScanToMap::findMatches(const Input& in, const Eigen::Isometry3d& T, MatchKinds kinds, Matches& out) const
{
	out.clear();
	if (kinds.edges) findEdgeMatches(in, T, out);
	findPlaneMatches(in, T, kinds.rough_planes ? opt_.rough_plane_max_distance : opt_.plane_max_distance, out);
}

double ScanToMap::translationInformation(
	const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes, const Eigen::Isometry3d& T) const
{
	Eigen::Matrix<double, 6, 6> JtJ;
	double rms;
	evaluateMatches(edges, planes, opt_.solver, T, JtJ, rms);
	return analyseDegeneracy(JtJ, 0).translation_information(0);
}

double ScanToMap::planeFit(const Input& in, const Eigen::Isometry3d& T) const
{
	Matches m;
	findMatches(in, T, {}, m);
	const double c2 = opt_.solver.loss_scale * opt_.solver.loss_scale;
	double sum = 0;
	for (const PlaneMatch& p : m.planes)
	{
		const double r = p.n.dot(T * p.p) + p.d;
		sum += 1.0 / (1.0 + r * r / c2);  // Cauchy's weight
	}
	return sum;
}

bool ScanToMap::refine(const Input& in, Result& res, const PosePrior* prior) const
{
	Matches m;
	Eigen::Isometry3d T = res.T_map_curr;
	SolveReport rep;
	// Round 0's plane matches at the guess decide, once per frame, whether lines are sought too
	// (edges = auto: only where the planes leave the translation weak).
	findMatches(in, T, {}, m);
	res.plane_information = translationInformation({}, m.planes, T);
	MatchKinds kinds;
	kinds.edges = opt_.edges == "on" || (opt_.edges == "auto" && res.plane_information < opt_.weak_plane_information);
	if (kinds.edges) findEdgeMatches(in, T, m);
	// Where planes and lines leave the translation nearly free (a 16-beam scan among trees), rough
	// planes (bumpy canopies, hedges) hold it; where the others fix it, they only add their bias.
	kinds.rough_planes = opt_.rough_plane_max_distance > opt_.plane_max_distance &&
		translationInformation(m.edges, m.planes, T) < opt_.rough_plane_information;
	if (kinds.rough_planes)
	{
		m.planes.clear();
		findPlaneMatches(in, T, opt_.rough_plane_max_distance, m);
	}
	res.used_edges = kinds.edges;
	res.used_rough_planes = kinds.rough_planes;
	double last_step = std::numeric_limits<double>::infinity();
	for (int round = 0; round < opt_.max_rounds; ++round)
	{
		if (round > 0) findMatches(in, T, kinds, m);
		res.n_edges = static_cast<int>(m.edges.size());
		res.n_planes = static_cast<int>(m.planes.size());
		if (res.n_planes < opt_.min_plane_correspondences || res.n_edges < opt_.min_edge_correspondences)
		{
			res.reason = "too few scan-to-map matches (" + std::to_string(res.n_edges) + " edges, " +
				std::to_string(res.n_planes) + " planes)";
			return false;
		}
		const Eigen::Isometry3d before = T;
		rep = solvePose(m, opt_.solver, T, prior);
		res.iterations += rep.iterations;
		++res.rounds;
		if (roundConverged(before, T, opt_.solver)) break;  // the matches would not change
		// Past A-LOAM's rounds only while the planes fix the translation at the pose reached, or, where
		// they leave it weak, while the lines fix it and each round moves less than the one before:
		// along a corridor the rounds slide off the guess on lines from the walls' noise, moving as
		// much each round; on a straight road the planes leave the way ahead weak, the poles and
		// corners fix it, and the rounds settle (stopping there left every frame 1 % short on the
		// real KITTI raw drive 2011_09_26_0013, doc/LOAM.md).
		const double step = (before.inverse() * T).translation().norm();
		const bool settling = step < last_step && translationInformation(m.edges, m.planes, T) >= opt_.weak_plane_information;
		last_step = step;
		if (res.rounds >= opt_.solver.outer_iterations && translationInformation({}, m.planes, T) < opt_.weak_plane_information &&
			!settling)
			break;
	}
	res.rms = rep.rms;
	if (prior) res.prior_geometry_cost = geometryCostOfPrior(*prior, rep.JtJ, T);
	res.degeneracy = analyseDegeneracy(rep.JtJ, opt_.degeneracy_threshold);
	res.JtJ = rep.JtJ;
	res.T_map_curr = T;
	return true;
}

ScanToMap::Input ScanToMap::withoutArrivals(const Input& in, const Eigen::Isometry3d& T, Result& res) const
{
	const Eigen::Isometry3f T_last_curr = (T_map_last_.inverse() * T).cast<float>();
	const Eigen::Isometry3f T_map_curr = T.cast<float>();
	Input still;
	const auto keep = [&](const std::vector<Eigen::Vector3f>& pts, std::vector<Eigen::Vector3f>& out) {
		for (const Eigen::Vector3f& p : pts)
			if (!last_free_->seenThrough(T_last_curr * p, static_cast<float>(opt_.free_space_beam_radius),
					static_cast<float>(opt_.free_space_margin), static_cast<float>(opt_.free_space_margin_per_metre)))
				out.push_back(p);
			else
				res.arrived.push_back(T_map_curr * p);
	};
	keep(in.edges, still.edges);
	keep(in.planes, still.planes);
	return still;
}

ScanToMap::Result ScanToMap::align(const Input& in, const Eigen::Isometry3d& guess, const PosePrior* prior) const
{
	Result res;
	res.T_map_curr = guess;
	// The guess is good to centimetres: enough to tell points that stand where the previous scan
	// saw through (a vehicle that drove into that space) from the static scene.
	if (opt_.drop_arrivals && last_free_)
		res.ok = refine(withoutArrivals(in, guess, res), res, prior);
	else
		res.ok = refine(in, res, prior);
	return res;
}

void ScanToMap::insert(const FeatureSet& f, const Eigen::Isometry3d& T_map_curr, const std::vector<Eigen::Vector3f>& arrived)
{
	const NearPoints near_arrivals(arrived, static_cast<float>(opt_.arrival_radius));
	const Eigen::Matrix3f R = T_map_curr.linear().cast<float>();
	const Eigen::Vector3f t = T_map_curr.translation().cast<float>();
	const float radius = static_cast<float>(opt_.map_radius);
	// Edges: centroids at the map's resolution (a third of the points, noise averaged).
	std::vector<Eigen::Vector3f> w;
	if (opt_.edges != "off")
	{
		const std::size_t n_creases = downsampledEdges(f, opt_.map_edge_resolution, w);
		std::vector<std::uint32_t> edge_tags;
		std::size_t n = 0;
		for (std::size_t i = 0; i < w.size(); ++i)
		{
			const Eigen::Vector3f q = R * w[i] + t;
			if (near_arrivals.near(q)) continue;
			w[n++] = q;
			edge_tags.push_back((scans_inserted_ << 1) | (i < n_creases ? 0u : 1u));
		}
		w.resize(n);
		edge_map_.insert(w, &edge_tags);
		edge_map_.removeFar(t, radius);
	}
	// Planes: merged along each ring, so every point keeps its scan line (frame, ring) as a tag.
	ScanPoints merged;
	{
		RingVoxelMerger merger(static_cast<float>(opt_.map_plane_resolution), merged);
		int ring = -1;
		for (const ScanPoint& p : f.less_flat)
		{
			if (p.ring != ring) merger.flush(), ring = p.ring;
			merger.add(p);
		}
	}
	w.clear();
	std::vector<std::uint32_t> tags;
	for (const ScanPoint& p : merged)
	{
		const Eigen::Vector3f q = R * p.p + t;
		if (near_arrivals.near(q)) continue;
		w.push_back(q);
		tags.push_back((scans_inserted_ << 8) | static_cast<std::uint32_t>(p.ring & 0xFF));
	}
	plane_map_.insert(w, &tags);
	plane_map_.removeFar(t, radius);
	scan_origins_.push_back(t);
	++scans_inserted_;
}

std::size_t ScanToMap::carve(const FeatureSet& f, const Eigen::Isometry3d& T_map_curr)
{
	if (opt_.free_space_radius <= 0) return 0;
	FreeSpace free(f.less_flat, f.less_sharp, opt_.free_space_azimuth_bins);
	const Eigen::Isometry3f T_curr_map = T_map_curr.inverse().cast<float>();
	const auto gone = [&](const Eigen::Vector3f& p) {
		return free.seenThrough(T_curr_map * p, static_cast<float>(opt_.free_space_beam_radius),
			static_cast<float>(opt_.free_space_margin), static_cast<float>(opt_.free_space_margin_per_metre));
	};
	const Eigen::Vector3f c = T_map_curr.translation().cast<float>();
	const float radius = static_cast<float>(opt_.free_space_radius);
	const std::size_t removed = edge_map_.removeIf(c, radius, gone) + plane_map_.removeIf(c, radius, gone);
	last_free_ = std::move(free);
	T_map_last_ = T_map_curr;
	return removed;
}

void ScanToMap::clear()
{
	edge_map_.clear();
	plane_map_.clear();
	last_free_.reset();
}
}  // namespace vlo::loam
