// The epipolar search's candidate grid: every item within the band of a segment is returned, and
// far fewer than all of them.
#include <gtest/gtest.h>
#include <vlo/vo/segment_grid.h>

#include <algorithm>
#include <random>

using namespace vlo::vo;

namespace
{
double distanceToSegment(const Vec2& x, const Vec2& p, const Vec2& q)
{
	const Vec2 d = q - p;
	const double u = d.squaredNorm() > 0 ? std::clamp((x - p).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
	return (x - (p + u * d)).norm();
}
}  // namespace

TEST(SegmentGrid, VisitsEveryItemWithinTheBandOnce)
{
	const int W = 1241, H = 376;
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> ux(0, W), uy(0, H), far(-3000, 3000);
	std::vector<Vec2> pts;
	SegmentGrid grid(W, H, 32.0);
	for (int i = 0; i < 3000; ++i)
	{
		pts.emplace_back(ux(rng), uy(rng));
		grid.add(pts.back().x(), pts.back().y(), i);
	}
	std::vector<int> got;
	std::size_t returned = 0, within = 0;
	for (int trial = 0; trial < 300; ++trial)
	{
		// Segments inside, crossing and far outside the image, and degenerate ones.
		const Vec2 p(far(rng), far(rng));
		const Vec2 q = trial % 10 == 0 ? p : Vec2(ux(rng), uy(rng));
		const double band = trial % 3 == 0 ? 1.5 : 7.2;
		got.clear();
		grid.forEachNear(p, q, band, [&](int i) { got.push_back(i); });
		std::sort(got.begin(), got.end());
		EXPECT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end()) << "an item twice";
		returned += got.size();
		for (int i = 0; i < 3000; ++i)
			if (distanceToSegment(pts[std::size_t(i)], p, q) <= band)
			{
				++within;
				EXPECT_TRUE(std::binary_search(got.begin(), got.end(), i)) << "trial " << trial << " item " << i;
			}
	}
	EXPECT_GT(within, 1000u);
	EXPECT_LT(returned, 300u * 3000u / 10);  // the point of the grid
}

TEST(SegmentGrid, SegmentOutsideTheImageFindsNothing)
{
	SegmentGrid grid(640, 480, 32.0);
	grid.add(10, 10, 0);
	std::vector<int> got;
	const auto collect = [&](int i) { got.push_back(i); };
	grid.forEachNear(Vec2(-100, -100), Vec2(-100, 900), 5.0, collect);
	EXPECT_TRUE(got.empty());
	grid.forEachNear(Vec2(-100, 12), Vec2(900, 12), 5.0, collect);
	EXPECT_EQ(got, std::vector<int>{0});
}
