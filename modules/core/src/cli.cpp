#include <vlo/core/cli.h>
#include <vlo/core/error.h>

#include <cstdlib>
#include <sstream>

namespace vlo
{
namespace
{
const CliOption* findOption(const std::vector<CliOption>& options, const std::string& name)
{
	for (const auto& o : options)
		if (o.name == name) return &o;
	return nullptr;
}
}  // namespace

CommandLine::CommandLine(int argc, char** argv, int first, std::vector<CliOption> options)
	: options_(std::move(options))
{
	for (int i = first; i < argc; ++i)
	{
		const std::string arg = argv[i];
		if (arg == "--help" || arg == "-h")
		{
			help_ = true;
			return;
		}
		if (arg.rfind("--", 0) != 0) failInput("command line", "unexpected argument '" + arg + "'");
		std::string name = arg.substr(2), value;
		const auto eq = name.find('=');
		const bool inlineValue = eq != std::string::npos;
		if (inlineValue)
		{
			value = name.substr(eq + 1);
			name = name.substr(0, eq);
		}
		const CliOption* opt = findOption(options_, name);
		if (!opt) failInput("command line", "unknown option '--" + name + "' (see --help)");
		if (!opt->value_name.empty() && !inlineValue)
		{
			if (i + 1 >= argc) failInput("command line", "option '--" + name + "' needs a value");
			value = argv[++i];
		}
		if (values_.count(name) && !opt->repeatable)
			failInput("command line", "option '--" + name + "' given twice");
		values_[name].push_back(value);
	}
	for (const auto& o : options_)
		if (o.required && !has(o.name)) failInput("command line", "missing required option '--" + o.name + "'");
}

std::string CommandLine::usage(const std::string& synopsis) const
{
	std::ostringstream s;
	s << synopsis << "\n\nOptions:\n";
	for (const auto& o : options_)
	{
		std::string left = "  --" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
		if (left.size() < 28) left.resize(28, ' ');
		s << left << " " << o.help << (o.required ? " (required)" : "") << (o.repeatable ? " (repeatable)" : "")
		  << "\n";
	}
	s << "  --help                       this text\n";
	return s.str();
}

std::string CommandLine::get(const std::string& name, const std::string& fallback) const
{
	const auto it = values_.find(name);
	return it == values_.end() ? fallback : it->second.back();
}

std::vector<std::string> CommandLine::getAll(const std::string& name) const
{
	const auto it = values_.find(name);
	return it == values_.end() ? std::vector<std::string>{} : it->second;
}

double CommandLine::getDouble(const std::string& name, double fallback) const
{
	if (!has(name)) return fallback;
	const std::string v = get(name);
	char* end = nullptr;
	const double d = std::strtod(v.c_str(), &end);
	if (v.empty() || *end != '\0') failInput("command line", "option '--" + name + "' expects a number, got '" + v + "'");
	return d;
}

long CommandLine::getInt(const std::string& name, long fallback) const
{
	if (!has(name)) return fallback;
	const std::string v = get(name);
	char* end = nullptr;
	const long d = std::strtol(v.c_str(), &end, 10);
	if (v.empty() || *end != '\0')
		failInput("command line", "option '--" + name + "' expects an integer, got '" + v + "'");
	return d;
}
}  // namespace vlo
