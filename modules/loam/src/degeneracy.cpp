#include <vlo/loam/degeneracy.h>

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
	const Eigen::Matrix3d Rr = JtJ.topLeftCorner<3, 3>(), Rt = JtJ.topRightCorner<3, 3>();
	const Eigen::Matrix3d S = JtJ.bottomRightCorner<3, 3>() - Rt.transpose() * Rr.ldlt().solve(Rt);
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es3(S, Eigen::EigenvaluesOnly);
	d.translation_information = es3.eigenvalues();
	d.degenerate = !(d.min_eigenvalue >= threshold);
	return d;
}

bool weakTranslation(const Degeneracy& d, double min_information, double min_ratio)
{
	const Eigen::Vector3d& info = d.translation_information;
	return !(info(0) >= min_information) || !(info(0) >= min_ratio * info(1));
}
}  // namespace vlo::loam
