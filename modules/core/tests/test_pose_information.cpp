// Information of poses: the registrations' scaling, the composition along a chain and the change
// to the vehicle frame, against closed forms.
#include <gtest/gtest.h>
#include <vlo/core/pose_information.h>
#include <vlo/core/se3_twist.h>

#include <cmath>

using namespace vlo;

namespace
{
Eigen::Isometry3d pose(const Eigen::Vector3d& p, const Eigen::Vector3d& rotation_vector)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(rotation_vector.norm(), rotation_vector.normalized()).toRotationMatrix();
	T.translation() = p;
	return T;
}

/// T perturbed by delta = [dp; dtheta]: [exp(dtheta) R, p + dp].
Eigen::Isometry3d perturbed(const Eigen::Isometry3d& T, const Vector6d& delta)
{
	Eigen::Isometry3d out = T;
	out.linear() = expTwist((Vector6d() << 0, 0, 0, delta.tail<3>()).finished()).linear() * T.linear();
	out.translation() += delta.head<3>();
	return out;
}

/// delta taking T to T2 (to first order).
Vector6d deltaBetween(const Eigen::Isometry3d& T, const Eigen::Isometry3d& T2)
{
	Vector6d d;
	d.head<3>() = T2.translation() - T.translation();
	const Eigen::AngleAxisd aa(T2.linear() * T.linear().transpose());
	d.tail<3>() = aa.angle() * aa.axis();
	return d;
}

Matrix6d diagonal(double a, double b, double c, double d, double e, double f)
{
	return (Eigen::Matrix<double, 6, 1>() << a, b, c, d, e, f).finished().asDiagonal();
}
}  // namespace

TEST(PoseInformation, RegistrationInformationIsThatOfAHundredPointsAtTheRms)
{
	const Matrix6d JtJ = diagonal(400, 400, 800, 4000, 4000, 8000);
	// 400 pairs at 5 cm: x 100 / 400 / 0.0025.
	EXPECT_NEAR(registrationInformation(JtJ, 400, 0.05)(0, 0), 400 * 100.0, 1e-6);
	EXPECT_NEAR(registrationInformation(JtJ, 400, 0.05)(5, 5), 8000 * 100.0, 1e-6);
	// Below 1 cm the rms counts as 1 cm; no pairs, no information.
	EXPECT_NEAR(registrationInformation(JtJ, 400, 0.001)(2, 2), 800 * 0.25 / 1e-4, 1e-3);
	EXPECT_EQ(registrationInformation(JtJ, 0, 0.05), Matrix6d::Zero());
}

TEST(PoseInformation, InvertingAnUnconstrainedDirectionGivesAHugeVariance)
{
	const Matrix6d cov = invertPositive(diagonal(0, 4, 4, 100, 100, 100));
	EXPECT_GT(cov(0, 0), 1e9);
	EXPECT_NEAR(cov(1, 1), 0.25, 1e-12);
	EXPECT_NEAR(cov(3, 3), 0.01, 1e-12);
	EXPECT_TRUE(invertPositive(invertPositive(diagonal(1, 2, 3, 4, 5, 6))).isApprox(diagonal(1, 2, 3, 4, 5, 6), 1e-12));
}

TEST(PoseInformation, CovariancesComposeAlongAStraightChainAsInClosedForm)
{
	// N steps of s along x, each with sigma_t in translation and sigma_r in rotation (isotropic): a
	// turn at step i swings the remaining (N - i) s, so across the way the variance is
	// N st^2 + sr^2 s^2 sum_{i=1..N} (N - i)^2 = N st^2 + sr^2 s^2 (N - 1) N (2N - 1) / 6.
	const int N = 7;
	const double s = 1.5, st = 0.02, sr = 0.003;
	const Eigen::Isometry3d step = pose({s, 0, 0}, {0, 0, 1e-12});
	const Matrix6d step_cov = diagonal(st * st, st * st, st * st, sr * sr, sr * sr, sr * sr);
	Matrix6d cov = Matrix6d::Zero();
	Eigen::Isometry3d chain = Eigen::Isometry3d::Identity();
	for (int i = 0; i < N; ++i)
	{
		cov = composeCovariance(cov, chain, step_cov, step);
		chain = chain * step;
	}
	const double across = N * st * st + sr * sr * s * s * (N - 1) * N * (2 * N - 1) / 6.0;
	EXPECT_NEAR(cov(0, 0), N * st * st, 1e-12);
	EXPECT_NEAR(cov(1, 1), across, 1e-12);
	EXPECT_NEAR(cov(2, 2), across, 1e-12);
	EXPECT_NEAR(cov(5, 5), N * sr * sr, 1e-12);
	// y and yaw: sum (N - i) s sr^2; z and pitch the opposite sign (a pitch up lowers what is ahead).
	EXPECT_NEAR(cov(1, 5), sr * sr * s * (N - 1) * N / 2.0, 1e-12);
	EXPECT_NEAR(cov(2, 4), -sr * sr * s * (N - 1) * N / 2.0, 1e-12);
}

