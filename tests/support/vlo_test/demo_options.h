#pragma once
// An options struct with one key of each kind and one relation, for the tests of the option-check
// path (OptionTable in core, RunConfig in kernel). Only for tests.
#include <vlo/core/option_table.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vlo::test
{
struct DemoOptions : public OptionSet
{
	double gain = 0.25;
	int count = 3;
	bool on = true;
	std::string mode = "fast";
	std::vector<double> table{1.5, -2};

   protected:
	void declare(OptionTable& t) override
	{
		t.add("gain", gain, "(0, 1]", "a gain");
		t.add("count", count, ">= 1", "how many");
		t.add("on", on, "true | false", "switch");
		t.add("mode", mode, "fast | slow", "speed");
		t.add("table", table, "(-90, 90)", "angles [deg]");
	}
	void checkRelations() const override { require(gain < count, "gain", "must be below count"); }
};

/// INI lines that DemoOptions refuses, each with the problem reported after "[section] key: ".
inline const std::vector<std::pair<std::string, std::string>> kRefusedDemoLines{
	{"gain = abc", "expects a number, got 'abc'"},
	{"gain = nan", "expects a finite number, got 'nan'"},
	{"gain = 0", "must be in (0, 1]"},
	{"count = 1.5", "expects an integer, got '1.5'"},
	{"count = 2.5x", "expects an integer, got '2.5x'"},
	{"count = 99999999999", "the integer '99999999999' is out of range"},
	{"count = 0", "must be >= 1"},
	{"on = maybe", "expects true or false, got 'maybe'"},
	{"mode = slwo", "'slwo' is not one of fast, slow (did you mean slow?)"},
	{"table = [1 x]", "expects a list of numbers like [1.5 -2 3], got '[1 x]'"},
	{"table = [1 95]", "each value must be in (-90, 90)"},
};

/// The key of an INI line "key = value".
inline std::string keyOf(const std::string& line) { return line.substr(0, line.find(" = ")); }

/// The message of the InputError that f() throws, or "" when it throws none.
inline std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace vlo::test
