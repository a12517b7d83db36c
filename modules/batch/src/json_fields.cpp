#include <vlo/batch/json_fields.h>
#include <vlo/core/error.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vlo::batch
{
JsonFields JsonFields::parse(const std::string& text, const std::string& origin)
{
	nlohmann::json j;
	try
	{
		j = nlohmann::json::parse(text);
	}
	catch (const nlohmann::json::parse_error& e)
	{
		// "[json.exception.parse_error.101] parse error at line 1, column 8: ..." without the tag.
		const std::string what = e.what();
		failInput(origin, "not valid JSON (" + what.substr(what.find(' ') + 1) + ")");
	}
	if (!j.is_object()) failInput(origin, "not valid JSON (expected an object)");
	JsonFields f;
	for (const auto& [key, value] : j.items())
	{
		if (value.is_string()) f.values_[key] = value.get<std::string>();
		else if (value.is_primitive()) f.values_[key] = value.dump();
	}
	return f;
}

JsonFields JsonFields::read(const std::string& path)
{
	std::ifstream in(path);
	if (!in) failInput(path, "cannot open");
	std::stringstream ss;
	ss << in.rdbuf();
	return parse(ss.str(), path);
}

double JsonFields::number(const std::string& key) const
{
	const auto it = values_.find(key);
	if (it == values_.end()) return NAN;
	char* end = nullptr;
	const double d = std::strtod(it->second.c_str(), &end);
	return it->second.empty() || *end != '\0' ? NAN : d;
}

std::string JsonFields::text(const std::string& key) const
{
	const auto it = values_.find(key);
	return it == values_.end() ? "" : it->second;
}
}  // namespace vlo::batch
