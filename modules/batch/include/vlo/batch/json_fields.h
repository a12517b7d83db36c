#pragma once
// The top-level scalar fields of a JSON object, as written by vlo-eval --json and vlo-run's
// summary.json (parsed with nlohmann-json). Nested arrays and objects are skipped.
#include <map>
#include <string>

namespace vlo::batch
{
class JsonFields
{
   public:
	JsonFields() = default;
	/// Throws InputError(origin, ...) when the text is not a JSON object.
	static JsonFields parse(const std::string& text, const std::string& origin);
	/// Reads and parses a file; throws InputError naming it.
	static JsonFields read(const std::string& path);

	bool has(const std::string& key) const { return values_.count(key) > 0; }
	/// NaN when absent, null or not a number.
	double number(const std::string& key) const;
	/// The string value (unescaped), or the literal text of a number/true/false/null; "" when absent.
	std::string text(const std::string& key) const;

   private:
	std::map<std::string, std::string> values_;
};
}  // namespace vlo::batch
