#pragma once
// Provenance of the binaries: the project's version, the git commit they were built from (taken at build
// time; "-dirty" with uncommitted changes, "unknown" outside a git checkout) and the CMake build type.
#include <string>

namespace vlo
{
struct BuildInfo
{
	std::string version, git_commit, build_type;
};
const BuildInfo& buildInfo();

/// "<app> 0.1.0 (git 504f40c1a2b3, Release)": what --version prints.
std::string versionLine(const std::string& app);
}  // namespace vlo
