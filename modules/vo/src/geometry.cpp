#include <vlo/vo/geometry.h>

namespace vlo::vo
{
Mat3 skew(const Vec3& v)
{
	Mat3 S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}

SE3 makeSE3(const Mat3& R, const Vec3& t)
{
	SE3 T = SE3::Identity();
	T.linear() = R;
	T.translation() = t;
	return T;
}

Mat3 fundamentalBetween(const SE3& T1w, const SE3& T2w, const PinholeCamera& c)
{
	// Pose of camera 2 in camera 1: X1 = R12 X2 + t12, so E12 = [t12]x R12 and x1^T E12 x2 = 0.
	const SE3 T12 = T1w * T2w.inverse();
	const Mat3 E12 = skew(T12.translation()) * T12.linear();
	const Mat3 Kinv = c.K().inverse();
	return Kinv.transpose() * E12 * Kinv;
}
}  // namespace vlo::vo
