#include <vlo/core/cli.h>
#include <vlo/core/error.h>

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <memory>

namespace vlo
{
namespace
{
/// CLI11's help layout with the app's own synopsis in place of its generic "Usage: app [OPTIONS]".
class SynopsisFormatter : public CLI::Formatter
{
   public:
	explicit SynopsisFormatter(std::string synopsis) : synopsis_(std::move(synopsis)) { column_width(30); }
	std::string make_usage(const CLI::App*, std::string) const override { return synopsis_ + "\n"; }

   private:
	std::string synopsis_;
};

/// Required and repeated options are checked by CommandLine (one-line errors naming the option), so CLI11 only
/// collects every value; the help text says which options are required or repeatable.
std::unique_ptr<CLI::App> makeApp(const std::vector<CliOption>& options)
{
	auto app = std::make_unique<CLI::App>();
	app->allow_extras();
	for (const auto& o : options)
	{
		const std::string help = o.help + (o.required ? " (required)" : "") + (o.repeatable ? " (repeatable)" : "");
		CLI::Option* opt = o.value_name.empty() ? app->add_flag("--" + o.name, help)
												: app->add_option("--" + o.name, help)->type_name(o.value_name);
		opt->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
	}
	return app;
}

/// The option named in CLI11's "Expected exactly 1 arguments to --name, got 0".
std::string optionIn(const std::string& message)
{
	const auto at = message.find("--");
	if (at == std::string::npos) return message;
	const auto end = message.find_first_of(",: ", at);
	return message.substr(at, end == std::string::npos ? std::string::npos : end - at);
}
}  // namespace

CommandLine::CommandLine(int argc, char** argv, int first, std::vector<CliOption> options)
	: options_(std::move(options))
{
	auto app = makeApp(options_);
	std::vector<std::string> args(argv + std::min(first, argc), argv + argc);
	std::reverse(args.begin(), args.end());  // CLI11 takes them last first
	try
	{
		app->parse(args);
	}
	catch (const CLI::CallForHelp&)
	{
		help_ = true;
		return;
	}
	catch (const CLI::ArgumentMismatch& e)
	{
		failInput("command line", "option '" + optionIn(e.what()) + "' needs a value");
	}
	catch (const CLI::ParseError& e)
	{
		failInput("command line", e.what());
	}
	for (const std::string& extra : app->remaining())
	{
		if (extra.rfind("--", 0) != 0) failInput("command line", "unexpected argument '" + extra + "'");
		failInput("command line", "unknown option '" + extra.substr(0, extra.find('=')) + "' (see --help)");
	}
	for (const auto& o : options_)
	{
		const CLI::Option* opt = app->get_option("--" + o.name);
		if (opt->count() == 0) continue;
		if (opt->count() > 1 && !o.repeatable) failInput("command line", "option '--" + o.name + "' given twice");
		values_[o.name] = o.value_name.empty() ? std::vector<std::string>(opt->count()) : opt->results();
	}
	for (const auto& o : options_)
		if (o.required && !has(o.name)) failInput("command line", "missing required option '--" + o.name + "'");
}

std::string CommandLine::usage(const std::string& synopsis) const
{
	auto app = makeApp(options_);
	app->formatter(std::make_shared<SynopsisFormatter>(synopsis));
	return app->help();
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
