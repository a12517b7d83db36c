#pragma once
// The command line of every app (CLI11 underneath): "--name value" options, "--flag" switches,
// repeatable options, --help, and a clear error for anything unknown or missing.
#include <map>
#include <string>
#include <vector>

namespace vlo
{
struct CliOption
{
	std::string name;  ///< without the leading "--"
	std::string value_name;  ///< empty for a switch that takes no value
	std::string help;
	bool required = false;
	bool repeatable = false;
};

class CommandLine
{
   public:
	/// Parses argv[first..]. Throws InputError("command line", ...) on bad input.
	/// Returns with helpRequested() true when --help or -h is given.
	CommandLine(int argc, char** argv, int first, std::vector<CliOption> options);

	bool helpRequested() const { return help_; }
	std::string usage(const std::string& synopsis) const;

	bool has(const std::string& name) const { return values_.count(name) > 0; }
	std::string get(const std::string& name, const std::string& fallback = "") const;
	std::vector<std::string> getAll(const std::string& name) const;
	double getDouble(const std::string& name, double fallback) const;
	long getInt(const std::string& name, long fallback) const;

   private:
	std::vector<CliOption> options_;
	std::map<std::string, std::vector<std::string>> values_;
	bool help_ = false;
};
}  // namespace vlo
