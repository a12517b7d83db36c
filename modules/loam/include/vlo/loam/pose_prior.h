#pragma once
// An external motion (the visual odometry's) as a residual of scan-to-map's solve: the pose should
// lie at the prior's pose, with an information that says how far along each direction it can be
// trusted. Where the map's lines and planes hardly constrain a direction (a corridor's axis, a
// VLP-16 among foliage) the prior decides it; where they are strong they outweigh it.
#include <vlo/loam/options.h>

#include <Eigen/Geometry>
#include <limits>

namespace vlo::loam
{
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

struct PosePrior
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< where the prior puts the scan in the map
	/// Over the solver's tangent [rotation (left, map axes), translation (map axes)], in the units of
	/// the matches' J^T J: a unit-weight plane match with normal n adds n n^T to the translation block.
	Matrix6d information = Matrix6d::Zero();

	/// [log(R R_prior^T), t - t_prior]: the solver's tangent, so its Jacobian is the identity.
	Vector6d residual(const Eigen::Isometry3d& T) const;
	/// The prior's cost term r^T information r at T (twice the cost it adds).
	double squaredMahalanobis(const Eigen::Isometry3d& T) const;
};

/// What the source of an external motion says of it (NaN: unknown).
struct ExternalMotionQuality
{
	double tracked = std::numeric_limits<double>::quiet_NaN();  ///< image features tracked for it
	double length_error = std::numeric_limits<double>::quiet_NaN();  ///< relative standard error of its length
};

/// The prior of an external motion (the pose of this LiDAR frame in the previous one) from the
/// previous frame's map pose: [loam.prior] motion_sigma per axis, motion_sigma_deg for roll and pitch,
/// motion_sigma_yaw_deg about the scan's z axis, the variances
/// scaled up where fewer than full_quality_tracked features were tracked, plus (length x
/// length_error)^2 along the motion; in the units of matches of standard deviation `match_sigma`
/// (match_sigma^2 / variance).
PosePrior externalMotionPrior(const Eigen::Isometry3d& previous_pose, const Eigen::Isometry3d& motion,
	const ExternalMotionQuality& quality, const PriorOptions& o, double match_sigma);

/// How much the prior raised the matches' cost at the joint solution T, twice the rise:
/// (I r)^T H^-1 (I r) with I the prior's information, r its residual at T and H the matches'
/// J^T J. At the joint optimum I r balances the matches' gradient, and this is what moving back to
/// their own optimum would save them: small along directions they hardly constrain, large where
/// the prior pulls against a direction they fix.
double geometryCostOfPrior(const PosePrior& prior, const Matrix6d& matches_JtJ, const Eigen::Isometry3d& T);

/// A prior at `pose` whose information is given in the scan's own axes (the LiDAR frame at `pose`):
/// `rotation_information` and `translation_information` (3x3 each) are turned into the map's axes.
PosePrior posePriorInScanAxes(
	const Eigen::Isometry3d& pose, const Eigen::Matrix3d& rotation_information, const Eigen::Matrix3d& translation_information);
}  // namespace vlo::loam
