#include <vlo/core/app_cli.h>
#include <vlo/core/build_info.h>
#include <vlo/core/log.h>

#include <iostream>
#include <string>

namespace vlo
{
CommandLine parseAppCommandLine(
	int argc, char** argv, int first, std::vector<CliOption> options, const std::string& synopsis)
{
	options.push_back({"verbose", "", "debug messages too"});
	options.push_back({"quiet", "", "errors and the final line only"});
	options.push_back({"version", "", "print the version, git commit and build type, and stop"});
	// Before the options are checked: --version needs none of the required ones.
	for (int i = first; i < argc; ++i)
		if (std::string(argv[i]) == "--version")
		{
			std::cout << versionLine(logger().getLoggerName()) << "\n";
			throw HelpShown{};
		}
	CommandLine cl(argc, argv, first, std::move(options));
	if (cl.helpRequested())
	{
		std::cout << cl.usage(synopsis);
		throw HelpShown{};
	}
	setVerbosity(cl.has("verbose"), cl.has("quiet"));
	return cl;
}
}  // namespace vlo
