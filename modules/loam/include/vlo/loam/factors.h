#pragma once
// Ceres residuals of the point-to-line and point-to-plane distances, with analytic Jacobians
// (about three times cheaper than automatic differentiation for these tiny blocks).
// Parameters: an Eigen quaternion (x, y, z, w; with EigenQuaternionManifold) and a translation.
#include <vlo/loam/correspondences.h>

#include <ceres/sized_cost_function.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
/// d(q * p) / d(q.x, q.y, q.z, q.w) of Eigen's rotation formula p + 2w(v x p) + 2v x (v x p).
Eigen::Matrix<double, 3, 4> rotatedPointJacobian(const double* q, const Eigen::Vector3d& p);

/// r = (I - u u^T)(R p + t - a): the vector from the line to the point, 3 residuals.
class EdgeFactor final : public ceres::SizedCostFunction<3, 4, 3>
{
   public:
	explicit EdgeFactor(const EdgeMatch& m);
	bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

   private:
	Eigen::Vector3d p_, a_;
	Eigen::Matrix3d P_;  ///< projector orthogonal to the line
};

/// r = n . (R p + t) + d: signed distance to the plane.
class PlaneFactor final : public ceres::SizedCostFunction<1, 4, 3>
{
   public:
	explicit PlaneFactor(const PlaneMatch& m) : m_(m) {}
	bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

   private:
	PlaneMatch m_;
};

/// Many matches in one Ceres residual block, each weighted: residual sqrt(w_i) r_i with its exact
/// Jacobian, so the block's cost is the weighted least squares sum w_i |r_i|^2 / 2. With the
/// robust loss's weights rho'(s_i) taken at the start of a solve this is one step of iteratively
/// reweighted least squares: Ceres' own robust step for Huber and Cauchy (its corrector scales
/// by sqrt(rho') where rho'' <= 0), at a fraction of its per-block overhead. Null weights: all 1.
/// Matches and weights must outlive the factor.
class BatchFactor final : public ceres::CostFunction
{
   public:
	BatchFactor(const EdgeMatch* edges, const double* edge_weights, int n_edges, const PlaneMatch* planes,
		const double* plane_weights, int n_planes);
	bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

   private:
	const EdgeMatch* edges_;
	const PlaneMatch* planes_;
	const double *edge_w_, *plane_w_;
	int n_edges_, n_planes_;
};
}  // namespace vlo::loam