TEST(PoseInformation, AMountTurnedAQuarterSwapsTheAxes)
{
	const Eigen::Isometry3d mount = pose({0, 0, 0}, {0, 0, M_PI / 2});
	const Matrix6d vehicle = vehicleMotionInformation(diagonal(1, 2, 3, 4, 5, 6), mount, pose({1, 0, 0}, {0, 0, 0.1}));
	EXPECT_TRUE(vehicle.isApprox(diagonal(2, 1, 3, 5, 4, 6), 1e-12)) << vehicle;
}

TEST(PoseInformation, TheSensorsYawIsTheVehiclesSidewaysMotionAtTheLeverArm)
{
	// The LiDAR L m ahead of and 1.7 m above the vehicle's origin, its yaw known to sr, all else to
	// 1 mm / 1 mrad: the vehicle's origin moves sideways by -L dyaw.
	const double L = 1.2, sr = 0.01;
	const Eigen::Isometry3d mount = pose({L, 0, 1.7}, {0, 0, 1e-12});
	const Matrix6d lidar = diagonal(1e6, 1e6, 1e6, 1e6, 1e6, 1 / (sr * sr));
	const Matrix6d cov = invertPositive(vehicleMotionInformation(lidar, mount, Eigen::Isometry3d::Identity()));
	EXPECT_NEAR(cov(1, 1), 1e-6 + L * L * sr * sr + 1.7 * 1.7 * 1e-6, 1e-12);  // and the roll at 1.7 m up
	EXPECT_NEAR(cov(1, 5), -L * sr * sr, 1e-12);
	EXPECT_NEAR(cov(5, 5), sr * sr, 1e-12);
	EXPECT_NEAR(cov(0, 0), 1e-6 + 1.7 * 1.7 * 1e-6, 1e-12);  // the pitch at 1.7 m up moves x as well
}

TEST(PoseInformation, ChangesOfFrameKeepTheCostOfAPerturbation)
{
	// The same small perturbation costs as much in either frame: delta_L^T I_L delta_L = delta_V^T I_V delta_V.
	const Eigen::Isometry3d mount = pose({0.8, -0.3, 1.7}, {0.02, -0.05, 1.3});
	const Eigen::Isometry3d lidar_motion = pose({1.1, 0.2, -0.05}, {0.01, 0.02, 0.15});
	const Eigen::Isometry3d previous = pose({30, -4, 2}, {0.1, -0.2, 2.0});
	Eigen::Matrix<double, 6, 6> M;
	M << 5, 1, 0, 0.5, 0, 0, 1, 4, 0, 0, 0.3, 0, 0, 0, 6, 0, 0, 0.2, 0.5, 0, 0, 90, 3, 0, 0, 0.3, 0, 3, 80, 0, 0, 0,
		0.2, 0, 0, 70;
	const Matrix6d information = M * M.transpose();
	const Vector6d delta = (Vector6d() << 1e-6, -2e-6, 1.5e-6, 3e-7, -1e-7, 2e-7).finished();
	const double cost = delta.dot(information * delta);

	const Eigen::Isometry3d vehicle_motion = mount * lidar_motion * mount.inverse();
	const Vector6d delta_vehicle =
		deltaBetween(vehicle_motion, mount * perturbed(lidar_motion, delta) * mount.inverse());
	const Matrix6d vehicle = vehicleMotionInformation(information, mount, vehicle_motion);
	EXPECT_NEAR(delta_vehicle.dot(vehicle * delta_vehicle) / cost, 1.0, 1e-4);

	// KISS-ICP's left twist turns about the world's origin.
	const Vector6d twist = delta;
	const Vector6d delta_of_twist = deltaBetween(previous, expTwist(twist) * previous);
	const Matrix6d from_twist = informationFromLeftTwist(information, previous.translation());
	EXPECT_NEAR(delta_of_twist.dot(from_twist * delta_of_twist) / cost, 1.0, 1e-4);

	// A perturbation of the pose in the world is one of the motion from `previous` in its axes.
	const Eigen::Isometry3d T = previous * lidar_motion;
	const Vector6d delta_relative = deltaBetween(lidar_motion, previous.inverse() * perturbed(T, delta));
	const Matrix6d relative = relativeInformation(information, previous);
	EXPECT_NEAR(delta_relative.dot(relative * delta_relative) / cost, 1.0, 1e-4);
}
