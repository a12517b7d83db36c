#pragma once
// Degeneracy of a registration (Zhang, Kaess, Singh, ICRA 2016): small eigenvalues of the
// approximate Hessian J^T J mean directions the geometry does not constrain (a tunnel along its
// axis, a plain along its normal's rotation, ...).
#include <Eigen/Core>

namespace vlo::loam
{
/// J^T J is taken with respect to [rotation about the sensor (world axes) [rad], translation [m]].
struct Degeneracy
{
	Eigen::Matrix<double, 6, 1> eigenvalues = Eigen::Matrix<double, 6, 1>::Zero();  ///< ascending
	Eigen::Matrix<double, 6, 1> weakest = Eigen::Matrix<double, 6, 1>::Zero();  ///< eigenvector of the smallest
	double min_eigenvalue = 0;
	double min_translation_eigenvalue = 0;  ///< of the translation block alone
	bool degenerate = false;  ///< min_eigenvalue < threshold
};

Degeneracy analyseDegeneracy(const Eigen::Matrix<double, 6, 6>& JtJ, double threshold);
}  // namespace vlo::loam
