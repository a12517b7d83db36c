// Candidate motions of an essential matrix or a homography, and the cheirality check between them.
#include <vlo/vo/triangulation.h>
#include <vlo/vo/two_view.h>

#include <Eigen/SVD>
// After Eigen, as OpenCV's bridge requires.
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <algorithm>
#include <cmath>

namespace vlo::vo::detail
{
std::vector<Motion> decomposeEssential(const Mat3& E21)
{
	const Eigen::JacobiSVD<Mat3> svd(E21, Eigen::ComputeFullU | Eigen::ComputeFullV);
	const Mat3 U = svd.matrixU(), V = svd.matrixV();
	Mat3 W;
	W << 0, -1, 0, 1, 0, 0, 0, 0, 1;
	Mat3 R1 = U * W * V.transpose(), R2 = U * W.transpose() * V.transpose();
	if (R1.determinant() < 0) R1 = -R1;
	if (R2.determinant() < 0) R2 = -R2;
	const Vec3 t = U.col(2).normalized();
	return {{R1, t}, {R1, -t}, {R2, t}, {R2, -t}};
}

std::vector<Motion> decomposeHomography(const Mat3& H21, const Mat3& K)
{
	cv::Mat Hc, Kc;
	cv::eigen2cv(H21, Hc);
	cv::eigen2cv(K, Kc);
	std::vector<cv::Mat> Rs, ts, ns;
	cv::decomposeHomographyMat(Hc, Kc, Rs, ts, ns);
	std::vector<Motion> out;
	for (std::size_t i = 0; i < Rs.size(); ++i)
	{
		Motion m;
		cv::cv2eigen(Rs[i], m.R);
		cv::cv2eigen(ts[i], m.t);
		if (m.t.norm() < 1e-12) continue;  // pure rotation: no structure to check
		m.t.normalize();
		out.push_back(m);
	}
	return out;
}

CheckResult checkMotion(const Motion& m, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2,
	const std::vector<char>& inliers, const Mat3& K, double th2)
{
	CheckResult r;
	r.points.assign(x1.size(), Vec3::Zero());
	r.good.assign(x1.size(), 0);
	const Mat3 Kinv = K.inverse();
	const SE3 T1 = SE3::Identity(), T2 = makeSE3(m.R, m.t);
	const Vec3 O2 = centre(T2);
	std::vector<double> cos_parallax;
	for (std::size_t i = 0; i < x1.size(); ++i)
	{
		if (!inliers[i]) continue;
		Vec3 X;
		if (!triangulate(T1, T2, Kinv * x1[i].homogeneous(), Kinv * x2[i].homogeneous(), X)) continue;
		const double c = parallaxCos(X, Vec3::Zero(), O2);
		const Vec3 X2 = m.R * X + m.t;
		// Depth sign is meaningless without parallax, so only points with parallax must be in front.
		if ((X.z() <= 0 || X2.z() <= 0) && c < 0.99998) continue;
		const Vec2 p1 = (K * X).hnormalized(), p2 = (K * X2).hnormalized();
		if ((p1 - x1[i]).squaredNorm() > th2 || (p2 - x2[i]).squaredNorm() > th2) continue;
		cos_parallax.push_back(c);
		++r.n_good;
		r.points[i] = X;
		if (c < 0.99998) r.good[i] = 1;
	}
	if (!cos_parallax.empty())
	{
		std::sort(cos_parallax.begin(), cos_parallax.end());
		const double c = cos_parallax[std::min<std::size_t>(50, cos_parallax.size() - 1)];
		r.parallax_deg = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
	}
	return r;
}
}  // namespace vlo::vo::detail
