#include <vlo/core/app_main.h>
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>

#include <iostream>

namespace vlo
{
int runApp(const std::string& app, const std::function<int()>& body)
{
	installInterruptHandler();
	try
	{
		return body();
	}
	catch (const Interrupted&)
	{
		std::cerr << app << ": interrupted: the outputs it was writing are removed" << std::endl;
		return 130;
	}
	catch (const InputError& e)
	{
		std::cerr << app << ": error: " << e.what() << std::endl;
		return 2;
	}
	catch (const std::exception& e)
	{
		// MRPT exceptions carry a multi-line stack; keep the first line.
		std::string msg = e.what();
		const auto nl = msg.find('\n');
		if (nl != std::string::npos) msg.resize(nl);
		std::cerr << app << ": error: " << msg << std::endl;
		return 1;
	}
}
}  // namespace vlo
