#include <vlo/core/app_cli.h>
#include <vlo/core/app_main.h>
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>
#include <vlo/core/log.h>

#include <algorithm>
#include <iostream>

namespace vlo
{
int runApp(const std::string& app, const std::function<int()>& body)
{
	installInterruptHandler();
	setupLogging(app);
	try
	{
		return body();
	}
	catch (const HelpShown&)
	{
		return 0;
	}
	catch (const Interrupted& e)
	{
		// The last line of an interrupted run, like an app's final line: not a log message, shown with --quiet too.
		std::cerr << app << ": interrupted: " << e.what() << std::endl;
		return 130;
	}
	catch (const InputError& e)
	{
		// One line, whatever a library put into the message.
		std::string msg = e.what();
		msg.resize(std::min(msg.size(), msg.find('\n')));
		logger().logStr(mrpt::system::LVL_ERROR, msg);
		return 2;
	}
	catch (const std::exception& e)
	{
		// MRPT exceptions carry a multi-line stack; keep the first line.
		std::string msg = e.what();
		const auto nl = msg.find('\n');
		if (nl != std::string::npos) msg.resize(nl);
		logger().logStr(mrpt::system::LVL_ERROR, msg);
		return 1;
	}
}
}  // namespace vlo
