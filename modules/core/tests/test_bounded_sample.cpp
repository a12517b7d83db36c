#include <gtest/gtest.h>
#include <vlo/core/bounded_sample.h>

using vlo::BoundedSample;

// 1000 offers into 16 places: at most 16 kept at any time, evenly spread over the whole run.
TEST(BoundedSample, StaysWithinCapacityAndSpreadsOverTheRun)
{
	BoundedSample<int> s(16);
	std::size_t most = 0;
	for (int i = 0; i < 1000; ++i)
	{
		s.offer(i);
		most = std::max(most, s.items().size());
	}
	EXPECT_EQ(most, 16u);
	const auto& v = s.items();
	ASSERT_GE(v.size(), 8u);
	EXPECT_EQ(v.front(), 0);
	EXPECT_EQ(s.stride(), 64u);  // 16 places, 1000 offers: 1000 / 64 = 15.6
	for (std::size_t k = 1; k < v.size(); ++k) EXPECT_EQ(v[k] - v[k - 1], 64);
	EXPECT_GE(v.back(), 1000 - 64);
}

TEST(BoundedSample, ShortRunKeepsEverything)
{
	BoundedSample<int> s(16);
	for (int i = 0; i < 16; ++i) EXPECT_TRUE(s.offer(i));
	EXPECT_EQ(s.items().size(), 16u);
	EXPECT_EQ(s.stride(), 1u);
}
