#include "vlo/loam/degeneracy.h"

#include <Eigen/Eigenvalues>

namespace vlo::loam
{
Degeneracy analyseDegeneracy(const Eigen::Matrix<double, 6, 6>& JtJ, double threshold)
{
	Degeneracy d;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(JtJ);
	if (es.info() != Eigen::Success)
	{
		d.degenerate = true;
		return d;
	}
	d.eigenvalues = es.eigenvalues();
	d.weakest = es.eigenvectors().col(0);
	d.min_eigenvalue = d.eigenvalues(0);
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> et(JtJ.bottomRightCorner<3, 3>(), Eigen::EigenvaluesOnly);
	d.min_translation_eigenvalue = et.eigenvalues()(0);
	d.degenerate = !(d.min_eigenvalue >= threshold);
	return d;
}
}  // namespace vlo::loam
