#pragma once
// Items offered at a steady rate over a run of any length (snapshot frames every N frames), of which at
// most `capacity` are kept, spread evenly from start to end: when full, every other one goes and only
// every other later offer is taken. Memory stays bounded however long the run.
#include <cstddef>
#include <utility>
#include <vector>

namespace vlo
{
template <class T>
class BoundedSample
{
   public:
	explicit BoundedSample(std::size_t capacity) : capacity_(capacity < 2 ? 2 : capacity) {}

	/// Keeps `item` when it falls on the current stride; returns whether it was kept.
	bool offer(T item)
	{
		if (offered_++ % stride_ != 0) return false;
		if (items_.size() == capacity_)
		{
			std::size_t kept = 0;
			for (std::size_t i = 0; i < items_.size(); i += 2) items_[kept++] = std::move(items_[i]);
			items_.resize(kept);
			stride_ *= 2;
			if ((offered_ - 1) % stride_ != 0) return false;
		}
		items_.push_back(std::move(item));
		return true;
	}
	const std::vector<T>& items() const { return items_; }
	/// How many offers lie between two kept items (1 until the first thinning).
	std::size_t stride() const { return stride_; }

   private:
	std::size_t capacity_, stride_ = 1, offered_ = 0;
	std::vector<T> items_;
};
}  // namespace vlo
