#include <vlo/core/frame.h>

namespace vlo
{
Eigen::Matrix3d PinholeCamera::K() const
{
	Eigen::Matrix3d k;
	k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
	return k;
}
}  // namespace vlo
