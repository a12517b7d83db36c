#pragma once
// Keypoint culling with the VO relative pose (paper III-B-2, eqs. 2-4).
// cur_T_prev = T_{C(i-1)}^{C(i)} maps points of the C(i-1) optical frame into C(i): X_i = R X_{i-1} + t.
#include <vlo/scale/diagnostics.h>
#include <vlo/scale/options.h>

#include <opencv2/core/types.hpp>

#include <Eigen/Geometry>

namespace vlo::scale
{
/// F = K^-T [t]x R K^-1 with t normalised (its scale, wrong in a monocular VO, does not matter).
/// Zero when t is zero: there is no epipolar geometry without translation.
Eigen::Matrix3d fundamentalMatrix(const Eigen::Matrix3d& K, const Eigen::Isometry3d& cur_T_prev);

/// Epipolar line (A, B, C) in C(i) of pixel x_prev of C(i-1): A x + B y + C = 0.
Eigen::Vector3d epipolarLine(const Eigen::Matrix3d& F, cv::Point2f x_prev);

/// Eq. 3: |A x + B y + C| / sqrt(A^2 + B^2) [px]; infinity for a degenerate line.
double normalError(const Eigen::Vector3d& line, cv::Point2f x_cur);

/// Eq. 4: |cos| of the angle between the line direction (-B, A) and the image gradient; 0 when
/// either vanishes (a flat patch says nothing about where along the line the match is).
double absCosToLine(const Eigen::Vector3d& line, cv::Point2f gradient);

struct CullResult
{
	Stage rejected_by = Stage::None;  ///< None, Epipolar or Gradient
	double normal_error = 0, abs_cos = 0;
};
/// Both culling criteria for the match x_prev -> x_cur, `gradient` being the image gradient of C(i) at
/// x_cur: kept when normal error < epipolar_max_error and |cos| > min_abs_cos (each stage only when
/// switched on; both values are always computed for the diagnostics).
CullResult cullMatch(const Eigen::Matrix3d& F, cv::Point2f x_prev, cv::Point2f x_cur, cv::Point2f gradient,
	const ScaleOptions& opt);
}  // namespace vlo::scale
