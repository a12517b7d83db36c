#include <vlo/icp/registration.h>
#include <vlo/core/se3_twist.h>

#include <Eigen/Cholesky>
#include <cmath>

namespace vlo::icp
{
namespace
{
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct Step
{
	Matrix6d JtJ = Matrix6d::Zero();
	Vector6d Jtr = Vector6d::Zero();
	std::size_t n = 0;
	double sum_e2 = 0;
};

/// Pairs every moved scan point with its nearest map point and accumulates the weighted normal equations
/// of r = p - q, with dr/d(twist) = [I, -[p]x] for a left perturbation of the pose.
Step buildSystem(const Points& moved, const VoxelMap& map, const RegistrationParams& params)
{
	Step s;
	const double gate2 = params.max_distance * params.max_distance;
	Eigen::Matrix<double, 3, 6> J;
	J.leftCols<3>().setIdentity();
	Eigen::Vector3d q;
	double d2 = 0;
	for (const auto& p : moved)
	{
		if (!map.nearest(p, q, d2, gate2)) continue;
		const Eigen::Vector3d r = p - q;
		J.rightCols<3>() = -skew(p);
		const double w = gemanMcClureWeight(d2, params.kernel);
		s.JtJ.noalias() += w * J.transpose() * J;
		s.Jtr.noalias() += w * J.transpose() * r;
		s.sum_e2 += d2;
		++s.n;
	}
	return s;
}
}  // namespace

double gemanMcClureWeight(double e2, double kernel)
{
	const double k2 = kernel * kernel;
	const double f = k2 / (k2 + e2);
	return f * f;
}

RegistrationResult alignToMap(
	const Points& scan, const VoxelMap& map, const Eigen::Isometry3d& guess, const RegistrationParams& params)
{
	RegistrationResult res;
	res.pose = guess;
	if (map.empty() || scan.empty()) return res;
	Points moved(scan.size());
	for (; res.iterations < params.max_iterations;)
	{
		for (std::size_t i = 0; i < scan.size(); ++i) moved[i] = res.pose * scan[i];
		const Step s = buildSystem(moved, map, params);
		res.correspondences = s.n;
		res.rms = s.n ? std::sqrt(s.sum_e2 / static_cast<double>(s.n)) : 0.0;
		res.JtJ = s.JtJ;
		if (s.n < params.min_correspondences) break;
		const Vector6d dx = s.JtJ.ldlt().solve(-s.Jtr);
		if (!dx.allFinite()) break;
		res.pose = expTwist(dx) * res.pose;
		++res.iterations;
		if (dx.norm() < params.convergence)
		{
			res.converged = true;
			break;
		}
	}
	res.pose.linear() = Eigen::Quaterniond(res.pose.linear()).normalized().toRotationMatrix();
	return res;
}
}  // namespace vlo::icp
