#include <vlo/pipeline/visual_odometry_module.h>

namespace vlo
{
std::unique_ptr<VisualOdometryModule> makeOrbVisualOdometry();  // orb_vo_module.cpp

Registry<VisualOdometryModule>& visualOdometryRegistry()
{
	// Visual odometry modules register here.
	static Registry<VisualOdometryModule> registry = [] {
		Registry<VisualOdometryModule> r;
		r.add("orb", makeOrbVisualOdometry);
		return r;
	}();
	return registry;
}
}  // namespace vlo
