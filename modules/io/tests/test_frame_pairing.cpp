// Pairing of camera and LiDAR observations by timestamp: the decision rule and the reader's use of it.
#include "io_test_util.h"

#include <vlo/io/frame_pairing.h>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

TEST(FramePairing, DecisionRule)
{
	using Q = std::deque<double>;
	EXPECT_EQ(pairStep({}, {}, 0.05, false), PairStep::NeedMore);
	EXPECT_EQ(pairStep({}, {}, 0.05, true), PairStep::Done);
	EXPECT_EQ(pairStep(Q{1.0}, {}, 0.05, false), PairStep::NeedMore);
	EXPECT_EQ(pairStep(Q{1.0}, {}, 0.05, true), PairStep::SkipImage);
	EXPECT_EQ(pairStep(Q{1.0}, Q{0.9}, 0.05, false), PairStep::SkipScan);
	EXPECT_EQ(pairStep(Q{0.9}, Q{1.0}, 0.05, false), PairStep::SkipImage);
	EXPECT_EQ(pairStep(Q{1.0}, Q{1.02}, 0.05, false), PairStep::NeedMore);  // next image may be nearer
	EXPECT_EQ(pairStep(Q{1.0, 1.1}, Q{1.02}, 0.05, false), PairStep::Pair);
	EXPECT_EQ(pairStep(Q{1.0, 1.03}, Q{1.02}, 0.05, false), PairStep::SkipImage);
	EXPECT_EQ(pairStep(Q{1.02}, Q{1.0, 1.03}, 0.05, false), PairStep::SkipScan);
	EXPECT_EQ(pairStep(Q{1.0}, Q{1.02}, 0.05, true), PairStep::Pair);
	EXPECT_EQ(pairStep(Q{1.0}, Q{1.0}, 0.0, true), PairStep::Pair);
}

TEST(RawlogReader, PairsByNearestTimeWithinTolerance)
{
	const std::string path = freshDir() + "/p.rawlog";
	// 0.00/0.01 pair; 0.10 image has no scan within 0.05; 0.30 and 0.32 images compete for the
	// 0.33 scan: the nearer (0.32) wins; the 0.60 scan has no image.
	writeStreams(path, {0.0, 0.10, 0.30, 0.32}, {0.01, 0.33, 0.60});
	RawlogStats stats;
	const auto frames = readFrames(path, {}, &stats);
	ASSERT_EQ(frames.size(), 2u);
	EXPECT_NEAR(frames[0].t, 0.0, 1e-9);
	EXPECT_NEAR(frames[1].t, 0.32, 1e-9);  // a pair takes the image's time
	EXPECT_EQ(stats.unpaired_images, 2u);
	EXPECT_EQ(stats.unpaired_scans, 1u);
	EXPECT_EQ(stats.observations, 7u);
}

TEST(RawlogReader, ToleranceDecidesWhatPairs)
{
	const std::string path = freshDir() + "/t.rawlog";
	writeStreams(path, {0.0, 0.5}, {0.08, 0.54});
	RawlogStats stats;
	RawlogReaderOptions opt;
	EXPECT_EQ(readFrames(path, opt, &stats).size(), 1u);  // 0.08 s apart > 0.05 s default
	EXPECT_EQ(stats.unpaired_images, 1u);
	EXPECT_EQ(stats.unpaired_scans, 1u);
	opt.max_time_diff = 0.1;
	EXPECT_EQ(readFrames(path, opt, &stats).size(), 2u);
	EXPECT_EQ(stats.unpaired_images + stats.unpaired_scans, 0u);
	opt.max_time_diff = 0.01;  // nothing pairs: a clear error rather than an empty run
	expectInputError([&] { readFrames(path, opt); }, {path, "no frames", "2 images and 2 scans"});
}

TEST(RawlogReader, PairsStreamsThatLagInFileOrder)
{
	// Scans written 5 frames after their images (a logger with a LiDAR queue): still all paired,
	// as long as the lag stays under max_pending observations.
	const std::string path = freshDir() + "/lag.rawlog";
	{
		RawlogWriter w(path, false);
		for (std::size_t k = 0; k < 35; ++k)
		{
			if (k < 30)
			{
				Frame f = testFrame(k, 0.1 * k);
				f.has_scan = false;
				w.writeFrame(f);
			}
			if (k >= 5)
			{
				Frame f = testFrame(k - 5, 0.1 * (k - 5) + 0.01);
				f.has_image = false;
				w.writeFrame(f);
			}
		}
		w.commit();
	}
	RawlogStats stats;
	EXPECT_EQ(readFrames(path, {}, &stats).size(), 30u);
	EXPECT_EQ(stats.unpaired_images + stats.unpaired_scans, 0u);
	RawlogReaderOptions short_queue;
	short_queue.max_pending = 3;  // too short for this lag: images are given up, reported as such
	const auto frames = readFrames(path, short_queue, &stats);
	EXPECT_LT(frames.size(), 30u);
	EXPECT_EQ(frames.size() + stats.unpaired_images, 30u);
}
