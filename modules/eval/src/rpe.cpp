#include <vlo/core/se3.h>
#include <vlo/core/units.h>
#include <vlo/eval/rpe.h>

#include <cmath>

namespace vlo::eval
{
RpeResult computeRpe(const Trajectory& gt, const Trajectory& est)
{
	RpeResult r;
	double t2 = 0, r2 = 0, cvt2 = 0, cvr2 = 0;
	Eigen::Vector3d axes2 = Eigen::Vector3d::Zero();
	std::size_t n_cv = 0;
	for (std::size_t i = 0; i + 1 < gt.size() && i + 1 < est.size(); ++i)
	{
		const Eigen::Isometry3d g = gt[i].pose.inverse() * gt[i + 1].pose;
		const Eigen::Isometry3d e = g.inverse() * (est[i].pose.inverse() * est[i + 1].pose);
		t2 += e.translation().squaredNorm();
		axes2 += e.translation().cwiseAbs2();
		r2 += std::pow(kDegPerRad * rotationAngle(e.linear()), 2);
		++r.n;
		if (i + 2 < gt.size())
		{
			const Eigen::Isometry3d next = gt[i + 1].pose.inverse() * gt[i + 2].pose;
			const Eigen::Isometry3d miss = next.inverse() * g;
			cvt2 += miss.translation().squaredNorm();
			cvr2 += std::pow(kDegPerRad * rotationAngle(miss.linear()), 2);
			++n_cv;
		}
	}
	if (r.n == 0) return r;
	const double n = static_cast<double>(r.n);
	r.t_rmse_m = std::sqrt(t2 / n);
	r.r_rmse_deg = std::sqrt(r2 / n);
	r.t_rmse_axes_m = (axes2 / n).cwiseSqrt();
	if (n_cv > 0)
	{
		r.cv_t_rmse_m = std::sqrt(cvt2 / static_cast<double>(n_cv));
		r.cv_r_rmse_deg = std::sqrt(cvr2 / static_cast<double>(n_cv));
	}
	return r;
}
}  // namespace vlo::eval
