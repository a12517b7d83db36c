#include <vlo/core/error.h>
#include <vlo/core/input_file.h>

#include <filesystem>

namespace vlo
{
void requireInputFile(const std::string& path)
{
	std::error_code ec;
	const auto status = std::filesystem::status(path, ec);
	if (std::filesystem::is_directory(status)) failInput(path, "is a directory, expected a file");
	if (!std::filesystem::exists(status)) failInput(path, "cannot open file (no such file)");
}

std::ifstream openInputFile(const std::string& path, std::ios::openmode mode)
{
	requireInputFile(path);
	std::ifstream in(path, mode);
	if (!in) failInput(path, "cannot open file");
	return in;
}
}  // namespace vlo
