// The seeded mutation loop: every reader gets its real seed files and thousands of mutations of them
// (same seed, same inputs, every run). Each input must read, or fail with one InputError line naming
// the file. A failing input is kept as <build>/fuzz_work/<target>/failure-N for replay.
#include "mutator.h"
#include "seeds.h"
#include "targets.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

using namespace vlo::fuzz;
namespace fs = std::filesystem;

namespace
{
/// Inputs per target: enough to hit every header and count of the small seeds in a few seconds.
/// VLO_FUZZ_INPUTS=N sets another number (for long runs, or fewer under the sanitizers).
std::size_t inputsFor(const std::string& target)
{
	if (const char* n = std::getenv("VLO_FUZZ_INPUTS")) return std::strtoul(n, nullptr, 10);
	if (target == "rawlog") return 3000;
	if (target == "rawlog_velodyne") return 1000;  // each input decodes Velodyne packets
	if (target == "rosbag") return 2000;  // each input that reads is imported and read back
	return 5000;
}

class Fuzz : public ::testing::TestWithParam<std::string>
{
};

std::vector<Target> allTargets()
{
	auto all = ioTargets();
	all.push_back(iniTarget());
	all.push_back(rosbagTarget());
	return all;
}

TEST_P(Fuzz, EveryInputReadsOrFailsWithOneLineNamingTheFile)
{
	const auto all = allTargets();
	const Target& t = findTarget(all, GetParam());
	const std::string work = fs::path(VLO_BIN_DIR).parent_path().string() + "/test_data";
	const auto seeds = t.name == "rosbag" ? rosbagSeeds(work) : seedsOf(t.name, work);
	ASSERT_FALSE(seeds.empty());
	const fs::path dir = fs::path(VLO_BIN_DIR).parent_path() / "fuzz_work" / t.name;
	fs::remove_all(dir);
	fs::create_directories(dir);
	for (const auto& seed : seeds)  // the unmutated seeds must read: else the mutations test only the first check
	{
		std::ofstream(dir / t.file_name, std::ios::binary) << seed;
		EXPECT_NO_THROW(t.read((dir / t.file_name).string())) << t.name << " seed of " << seed.size() << " bytes";
	}
	Mutator mutator(std::hash<std::string>{}(t.name));
	const std::size_t n = inputsFor(t.name);
	std::size_t failures = 0;
	for (std::size_t i = 0; i < n && failures < 5; ++i)
	{
		const std::string input = mutator.mutate(seeds[i % seeds.size()]);
		const std::string failure = runOne(t, dir.string(), input);
		if (failure.empty()) continue;
		const fs::path kept = dir / ("failure-" + std::to_string(i));
		std::ofstream(kept, std::ios::binary) << input;
		ADD_FAILURE() << t.name << " input " << i << " (kept as " << kept.string() << "): " << failure;
		++failures;
	}
	std::cout << t.name << ": " << n << " mutated inputs, " << failures << " failures\n";
}

INSTANTIATE_TEST_SUITE_P(Readers, Fuzz,
	::testing::Values("rawlog", "rawlog_velodyne", "kitti_calib", "kitti_raw_calib", "kitti_times",
		"kitti_raw_timestamps", "kitti_poses", "kitti_bin", "tum", "ini", "rosbag"),
	[](const auto& info) { return info.param; });
}  // namespace

int main(int argc, char** argv)
{
#if !defined(VLO_ADDRESS_SANITIZER)
	// MRPT asks for tens of GB on a corrupt count: a limit turns that into a failed allocation, not a
	// machine out of memory. (AddressSanitizer reserves terabytes of shadow memory and caps allocations itself.)
	const rlimit limit{4000000000ul, 4000000000ul};
	setrlimit(RLIMIT_AS, &limit);
#endif
	::testing::InitGoogleTest(&argc, argv);
	return RUN_ALL_TESTS();
}
