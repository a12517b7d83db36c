#pragma once
// Monocular map initialisation: keeps a reference frame, matches each new frame against it, and
// once the two-view reconstruction succeeds builds a two-keyframe map, bundle-adjusts it and
// scales it to unit median depth. Every frame that does not initialise gets a reason.
#include <vlo/vo/map.h>
#include <vlo/vo/matcher.h>
#include <vlo/vo/two_view.h>

#include <memory>
#include <optional>
#include <string>

namespace vlo::vo
{
struct InitResult
{
	bool ok = false;
	std::string reason;  ///< why not yet
	int matches = 0;  ///< with the reference frame
	std::unique_ptr<Map> map;
	KeyFrame* first = nullptr;  ///< the reference frame, at the map origin
	KeyFrame* second = nullptr;  ///< the frame fed last
};

class MapInitializer
{
   public:
	MapInitializer(const PinholeCamera& cam, const ScalePyramid& pyr, const InitOptions& opt,
		const TrackingOptions& topt, const MappingOptions& mopt);

	/// Feeds a frame (features only). On success the map is returned and the reference dropped.
	InitResult feed(const TrackedFrame& f);
	void reset() { ref_.reset(); }
	bool hasReference() const { return ref_.has_value(); }

   private:
	void setReference(const TrackedFrame& f);
	InitResult buildMap(const TrackedFrame& cur, const TwoViewResult& tv, const std::vector<int>& m12,
		const std::vector<std::size_t>& pair_of);

	const PinholeCamera& cam_;
	const ScalePyramid& pyr_;
	const InitOptions& opt_;
	const MappingOptions& mopt_;
	MatchContext ctx_;
	std::optional<TrackedFrame> ref_;
	std::vector<Vec2> prev_;  ///< last matched position of each reference keypoint
};
}  // namespace vlo::vo
