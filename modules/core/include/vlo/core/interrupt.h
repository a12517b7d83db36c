#pragma once
// Ctrl-C (SIGINT) and SIGTERM end a long job cleanly: the first signal only sets a flag, which the
// job's loops test (ProgressLine::update does) and turn into an Interrupted exception, so that the
// outputs being written are removed while the stack unwinds. A second signal ends the process at once.
#include <stdexcept>
#include <string>

namespace vlo
{
class Interrupted : public std::runtime_error
{
   public:
	/// `what` says what was stopped and what became of its outputs; runApp prints it after "APP: interrupted: ".
	explicit Interrupted(const std::string& what = "the outputs it was writing are removed") : std::runtime_error(what) {}
};

/// Installs the handlers (runApp does this for every app).
void installInterruptHandler();
/// Throws Interrupted once a signal has arrived.
void throwIfInterrupted();
/// The signal that interrupted the process (SIGINT or SIGTERM), 0 if none: what a parent passes on to its children.
int interruptSignal();
}  // namespace vlo
