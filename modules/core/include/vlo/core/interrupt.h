#pragma once
// Ctrl-C (SIGINT) and SIGTERM end a long job cleanly: the first signal only sets a flag, which the
// job's loops test (ProgressLine::update does) and turn into an Interrupted exception, so that the
// outputs being written are removed while the stack unwinds. A second signal ends the process at once.
#include <stdexcept>

namespace vlo
{
class Interrupted : public std::runtime_error
{
   public:
	Interrupted() : std::runtime_error("interrupted") {}
};

/// Installs the handlers (runApp does this for every app).
void installInterruptHandler();
/// Throws Interrupted once a signal has arrived.
void throwIfInterrupted();
}  // namespace vlo
