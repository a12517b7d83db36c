#pragma once
// Information (inverse covariance) of a pose estimate and its changes of frame. A pose T = [R, p] is
// perturbed as T' = [exp(dtheta) R, p + dp], delta = [dp; dtheta] with both parts in the parent
// frame's axes (the rotation about T's own origin): the pose graph's residual (modules/loop). An
// information I over delta means a cost delta^T I delta.
#include <Eigen/Geometry>

#include <cstddef>

namespace vlo
{
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// A registration's J^T J (over delta, from `pairs` residuals of RMS `rms` [m]) as the information
/// of its pose, the same for the odometry's registrations and the loops': the residuals are not
/// independent (the calibration's and the surfaces' errors are shared by neighbouring points), so
/// the J^T J of all `pairs` is taken as that of kRegistrationEffectivePoints, at sigma = rms (at
/// least kRegistrationMinSigma). Zero without pairs.
Matrix6d registrationInformation(const Matrix6d& JtJ, std::size_t pairs, double rms);
constexpr double kRegistrationEffectivePoints = 100.0;
constexpr double kRegistrationMinSigma = 0.01;  // [m]

/// The inverse of a symmetric positive semi-definite matrix, its eigenvalues clamped to at least
/// 1e-12 of the largest: an information with a direction unconstrained gives a covariance that is
/// huge there, not infinite (and back).
Matrix6d invertPositive(const Matrix6d& M);

/// The information over delta of a pose at `position` from one over a left twist [translation;
/// rotation] (T' = exp(twist) T, KISS-ICP's Gauss-Newton): the twist turns the pose about the
/// world's origin, delta about the pose's own.
Matrix6d informationFromLeftTwist(const Matrix6d& twist_information, const Eigen::Vector3d& position);

/// The information of the motion from `previous` to a pose (previous^-1 T, previous held fixed) from
/// the information of the pose T itself (both over delta, the pose's in the world's axes).
Matrix6d relativeInformation(const Matrix6d& world_information, const Eigen::Isometry3d& previous);

/// The information of a sensor's motion L (over delta) seen as the vehicle's motion V =
/// vehicle_T_sensor * L * vehicle_T_sensor^-1: through the adjoint of vehicle_T_sensor. A rotation
/// of the sensor is a translation of the vehicle's origin at the lever arm.
Matrix6d vehicleMotionInformation(
	const Matrix6d& sensor_information, const Eigen::Isometry3d& vehicle_T_sensor, const Eigen::Isometry3d& vehicle_motion);

/// How delta of the composition A * B follows from delta_A and delta_B: d(AB) = Ja dA + Jb dB.
struct CompositionJacobians
{
	Matrix6d Ja, Jb;
};
CompositionJacobians compositionJacobians(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B);

/// The covariance of A * B from those of A and B (independent), to first order.
Matrix6d composeCovariance(
	const Matrix6d& cov_A, const Eigen::Isometry3d& A, const Matrix6d& cov_B, const Eigen::Isometry3d& B);
}  // namespace vlo
