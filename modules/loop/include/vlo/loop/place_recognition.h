#pragma once
// Place recognition: every keyframe's Scan Context in the order they come, and for each new one the
// most similar earlier place that the vehicle left long enough ago (min_revisit_path of odometry
// path): the `candidates` nearest ring keys (brute force, 20 numbers per keyframe), then the full
// descriptors of those.
#include <vlo/loop/keyframe.h>
#include <vlo/loop/scan_context.h>

#include <optional>
#include <vector>

namespace vlo::loop
{
struct PlaceCandidate
{
	std::size_t keyframe = 0;  ///< index in the database (the order of add)
	DescriptorMatch match;
};

struct PlaceRecognitionParams
{
	ScanContextParams descriptor;
	int candidates = 10;
	double max_distance = 0.25;
	double min_revisit_path = 50.0;
};

class PlaceDatabase
{
   public:
	explicit PlaceDatabase(const PlaceRecognitionParams& params) : params_(params) {}

	/// Adds the next keyframe (points in the vehicle frame, its odometry path) and returns the best
	/// earlier place under max_distance, if any.
	std::optional<PlaceCandidate> addAndQuery(const ScanPoints& points, double path);
	std::size_t size() const { return contexts_.size(); }

   private:
	PlaceRecognitionParams params_;
	std::vector<ScanContext> contexts_;
	std::vector<Eigen::VectorXd> keys_;
	std::vector<double> paths_;
};
}  // namespace vlo::loop
