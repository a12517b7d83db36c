#include <vlo/core/app_cli.h>
#include <vlo/core/log.h>

#include <iostream>

namespace vlo
{
CommandLine parseAppCommandLine(
	int argc, char** argv, int first, std::vector<CliOption> options, const std::string& synopsis)
{
	options.push_back({"verbose", "", "debug messages too"});
	options.push_back({"quiet", "", "errors and the final line only"});
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
