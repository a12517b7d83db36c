#pragma once
// A scratch folder per test and small file helpers shared by the batch tests.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace vlo::test
{
/// Creates a fresh folder under the system's temp folder; removes it at the end of the test.
class ScratchDir
{
   public:
	explicit ScratchDir(const std::string& name)
		: path_((std::filesystem::temp_directory_path() / ("vlo_batch_" + name + "_" + std::to_string(getpid()))).string())
	{
		std::filesystem::remove_all(path_);
		std::filesystem::create_directories(path_);
	}
	~ScratchDir() { std::filesystem::remove_all(path_); }
	const std::string& path() const { return path_; }
	std::string operator/(const std::string& rel) const { return path_ + "/" + rel; }

   private:
	std::string path_;
};

inline void writeFile(const std::string& path, const std::string& text)
{
	std::filesystem::create_directories(std::filesystem::path(path).parent_path());
	std::ofstream(path) << text;
}

inline std::string readFile(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	return ss.str();
}
}  // namespace vlo::test
