// Pose-only optimisation of a tracked frame (ORB-SLAM's PoseOptimization) with core's reweighted
// Levenberg-Marquardt: one pass over the observations per iteration, no per-solve set-up.
#include <vlo/core/robust_pose_solver.h>
#include <vlo/vo/optimizer.h>

#include "reprojection_error.h"

namespace vlo::vo
{
namespace
{
struct SeenPoint
{
	Vec3 X;  ///< the map point (world)
	Vec2 px;  ///< its keypoint
	double inv_sigma;  ///< 1 / the keypoint's pyramid scale
};

/// Fixed points' reprojection errors over their keypoints' sigma (the squared residual is the
/// chi-square statistic with 2 dof), as solveRobustPose's problem.
struct ReprojectionProblem
{
	const std::vector<SeenPoint>& obs;
	const PinholeCamera& cam;

	Vec2 residual(const SeenPoint& o, const Vec3& Xc) const
	{
		return (project(cam, Vec3(Xc.x(), Xc.y(), detail::safeDepth(Xc.z()))) - o.px) * o.inv_sigma;
	}
	void squaredResiduals(const SE3& T, std::vector<double>& s) const
	{
		s.clear();
		for (const SeenPoint& o : obs) s.push_back(residual(o, T * o.X).squaredNorm());
	}
	PoseNormalEquations normalEquations(const std::vector<double>& w, const SE3& T) const
	{
		PoseNormalEquations ne;
		Eigen::Matrix<double, 2, 6> J;
		for (std::size_t i = 0; i < obs.size(); ++i)
		{
			const SeenPoint& o = obs[i];
			const Vec3 RX = T.linear() * o.X, Xc = RX + T.translation();
			const Vec2 r = residual(o, Xc);
			const double iz = 1.0 / detail::safeDepth(Xc.z());
			Eigen::Matrix<double, 2, 3> Jp;
			Jp << cam.fx * iz, 0, -cam.fx * Xc.x() * iz * iz, 0, cam.fy * iz, -cam.fy * Xc.y() * iz * iz;
			Jp *= o.inv_sigma;
			J.leftCols<3>() = -Jp * skew(RX);  // rotation perturbed on the left: d(exp(w) R X)/dw
			J.rightCols<3>() = Jp;
			ne.H.noalias() += w[i] * J.transpose() * J;
			ne.g.noalias() += w[i] * J.transpose() * r;
			ne.cost += 0.5 * w[i] * r.squaredNorm();
		}
		return ne;
	}
};
}  // namespace

int optimizePose(TrackedFrame& f, const PinholeCamera& cam, const ScalePyramid& pyr, int rounds, int iterations,
	double chi2)
{
	std::vector<std::size_t> idx;
	for (std::size_t i = 0; i < f.size(); ++i)
	{
		f.outlier[i] = 0;
		if (f.points[i] && !f.points[i]->bad) idx.push_back(i);
	}
	if (idx.size() < 3) return 0;
	SE3 T = f.Tcw;
	int inliers = static_cast<int>(idx.size());
	std::vector<SeenPoint> obs;
	for (int round = 0; round < rounds; ++round)
	{
		obs.clear();
		for (std::size_t i : idx)
		{
			if (f.outlier[i]) continue;
			const cv::KeyPoint& k = f.feat->keys[i];
			obs.push_back({f.points[i]->pos, Vec2(k.pt.x, k.pt.y), pyr.inv_scale[static_cast<std::size_t>(k.octave)]});
		}
		if (obs.size() < 3) break;
		// Robust only in the first rounds: once outliers are marked, plain least squares.
		const RobustWeight weight(round < 2 ? RobustWeight::Huber : RobustWeight::None, std::sqrt(chi2));
		solveRobustPose(ReprojectionProblem{obs, cam}, weight, iterations, T);
		inliers = 0;
		for (std::size_t i : idx)
		{
			const cv::KeyPoint& k = f.feat->keys[i];
			const Vec3 Xc = T * f.points[i]->pos;
			const double e2 = Xc.z() > 0 ? (project(cam, Xc) - Vec2(k.pt.x, k.pt.y)).squaredNorm() *
					pyr.inv_sigma2[static_cast<std::size_t>(k.octave)]
										 : 1e18;
			f.outlier[i] = e2 > chi2 ? 1 : 0;
			if (!f.outlier[i]) ++inliers;
		}
		if (inliers < 10) break;
	}
	f.Tcw = T;
	return inliers;
}
}  // namespace vlo::vo
