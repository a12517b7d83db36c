#include <vlo/pipeline/visual_odometry_module.h>

namespace vlo
{
Registry<VisualOdometryModule>& visualOdometryRegistry()
{
	// Visual odometry modules register here (none is built yet).
	static Registry<VisualOdometryModule> registry;
	return registry;
}
}  // namespace vlo
