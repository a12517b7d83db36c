#pragma once
// Common main() wrapper: every error becomes one line on stderr and a non-zero exit code.
#include <functional>
#include <string>

namespace vlo
{
/// Sets up the logger for `app` (log.h), runs body(); HelpShown (app_cli.h) -> code 0; InputError -> "<app>: error: <what>"
/// and exit code 2; Ctrl-C or SIGTERM (see interrupt.h) -> one line and code 130; any other exception -> code 1.
int runApp(const std::string& app, const std::function<int()>& body);
}  // namespace vlo
