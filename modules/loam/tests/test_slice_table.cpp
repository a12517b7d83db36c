// SliceTable against std::lower_bound and std::upper_bound: at every value and its float neighbours,
// in a dense sweep beyond both ends, with repeated values, and for tables too small to slice.
#include <gtest/gtest.h>
#include <vlo/loam/slice_table.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vlo::loam::test
{
namespace
{
void expectSearchEverywhere(const std::vector<float>& v)
{
	const SliceTable t(v);
	std::vector<float> xs;
	for (float x : v)
	{
		for (int i = 0; i < 3; ++i) x = std::nextafter(x, -10.0f);
		for (int i = 0; i < 7; ++i, x = std::nextafter(x, 10.0f)) xs.push_back(x);
	}
	for (int i = 0; i <= 100000; ++i) xs.push_back(-1.5f + 3.0f * static_cast<float>(i) / 100000.0f);
	for (float x : xs)
	{
		ASSERT_EQ(t.lowerBound(x), static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin())) << x;
		ASSERT_EQ(t.upperBound(x), static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), x) - v.begin())) << x;
	}
}
}  // namespace

TEST(SliceTable, AgreesWithTheSearchEverywhere)
{
	// HDL-64-like ring elevations [rad]: 32 beams 1/3 deg apart, 32 half a degree apart.
	std::vector<float> hdl64;
	for (int k = 0; k < 32; ++k) hdl64.push_back(static_cast<float>((-24.33 + 0.5 * k) * M_PI / 180));
	for (int k = 0; k < 32; ++k) hdl64.push_back(static_cast<float>((-8.33 + k / 3.0) * M_PI / 180));
	expectSearchEverywhere(hdl64);
	expectSearchEverywhere({-0.26f, -0.2f, -0.2f, -0.2f, 0.0f, 0.0f, 0.25f});  // repeated values
	expectSearchEverywhere({-0.3f, 0.0f, 1e-6f, 0.3f});  // two values far closer than a slice
	expectSearchEverywhere({0.1f, 0.1f});  // no span to slice
	expectSearchEverywhere({0.1f});
	expectSearchEverywhere({});
}
}  // namespace vlo::loam::test
