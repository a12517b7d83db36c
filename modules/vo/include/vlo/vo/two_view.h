#pragma once
// Two-view reconstruction for map initialisation (ORB-SLAM's Initializer): homography and
// fundamental matrix estimated by RANSAC on the same random sets, scored by symmetric transfer
// error, chosen by R_H = S_H / (S_H + S_F); the chosen model is decomposed into its candidate
// motions and the one that places the most points in front of both cameras with enough parallax
// and small reprojection error wins, if it clearly beats the others.
#include <vlo/vo/geometry.h>
#include <vlo/vo/options.h>

#include <string>
#include <vector>

namespace vlo::vo
{
struct TwoViewResult
{
	bool ok = false;
	std::string reason;  ///< why not, when !ok
	char model = 0;  ///< 'H' or 'F'
	double rh = 0;  ///< S_H / (S_H + S_F)
	SE3 T21 = SE3::Identity();  ///< camera 1 -> camera 2 (X2 = T21 * X1), |t| = 1
	std::vector<Vec3> points;  ///< per correspondence, in camera 1 (valid where good)
	std::vector<char> good;  ///< triangulated, in front, consistent, with parallax
	int n_good = 0, n_inliers = 0;
	double parallax_deg = 0;
};

/// x1[i] <-> x2[i] in pixels (at least 8). Deterministic for a given opt.seed.
TwoViewResult reconstructTwoView(
	const PinholeCamera& cam, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, const InitOptions& opt);

namespace detail
{
/// Model fitting pieces, exposed for tests.
Mat3 homographyDLT(const std::vector<Vec2>& x1, const std::vector<Vec2>& x2);  ///< x2 ~ H21 x1
Mat3 fundamental8(const std::vector<Vec2>& x1, const std::vector<Vec2>& x2);  ///< x2^T F21 x1 = 0, rank 2
double scoreHomography(const Mat3& H21, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, double sigma,
	std::vector<char>& inliers);
double scoreFundamental(const Mat3& F21, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, double sigma,
	std::vector<char>& inliers);

struct Motion
{
	Mat3 R;
	Vec3 t;
};
/// The four (R, t) of an essential matrix, |t| = 1.
std::vector<Motion> decomposeEssential(const Mat3& E21);
/// The motions of a homography (OpenCV's analytic decomposition), t scaled to |t| = 1.
std::vector<Motion> decomposeHomography(const Mat3& H21, const Mat3& K);

struct CheckResult
{
	int n_good = 0;
	double parallax_deg = 0;
	std::vector<Vec3> points;
	std::vector<char> good;
};
/// Triangulates the inliers with motion m and counts points in front of both cameras with
/// reprojection error below th2 (squared pixels); parallax is that of the 50th largest.
CheckResult checkMotion(const Motion& m, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2,
	const std::vector<char>& inliers, const Mat3& K, double th2);
}  // namespace detail
}  // namespace vlo::vo
