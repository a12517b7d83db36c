#pragma once
// Place recognition: every keyframe's Scan Context in the order they come, and for each new one the
// most similar earlier place that the vehicle left long enough ago (min_revisit_path of odometry
// path): the `candidates` nearest ring keys (brute force, 20 numbers per keyframe), then the full
// descriptors of those. Scan Context's bins move with a lateral offset: a revisit in another lane,
// above all the other way round, is not found. With `query_shift` each keyframe is also queried with
// its descriptors seen from `query_shift` to its left and to its right (only its own is stored): the
// best of the three queries is the candidate, its viewpoint part of the registration's first guess.
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
	double query_shift = 0;  ///< [m] also query from this far to the left and right; 0 = off
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
	/// The best of the `candidates` nearest ring keys among the first `eligible` places.
	std::optional<PlaceCandidate> query(const ScanContext& sc, std::size_t eligible) const;

	PlaceRecognitionParams params_;
	std::vector<ScanContext> contexts_;
	std::vector<Eigen::VectorXd> keys_;
	std::vector<double> paths_;
};
}  // namespace vlo::loop
