#pragma once
// The logger of a vlo process: one mrpt::system::COutputLogger, named after the app, that every app
// and module writes its messages through, in one format on stderr:
//   "<app>: <message>" (information), "<app>: warning: ...", "<app>: error: ...", "<app>: debug: ...".
// Verbosity: --verbose adds the debug messages, --quiet leaves the errors (and each app's final line,
// which is not a log message) only, and turns the progress line off.
#include <mrpt/system/COutputLogger.h>

#include <string>

namespace vlo
{
/// The process's logger (named "vlo" until setupLogging names it).
mrpt::system::COutputLogger& logger();

/// Names the logger after the app and shows information, warnings and errors (runApp calls it).
void setupLogging(const std::string& app);

/// Applies --verbose / --quiet (both given: --quiet wins, as the stricter).
void setVerbosity(bool verbose, bool quiet);

/// True unless --quiet: for output that is not a message, such as vlo-run's table of timings.
bool infoVisible();
}  // namespace vlo
