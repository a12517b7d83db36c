#pragma once
// The start that every app's main shares: its own options plus --verbose/--quiet, --help answered with
// the usage text, the logger's verbosity set from the switches.
#include <vlo/core/cli.h>

#include <optional>
#include <string>
#include <vector>

namespace vlo
{
/// Parses argv[first..] with `options` and the --verbose/--quiet switches (throws InputError like CommandLine).
/// On --help prints usage(synopsis) to stdout and returns nothing: the app then exits 0. Otherwise applies
/// --verbose/--quiet to the logger and returns the parsed command line.
std::optional<CommandLine> parseAppCommandLine(
	int argc, char** argv, int first, std::vector<CliOption> options, const std::string& synopsis);
}  // namespace vlo
