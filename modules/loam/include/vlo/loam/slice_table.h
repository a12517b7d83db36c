#pragma once
// std::lower_bound / std::upper_bound over a few ascending floats (beam bounds, ring elevations) for
// lookups made once per point: a table of slices over the values' span gives where to start, and a
// short walk forward the exact answer, with none of a binary search's mispredicted branches.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vlo::loam
{
class SliceTable
{
   public:
	SliceTable() = default;
	/// `ascending`: sorted, not necessarily distinct.
	explicit SliceTable(std::vector<float> ascending);

	/// Index of the first value >= x (std::lower_bound).
	std::size_t lowerBound(float x) const
	{
		std::size_t i = start(x);
		while (i < v_.size() && v_[i] < x) ++i;
		return i;
	}
	/// Index of the first value > x (std::upper_bound).
	std::size_t upperBound(float x) const
	{
		std::size_t i = start(x);
		while (i < v_.size() && v_[i] <= x) ++i;
		return i;
	}
	const std::vector<float>& values() const { return v_; }

   private:
	static constexpr int kSlices = 1024;
	/// A lower bound of lowerBound(x): the table's entry for x's slice (0 below the span or NaN).
	std::size_t start(float x) const
	{
		if (!(x > lo_) || first_.empty()) return 0;
		const float s = (x - lo_) * scale_;
		return first_[s < static_cast<float>(kSlices) ? static_cast<std::size_t>(s) : static_cast<std::size_t>(kSlices)];
	}

	std::vector<float> v_;
	float lo_ = 0, scale_ = 0;  ///< the smallest value; slices per unit
	std::vector<std::uint32_t> first_;  ///< per slice: lowerBound of a point a little before it
};
}  // namespace vlo::loam
