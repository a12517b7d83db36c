#include <vlo/vo/features.h>

#include <algorithm>
#include <cmath>

namespace vlo::vo
{
ScalePyramid::ScalePyramid(int n, double f) : levels(n), factor(f), log_factor(std::log(f))
{
	scale.resize(n);
	inv_scale.resize(n);
	sigma2.resize(n);
	inv_sigma2.resize(n);
	for (int l = 0; l < n; ++l)
	{
		scale[l] = std::pow(f, l);
		inv_scale[l] = 1.0 / scale[l];
		sigma2[l] = scale[l] * scale[l];
		inv_sigma2[l] = 1.0 / sigma2[l];
	}
}

int ScalePyramid::predictLevel(double max_dist, double dist) const
{
	const int l = static_cast<int>(std::ceil(std::log(max_dist / dist) / log_factor));
	return std::clamp(l, 0, levels - 1);
}

void FeatureGrid::build(const std::vector<cv::KeyPoint>& keys, int width, int height, int cell)
{
	cell_ = cell;
	cols_ = std::max(1, (width + cell - 1) / cell);
	rows_ = std::max(1, (height + cell - 1) / cell);
	cells_.assign(static_cast<std::size_t>(cols_ * rows_), {});
	pts_.resize(keys.size());
	levels_.resize(keys.size());
	for (std::size_t i = 0; i < keys.size(); ++i)
	{
		pts_[i] = keys[i].pt;
		levels_[i] = keys[i].octave;
		const int cx = std::clamp(static_cast<int>(keys[i].pt.x) / cell, 0, cols_ - 1);
		const int cy = std::clamp(static_cast<int>(keys[i].pt.y) / cell, 0, rows_ - 1);
		cells_[cy * cols_ + cx].push_back(static_cast<int>(i));
	}
}

std::vector<int> FeatureGrid::inArea(double x, double y, double r, int min_level, int max_level) const
{
	std::vector<int> out;
	if (cells_.empty()) return out;
	const int c0 = std::max(0, static_cast<int>(std::floor((x - r) / cell_)));
	const int c1 = std::min(cols_ - 1, static_cast<int>(std::floor((x + r) / cell_)));
	const int r0 = std::max(0, static_cast<int>(std::floor((y - r) / cell_)));
	const int r1 = std::min(rows_ - 1, static_cast<int>(std::floor((y + r) / cell_)));
	for (int cy = r0; cy <= r1; ++cy)
		for (int cx = c0; cx <= c1; ++cx)
			for (int i : cells_[cy * cols_ + cx])
			{
				if (levels_[i] < min_level || (max_level >= 0 && levels_[i] > max_level)) continue;
				if (std::abs(pts_[i].x - x) <= r && std::abs(pts_[i].y - y) <= r) out.push_back(i);
			}
	return out;
}
}  // namespace vlo::vo
