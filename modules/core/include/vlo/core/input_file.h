#pragma once
// Opening a file the user names: a folder given where a file is expected is said to be one, not reported
// as whatever the parser then makes of reading nothing ("no [section]", "missing key", "no DATA line").
#include <fstream>
#include <string>

namespace vlo
{
/// Throws InputError naming `path` when it is a directory ("is a directory, expected a file") or does not
/// exist ("cannot open file (no such file)").
void requireInputFile(const std::string& path);

/// requireInputFile, then the open stream; InputError "cannot open file" when it cannot be opened.
std::ifstream openInputFile(const std::string& path, std::ios::openmode mode = std::ios::in);
}  // namespace vlo
