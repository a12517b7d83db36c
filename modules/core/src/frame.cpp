#include <vlo/core/frame.h>

namespace vlo
{
Eigen::Matrix3d PinholeCamera::K() const
{
	Eigen::Matrix3d k;
	k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
	return k;
}

bool PinholeCamera::distorted() const
{
	if (distortion == mrpt::img::DistortionModel::none) return false;
	for (double d : dist)
		if (d != 0.0) return true;
	return false;
}
}  // namespace vlo
