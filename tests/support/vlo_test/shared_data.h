#pragma once
// Shared test data (../shared/data) for the modules' unit tests: an archive unpacked once into the
// build tree. Only for tests (the paths come from the test targets' definitions).
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace vlo::test
{
/// `top` of the shared-data archive `name` (../shared/data), unpacked once into the build tree's
/// test_data/`area` (only the members matching `members`, tar wildcards); safe when ctest runs
/// tests in parallel.
/// `ready`, relative to `top`, is a file whose presence means it is unpacked. Nothing is unpacked
/// (the path does not exist) without the archive.
inline std::filesystem::path sharedData(const std::string& area, const std::string& name, const std::string& top,
	const std::string& members, const std::string& ready)
{
	namespace fs = std::filesystem;
	const fs::path archive = fs::path(VLO_SHARED_DATA) / name;
	const fs::path root = fs::path(VLO_BIN_DIR) / ".." / "test_data" / area;
	if (fs::exists(root / top / ready) || !fs::exists(archive)) return root / top;
	const fs::path tmp = root / ("unpack." + std::to_string(getpid()));
	fs::create_directories(tmp);
	const std::string cmd = "tar -xJf '" + archive.string() + "' -C '" + tmp.string() + "' --wildcards " + members;
	if (std::system(cmd.c_str()) != 0) return root / top;
	std::error_code ec;
	fs::rename(tmp / top, root / top, ec);  // loses harmlessly to a concurrent unpack
	fs::remove_all(tmp);
	return root / top;
}
}  // namespace vlo::test
