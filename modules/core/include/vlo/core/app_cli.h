#pragma once
// The start that every app's main shares: its own options plus --verbose/--quiet/--version, --help answered
// with the usage text (then exit code 0), the logger's verbosity set from the switches.
#include <vlo/core/cli.h>

#include <string>
#include <vector>

namespace vlo
{
/// Thrown once --help has printed the usage: runApp ends the app with code 0 (as CLI11's CallForHelp).
struct HelpShown
{
};

/// Parses argv[first..] with `options` and the --verbose/--quiet switches (throws InputError like CommandLine).
/// On --help prints usage(synopsis) to stdout and throws HelpShown; on --version prints the app's
/// versionLine (build_info.h) and throws HelpShown. Otherwise applies --verbose/--quiet to
/// the logger and returns the parsed command line.
CommandLine parseAppCommandLine(
	int argc, char** argv, int first, std::vector<CliOption> options, const std::string& synopsis);
}  // namespace vlo
