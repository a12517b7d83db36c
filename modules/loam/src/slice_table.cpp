#include <vlo/loam/slice_table.h>

#include <algorithm>

namespace vlo::loam
{
SliceTable::SliceTable(std::vector<float> ascending) : v_(std::move(ascending))
{
	if (v_.size() < 2 || !(v_.back() > v_.front())) return;  // nothing to slice: start at 0
	lo_ = v_.front();
	scale_ = static_cast<float>(kSlices) / (v_.back() - lo_);
	// Each slice starts a thousandth of a slice early, far more than the rounding of a query's slice
	// index, so start(x) never passes lowerBound(x).
	first_.resize(kSlices + 1);
	for (int s = 0; s <= kSlices; ++s)
	{
		const float at = lo_ + (static_cast<float>(s) - 1e-3f) / scale_;
		first_[static_cast<std::size_t>(s)] = static_cast<std::uint32_t>(std::lower_bound(v_.begin(), v_.end(), at) - v_.begin());
	}
}
}  // namespace vlo::loam
