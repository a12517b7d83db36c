// fuzz_seeds TARGET CORPUS_DIR WORK_DIR: writes the seed files of TARGET into CORPUS_DIR (for fuzz/run.sh).
#include "seeds.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: fuzz_seeds TARGET CORPUS_DIR WORK_DIR\n");
		return 2;
	}
	try
	{
		const std::string target = argv[1];
		const auto seeds = target == "rosbag" ? vlo::fuzz::rosbagSeeds(argv[3]) : vlo::fuzz::seedsOf(target, argv[3]);
		std::filesystem::create_directories(argv[2]);
		for (std::size_t k = 0; k < seeds.size(); ++k)
			std::ofstream(std::string(argv[2]) + "/seed-" + std::to_string(k), std::ios::binary) << seeds[k];
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
		return 1;
	}
	return 0;
}
