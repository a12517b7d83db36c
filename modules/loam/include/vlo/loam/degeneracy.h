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
	/// Of the translation information with the rotation estimated too (Schur complement of the
	/// rotation block), ascending [1/m^2 per m^2 of residual]: sigma / sqrt(value) is the standard
	/// deviation of the position along its eigenvector for residuals of standard deviation sigma.
	Eigen::Vector3d translation_information = Eigen::Vector3d::Zero();
	bool degenerate = false;  ///< min_eigenvalue < threshold
};

Degeneracy analyseDegeneracy(const Eigen::Matrix<double, 6, 6>& JtJ, double threshold);

/// Whether the translation is weakly constrained along one direction: its information there is
/// below `min_information`, or below `min_ratio` times that of the next weakest direction.
bool weakTranslation(const Degeneracy& d, double min_information, double min_ratio);
}  // namespace vlo::loam
