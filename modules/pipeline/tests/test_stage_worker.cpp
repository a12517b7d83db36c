// StageWorker: jobs in order beside the caller, an error rethrown where the caller starts or waits.
#include <gtest/gtest.h>
#include <vlo/pipeline/stage_worker.h>

#include <stdexcept>
#include <thread>
#include <vector>

using namespace vlo;
using namespace vlo::pipeline;

TEST(StageWorker, RunsEachJobOnceAndInOrderWithAndWithoutAThread)
{
	for (const bool threaded : {false, true})
	{
		std::vector<int> done;
		std::thread::id ranOn;
		StageWorker worker(threaded);
		for (int i = 0; i < 50; ++i)
		{
			worker.start([&done, &ranOn, i] {
				done.push_back(i);
				ranOn = std::this_thread::get_id();
			});
			worker.wait();
		}
		ASSERT_EQ(done.size(), 50u);
		for (int i = 0; i < 50; ++i) EXPECT_EQ(done[i], i);
		EXPECT_EQ(ranOn == std::this_thread::get_id(), !threaded);
	}
}

TEST(StageWorker, AJobsErrorComesOutOfWaitOnceAndTheWorkerGoesOn)
{
	StageWorker worker(true);
	worker.start([] { throw std::runtime_error("lidar failed"); });
	EXPECT_THROW(
		{
			try
			{
				worker.wait();
			}
			catch (const std::runtime_error& e)
			{
				EXPECT_STREQ(e.what(), "lidar failed");
				throw;
			}
		},
		std::runtime_error);
	EXPECT_NO_THROW(worker.wait());  // reported once
	int ran = 0;
	worker.start([&ran] { ran = 1; });
	worker.wait();
	EXPECT_EQ(ran, 1);
}

TEST(StageWorker, InlineTheErrorComesOutOfStart)
{
	StageWorker worker(false);
	EXPECT_THROW(worker.start([] { throw std::runtime_error("x"); }), std::runtime_error);
	EXPECT_NO_THROW(worker.wait());
}

TEST(StageWorker, DestroyingItWaitsForTheRunningJob)
{
	bool finished = false;
	{
		StageWorker worker(true);
		worker.start([&finished] {
			std::this_thread::sleep_for(std::chrono::milliseconds(50));
			finished = true;
		});
	}  // e.g. while another stage's exception unwinds: the job's data must outlive it
	EXPECT_TRUE(finished);
}

TEST(StageWorker, QueuedJobsRunInOrderAndAFailedOneDropsTheOnesAfterIt)
{
	std::vector<int> done;
	StageWorker worker(true, 3);
	worker.start([&done] {
		std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the next two queue meanwhile
		done.push_back(0);
	});
	worker.start([] { throw std::runtime_error("frame 1"); });
	worker.start([&done] { done.push_back(2); });
	EXPECT_THROW(worker.wait(), std::runtime_error);
	EXPECT_EQ(done, std::vector<int>{0});
	worker.start([&done] { done.push_back(3); });  // the error was reported: it goes on
	worker.wait();
	EXPECT_EQ(done, (std::vector<int>{0, 3}));
}
