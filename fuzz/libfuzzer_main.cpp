// libFuzzer entry point of one reader (VLO_FUZZ_TARGET, set per executable by CMake). An input that
// makes the reader crash, hang, or fail other than with a one-line InputError naming the file aborts,
// so libFuzzer keeps it as crash-<hash>.
#include "targets.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
#if defined(VLO_FUZZ_INI)
	static const vlo::fuzz::Target t = vlo::fuzz::iniTarget();
#elif defined(VLO_FUZZ_ROSBAG)
	static const vlo::fuzz::Target t = vlo::fuzz::rosbagTarget();
#else
	static const vlo::fuzz::Target t = vlo::fuzz::findTarget(vlo::fuzz::ioTargets(), VLO_FUZZ_TARGET);
#endif
	static const std::string dir = [] {
		const auto d = std::filesystem::temp_directory_path() / ("vlo_fuzz_" VLO_FUZZ_TARGET "_" + std::to_string(::getpid()));
		std::filesystem::create_directories(d);
		return d.string();
	}();
	const std::string failure = vlo::fuzz::runOne(t, dir, std::string(reinterpret_cast<const char*>(data), size));
	if (!failure.empty())
	{
		std::fprintf(stderr, "%s: %s\n", VLO_FUZZ_TARGET, failure.c_str());
		std::abort();
	}
	return 0;
}
