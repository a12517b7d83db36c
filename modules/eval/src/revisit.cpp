#include <vlo/core/se3.h>
#include <vlo/core/units.h>
#include <vlo/eval/kitti_metric.h>
#include <vlo/eval/revisit.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace vlo::eval
{
namespace
{
/// Cubes of the radius's size: a place's earlier visits are in its own cube or the 26 around it, so a
/// long drive is searched in linear time rather than comparing every pose with every other.
class PlaceGrid
{
   public:
	explicit PlaceGrid(double cell) : cell_(cell) {}

	void insert(const Eigen::Vector3d& p, std::size_t index) { cells_[key(cellOf(p))].push_back(index); }

	/// Calls f(index) for every inserted pose in the cube of p and its neighbours.
	template <class F>
	void forNeighbours(const Eigen::Vector3d& p, F f) const
	{
		const Eigen::Vector3i c = cellOf(p);
		for (int dx = -1; dx <= 1; ++dx)
			for (int dy = -1; dy <= 1; ++dy)
				for (int dz = -1; dz <= 1; ++dz)
				{
					const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
					if (it != cells_.end())
						for (const std::size_t i : it->second) f(i);
				}
	}

   private:
	Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const { return (p / cell_).array().floor().cast<int>(); }
	/// 21 bits per axis: unique within +-1e6 cells (3000 km at 3 m); beyond, cells share a key, which only
	/// adds candidates that the distance test then rejects.
	static std::int64_t key(const Eigen::Vector3i& c)
	{
		const auto bits = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & ((1 << 21) - 1); };
		return (bits(c.x()) << 42) | (bits(c.y()) << 21) | bits(c.z());
	}

	double cell_;
	std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};
}  // namespace

std::vector<RevisitPair> findRevisits(const Trajectory& gt, const RevisitOptions& opts)
{
	if (!(opts.radius_m > 0) || !std::isfinite(opts.radius_m))
		throw std::invalid_argument("findRevisits: the radius must be positive and finite");
	const std::vector<double> dist = trajectoryDistances(gt);
	PlaceGrid grid(opts.radius_m);
	std::vector<RevisitPair> pairs;
	std::size_t inserted = 0;  // poses [0, inserted) lie at least min_path_m of path before the current one
	for (std::size_t j = 0; j < gt.size(); ++j)
	{
		for (; inserted < j && dist[j] - dist[inserted] >= opts.min_path_m; ++inserted)
			grid.insert(gt[inserted].pose.translation(), inserted);
		const Eigen::Vector3d pj = gt[j].pose.translation();
		RevisitPair best{0, j, opts.radius_m, 0, 0};
		bool found = false;
		grid.forNeighbours(pj, [&](std::size_t i) {
			const double d = (gt[i].pose.translation() - pj).norm();
			if (d > opts.radius_m || (found && (d > best.distance_m || (d == best.distance_m && i > best.first)))) return;
			best.first = i, best.distance_m = d, found = true;
		});
		if (found) pairs.push_back(best);
	}
	return pairs;
}

RevisitResult computeRevisitError(const Trajectory& gt, const Trajectory& est, const RevisitOptions& opts)
{
	RevisitResult r;
	r.pairs = findRevisits(gt, opts);
	if (r.empty()) return r;
	double t2 = 0, r2 = 0;
	for (auto& p : r.pairs)
	{
		const Eigen::Isometry3d truth = gt[p.first].pose.inverse() * gt[p.second].pose;
		const Eigen::Isometry3d e = truth.inverse() * (est[p.first].pose.inverse() * est[p.second].pose);
		p.t_err_m = e.translation().norm();
		p.r_err_deg = kDegPerRad * rotationAngle(e.linear());
		t2 += p.t_err_m * p.t_err_m, r2 += p.r_err_deg * p.r_err_deg;
		r.t_max_m = std::max(r.t_max_m, p.t_err_m), r.r_max_deg = std::max(r.r_max_deg, p.r_err_deg);
	}
	const double n = static_cast<double>(r.pairs.size());
	r.t_rmse_m = std::sqrt(t2 / n), r.r_rmse_deg = std::sqrt(r2 / n);
	return r;
}
}  // namespace vlo::eval
