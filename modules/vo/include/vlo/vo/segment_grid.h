#pragma once
// Items bucketed by image cell and queried along a line segment widened by a band: the candidates of
// an epipolar search without testing every keypoint of the image against every line.
#include <vlo/vo/geometry.h>

#include <vector>

namespace vlo::vo
{
class SegmentGrid
{
   public:
	SegmentGrid(int width, int height, double cell);
	void add(double x, double y, int item);
	/// Calls fn(item) for every item within distance `band` of the segment p-q, and for others of the
	/// same cells (the caller tests exactly); each once, in no particular order.
	template <class Fn>
	void forEachNear(const Vec2& p, const Vec2& q, double band, Fn&& fn)
	{
		markCells(p, q, band);
		for (int c : marked_)
			for (int item : items_[static_cast<std::size_t>(c)]) fn(item);
	}

   private:
	void markCells(const Vec2& p, const Vec2& q, double band);
	double cell_;
	int cols_, rows_;
	std::vector<std::vector<int>> items_;
	std::vector<int> marked_;  ///< cells of the last query
};
}  // namespace vlo::vo
