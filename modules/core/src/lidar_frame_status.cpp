#include <vlo/core/lidar_frame_status.h>

namespace vlo
{
const char* toString(LidarFrameStatus s)
{
	switch (s)
	{
		case LidarFrameStatus::Ok: return "ok";
		case LidarFrameStatus::Initialized: return "initialized";
		case LidarFrameStatus::Degraded: return "degraded";
		case LidarFrameStatus::Skipped: return "skipped";
	}
	return "?";
}
}  // namespace vlo
