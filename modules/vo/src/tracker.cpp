#include <vlo/vo/optimizer.h>
#include <vlo/vo/tracker.h>

#include <algorithm>
#include <unordered_map>

namespace vlo::vo
{
Tracker::Tracker(const PinholeCamera& cam, const ScalePyramid& pyr, const TrackingOptions& opt)
	: cam_(cam), pyr_(pyr), opt_(opt), ctx_{cam, pyr, opt}
{
}

int Tracker::optimizeAndClean(TrackedFrame& cur)
{
	optimizePose(cur, cam_, pyr_, opt_.pose_rounds, opt_.pose_iterations, opt_.chi2);
	int n = 0;
	for (std::size_t i = 0; i < cur.size(); ++i)
	{
		if (!cur.points[i]) continue;
		if (cur.outlier[i])
		{
			cur.points[i] = nullptr;
			cur.outlier[i] = 0;
		}
		else if (cur.points[i]->numObservations() > 0)
			++n;
	}
	return n;
}

bool Tracker::withMotionModel(TrackedFrame& cur, const TrackedFrame& last, const SE3& velocity, std::string& why)
{
	cur.Tcw = velocity * last.Tcw;
	cur.clearMatches();
	int n = searchByProjection(cur, last, opt_.motion_radius, ctx_);
	if (n < opt_.min_motion_matches)
	{
		cur.clearMatches();
		n = searchByProjection(cur, last, 2 * opt_.motion_radius, ctx_);
	}
	if (n < opt_.min_motion_matches)
	{
		why = "motion model: " + std::to_string(n) + " matches";
		return false;
	}
	const int inl = optimizeAndClean(cur);
	if (inl < opt_.min_pose_inliers) why = "motion model: " + std::to_string(inl) + " inliers";
	return inl >= opt_.min_pose_inliers;
}

bool Tracker::withReferenceKeyFrame(TrackedFrame& cur, KeyFrame* ref, const SE3& start, std::string& why)
{
	cur.clearMatches();
	cur.Tcw = start;
	const int n = searchKeyFrame(*ref, cur, &start, ctx_);
	if (n < opt_.min_reference_matches)
	{
		why += std::string(why.empty() ? "" : "; ") + "reference keyframe: " + std::to_string(n) + " matches";
		return false;
	}
	const int inl = optimizeAndClean(cur);
	if (inl < opt_.min_pose_inliers)
		why += std::string(why.empty() ? "" : "; ") + "reference keyframe: " + std::to_string(inl) + " inliers";
	return inl >= opt_.min_pose_inliers;
}

void Tracker::updateLocalMap(TrackedFrame& cur)
{
	// Keyframes that see the frame's points, by number of shared points (ties by id).
	std::unordered_map<KeyFrame*, int> votes;
	for (MapPoint* mp : cur.points)
		if (mp && !mp->bad)
			for (const auto& o : mp->observations()) ++votes[o.kf];
	std::vector<std::pair<KeyFrame*, int>> v(votes.begin(), votes.end());
	std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first->id < b.first->id; });
	local_kfs_.clear();
	KeyFrame* best = nullptr;
	int best_votes = 0;
	for (const auto& [kf, n] : v)
	{
		if (kf->bad) continue;
		local_kfs_.push_back(kf);
		kf->mark_local = cur.index;
		if (n > best_votes) best = kf, best_votes = n;
	}
	// Plus one unseen neighbour of each, as ORB-SLAM, up to the cap.
	for (std::size_t i = 0, n0 = local_kfs_.size(); i < n0 && static_cast<int>(local_kfs_.size()) < opt_.max_local_keyframes; ++i)
		for (KeyFrame* nb : local_kfs_[i]->bestCovisibles(10))
			if (nb->mark_local != cur.index)
			{
				nb->mark_local = cur.index;
				local_kfs_.push_back(nb);
				break;
			}
	if (static_cast<int>(local_kfs_.size()) > opt_.max_local_keyframes) local_kfs_.resize(static_cast<std::size_t>(opt_.max_local_keyframes));
	if (best) cur.ref_kf = best;

	local_points_.clear();
	for (KeyFrame* kf : local_kfs_)
		for (MapPoint* mp : kf->points)
			if (mp && !mp->bad && mp->mark_local != cur.index)
			{
				mp->mark_local = cur.index;
				local_points_.push_back(mp);
			}
}

int Tracker::withLocalMap(TrackedFrame& cur)
{
	updateLocalMap(cur);
	for (MapPoint* mp : cur.points)
		if (mp && !mp->bad)
		{
			++mp->visible;
			mp->mark_seen = cur.index;
		}
	searchLocalPoints(cur, local_points_, ctx_);
	optimizePose(cur, cam_, pyr_, opt_.pose_rounds, opt_.pose_iterations, opt_.chi2);
	int inliers = 0;
	for (std::size_t i = 0; i < cur.size(); ++i)
	{
		MapPoint* mp = cur.points[i];
		if (!mp) continue;
		if (cur.outlier[i])
		{
			cur.points[i] = nullptr;
			cur.outlier[i] = 0;
			continue;
		}
		++mp->found;
		if (mp->numObservations() > 0) ++inliers;
	}
	return inliers;
}

bool Tracker::needKeyFrame(int inliers, const KeyFrame* ref, long frames_since_keyframe, std::size_t n_keyframes) const
{
	if (!ref || frames_since_keyframe < opt_.min_frames_between_keyframes) return false;
	const int min_obs = n_keyframes <= 2 ? 2 : 3;
	const int ref_matches = ref->trackedPoints(min_obs);
	// ORB-SLAM: (c1a: max frames passed || c1b: min frames passed and local mapping idle) && c2.
	// Inline local mapping is always idle, so c1b holds once the minimum has passed (checked above).
	// Plus: a frame close to the loss threshold needs new points, whatever its reference tracks.
	const bool weak = inliers < opt_.keyframe_weak_inliers;
	return (inliers < opt_.keyframe_ref_ratio * ref_matches || weak) && inliers > opt_.keyframe_min_inliers;
}
}  // namespace vlo::vo
