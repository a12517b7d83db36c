#pragma once
// An options struct with one key of each kind and one relation, for the tests of the option-check
// path (OptionTable in core, RunConfig in kernel). Only for tests.
#include <vlo/core/option_table.h>

#include <functional>
#include <string>
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
