// FramePrefetcher: the same frames, statistics and errors as reading on the caller's thread.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/pipeline/frame_prefetcher.h>

#include <filesystem>
#include <string>
#include <vector>

#include "small_drive.h"

using namespace vlo;
using namespace vlo::pipeline;

namespace
{
constexpr int kFrames = 7;

class Prefetcher : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		dir_ = std::filesystem::absolute(std::string("prefetch_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
		std::filesystem::remove_all(dir_);
		std::filesystem::create_directories(dir_);
		test::writeSmallDrive(path(), kFrames, test::smallRig());
	}
	void TearDown() override { std::filesystem::remove_all(dir_); }
	std::string path() const { return dir_ + "/drive.rawlog"; }

	/// (index, scan's first x, image's first pixel) of each frame read; the reader's observation count.
	struct Read
	{
		std::vector<std::tuple<std::size_t, float, int>> frames;
		std::size_t observations = 0;
		std::string error;
	};
	static Read readAll(const std::string& file, std::size_t ahead, std::size_t limit)
	{
		Read r;
		io::RawlogReader reader(file);
		try
		{
			FramePrefetcher frames(reader, ahead, limit);
			for (ReadFrame f; frames.next(f);)
				r.frames.emplace_back(f.frame.index, f.frame.scan.at(0).x, int(f.frame.image.at<std::uint8_t>(0, 0)));
			frames.stop();
		}
		catch (const InputError& e)
		{
			r.error = e.what();
		}
		r.observations = reader.stats().observations;
		return r;
	}
	std::string dir_;
};
}  // namespace

TEST_F(Prefetcher, ReadsTheSameFramesAsTheCallersThread)
{
	for (const std::size_t limit : {0, 3})
	{
		const Read direct = readAll(path(), 0, limit);
		ASSERT_EQ(direct.frames.size(), limit == 0 ? std::size_t(kFrames) : limit);
		for (std::size_t i = 0; i < direct.frames.size(); ++i)
		{
			EXPECT_EQ(std::get<0>(direct.frames[i]), i);
			EXPECT_FLOAT_EQ(std::get<1>(direct.frames[i]), 5.f + float(i));
			EXPECT_EQ(std::get<2>(direct.frames[i]), 10 * int(i));
		}
		for (const std::size_t ahead : {1, 2, 5})
		{
			const Read pre = readAll(path(), ahead, limit);
			EXPECT_EQ(pre.frames, direct.frames) << ahead;
			// Nothing past the limit is read: the statistics of summary.json do not depend on the threads.
			EXPECT_EQ(pre.observations, direct.observations) << ahead;
		}
	}
}

TEST_F(Prefetcher, AReadErrorComesAfterTheFramesBeforeIt)
{
	const std::string cut = dir_ + "/cut.rawlog";
	std::filesystem::copy_file(path(), cut);
	std::filesystem::resize_file(cut, std::filesystem::file_size(path()) * 2 / 3);
	const Read direct = readAll(cut, 0, 0);
	ASSERT_FALSE(direct.error.empty());
	ASSERT_GT(direct.frames.size(), 0u);
	const Read pre = readAll(cut, 2, 0);
	EXPECT_EQ(pre.frames, direct.frames);
	EXPECT_EQ(pre.error, direct.error);
}

TEST_F(Prefetcher, StoppingEarlyEndsTheReaderThread)
{
	io::RawlogReader reader(path());
	FramePrefetcher frames(reader, 1, 0);
	ReadFrame f;
	ASSERT_TRUE(frames.next(f));
	frames.stop();  // the thread waits for room in the queue: stop must not hang
	EXPECT_LE(reader.stats().frames, 3u);
}
