#include <vlo/core/interrupt.h>

#include <csignal>

namespace vlo
{
namespace
{
volatile std::sig_atomic_t g_signal = 0;

extern "C" void onSignal(int sig)
{
	g_signal = sig;
	std::signal(sig, SIG_DFL);  // a second signal ends the process at once
}
}  // namespace

void installInterruptHandler()
{
	std::signal(SIGINT, onSignal);
	std::signal(SIGTERM, onSignal);
}

void throwIfInterrupted()
{
	if (g_signal != 0) throw Interrupted();
}

int interruptSignal() { return g_signal; }
}  // namespace vlo
