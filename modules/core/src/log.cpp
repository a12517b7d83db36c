#include <vlo/core/log.h>
#include <vlo/core/progress.h>

#include <cstdio>

namespace vlo
{
namespace
{
const char* levelTag(mrpt::system::VerbosityLevel level)
{
	switch (level)
	{
		case mrpt::system::LVL_DEBUG: return "debug: ";
		case mrpt::system::LVL_WARN: return "warning: ";
		case mrpt::system::LVL_ERROR: return "error: ";
		default: return "";
	}
}

/// MRPT's own console format ("[name|LEVEL|time] msg") is replaced by vlo's one-line format.
void toStderr(std::string_view msg, mrpt::system::VerbosityLevel level, std::string_view name, mrpt::Clock::time_point)
{
	std::fprintf(stderr, "%.*s: %s%.*s\n", static_cast<int>(name.size()), name.data(), levelTag(level),
		static_cast<int>(msg.size()), msg.data());
	std::fflush(stderr);
}

mrpt::system::COutputLogger& make()
{
	static mrpt::system::COutputLogger log("vlo");
	log.logging_enable_console_output = false;
	log.logRegisterCallback(&toStderr);
	return log;
}
}  // namespace

mrpt::system::COutputLogger& logger()
{
	static mrpt::system::COutputLogger& log = make();
	return log;
}

void setupLogging(const std::string& app)
{
	logger().setLoggerName(app);
	setVerbosity(false, false);
}

void setVerbosity(bool verbose, bool quiet)
{
	const auto level = quiet ? mrpt::system::LVL_ERROR : verbose ? mrpt::system::LVL_DEBUG
																 : mrpt::system::LVL_INFO;
	logger().setMinLoggingLevel(level);
	logger().setVerbosityLevelForCallbacks(level);
	if (quiet) ProgressLine::setEnabled(false);
}

bool infoVisible() { return logger().isLoggingLevelVisible(mrpt::system::LVL_INFO); }
}  // namespace vlo
