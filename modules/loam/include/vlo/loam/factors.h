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
}  // namespace vlo::loam

namespace ceres
{
class LossFunction;
}

namespace vlo::loam
{
/// Many matches in one Ceres residual block, each robustified on its own: residual
/// sqrt(rho(s)/s) * r with its exact Jacobian, so the block's squared norm is sum rho(s_i), the
/// very cost of one block per match with the loss attached, at a fraction of Ceres' per-block
/// overhead. `loss` may be null (plain least squares); matches must outlive the factor.
class BatchFactor final : public ceres::CostFunction
{
   public:
	BatchFactor(const EdgeMatch* edges, int n_edges, const PlaneMatch* planes, int n_planes, const ceres::LossFunction* loss);
	bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

   private:
	const EdgeMatch* edges_;
	const PlaneMatch* planes_;
	int n_edges_, n_planes_;
	const ceres::LossFunction* loss_;
};
}  // namespace vlo::loam
