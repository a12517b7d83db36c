// PLACEHOLDER (branch loop-api only): the odometry passed through, replaced by the loop-core branch.
#include <vlo/loop/loop_closure.h>

namespace vlo::loop
{
struct LoopClosure::Impl
{
	Trajectory odometry;
	std::vector<LoopRecord> loops;
};

LoopClosure::LoopClosure(const LoopOptions&) : impl_(std::make_unique<Impl>()) {}
LoopClosure::~LoopClosure() = default;

void LoopClosure::addFrame(long long, double t, const Eigen::Isometry3d& world_T_vehicle, const PointCloud&, const Eigen::Isometry3d&)
{
	impl_->odometry.push_back({t, world_T_vehicle});
}

void LoopClosure::finish() {}
Trajectory LoopClosure::corrected() const { return impl_->odometry; }
const std::vector<LoopRecord>& LoopClosure::loops() const { return impl_->loops; }
std::size_t LoopClosure::keyframes() const { return 0; }
double LoopClosure::finalOptimisationSeconds() const { return 0; }
}  // namespace vlo::loop
