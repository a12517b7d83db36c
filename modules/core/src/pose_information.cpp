#include <vlo/core/pose_information.h>
#include <vlo/core/se3_twist.h>

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace vlo
{
namespace
{
Matrix6d blockDiagonal(const Eigen::Matrix3d& R)
{
	Matrix6d B = Matrix6d::Zero();
	B.topLeftCorner<3, 3>() = R;
	B.bottomRightCorner<3, 3>() = R;
	return B;
}

Matrix6d symmetric(const Matrix6d& M) { return 0.5 * (M + M.transpose()); }
}  // namespace

Matrix6d registrationInformation(const Matrix6d& JtJ, std::size_t pairs, double rms)
{
	if (pairs == 0) return Matrix6d::Zero();
	const double sigma = std::max(rms, kRegistrationMinSigma);
	return JtJ * (kRegistrationEffectivePoints / static_cast<double>(pairs)) / (sigma * sigma);
}

Matrix6d invertPositive(const Matrix6d& M)
{
	const Eigen::SelfAdjointEigenSolver<Matrix6d> es(symmetric(M));
	const double largest = std::max(es.eigenvalues().maxCoeff(), 1e-300);
	const Eigen::Matrix<double, 6, 1> inverse =
		es.eigenvalues().cwiseMax(1e-12 * largest).cwiseInverse();
	return es.eigenvectors() * inverse.asDiagonal() * es.eigenvectors().transpose();
}

Matrix6d informationFromLeftTwist(const Matrix6d& twist_information, const Eigen::Vector3d& position)
{
	// delta = C twist, C = [I, -[p]x; 0, I]: a turn dtheta about the origin moves the pose by dtheta x p.
	Matrix6d C_inv = Matrix6d::Identity();
	C_inv.topRightCorner<3, 3>() = skew(position);
	return symmetric(C_inv.transpose() * twist_information * C_inv);
}

Matrix6d relativeInformation(const Matrix6d& world_information, const Eigen::Isometry3d& previous)
{
	// delta of T in the world's axes = diag(Rp, Rp) delta of previous^-1 T in previous' axes.
	const Matrix6d B = blockDiagonal(previous.linear());
	return symmetric(B.transpose() * world_information * B);
}

Matrix6d vehicleMotionInformation(
	const Matrix6d& sensor_information, const Eigen::Isometry3d& vehicle_T_sensor, const Eigen::Isometry3d& vehicle_motion)
{
	// With right perturbations xi (T' = T exp(xi)), V = M L M^-1 gives xi_V = Ad(M) xi_L; delta =
	// diag(R, R) xi for a pose of rotation R.
	const Eigen::Matrix3d& Rm = vehicle_T_sensor.linear();
	Matrix6d Ad = blockDiagonal(Rm);
	Ad.topRightCorner<3, 3>() = skew(vehicle_T_sensor.translation()) * Rm;
	const Eigen::Matrix3d RL = Rm.transpose() * vehicle_motion.linear() * Rm;
	const Matrix6d A = blockDiagonal(vehicle_motion.linear()) * Ad * blockDiagonal(RL.transpose());  // delta_V = A delta_L
	const Matrix6d A_inv = A.inverse();
	return symmetric(A_inv.transpose() * sensor_information * A_inv);
}

CompositionJacobians compositionJacobians(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B)
{
	// AB = [Ra Rb, pa + Ra pb]: dA turns Ra pb about A's origin; dB is in A's axes.
	CompositionJacobians J;
	J.Ja = Matrix6d::Identity();
	J.Ja.topRightCorner<3, 3>() = -skew(A.linear() * B.translation());
	J.Jb = blockDiagonal(A.linear());
	return J;
}

Matrix6d composeCovariance(
	const Matrix6d& cov_A, const Eigen::Isometry3d& A, const Matrix6d& cov_B, const Eigen::Isometry3d& B)
{
	const CompositionJacobians J = compositionJacobians(A, B);
	return symmetric(J.Ja * cov_A * J.Ja.transpose() + J.Jb * cov_B * J.Jb.transpose());
}
}  // namespace vlo
