#pragma once
// Strict INI value checks shared by the options files (MRPT turns "abc" into 0 silently).
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>

#include <cstdlib>
#include <string>

namespace vlo::loam::detail
{
inline void checkNumber(
	const mrpt::config::CConfigFileBase& c, const std::string& s, const char* key, bool integer)
{
	if (!c.keyExists(s, key)) return;
	const std::string v = c.read_string(s, key, "");
	const char* b = v.c_str();
	char* e = nullptr;
	if (integer) (void)std::strtol(b, &e, 10);
	else (void)std::strtod(b, &e);
	while (e && (*e == ' ' || *e == '\t')) ++e;
	if (v.empty() || e == b || (e && *e != '\0'))
		failInput("[" + s + "] " + key, "'" + v + "' is not " + (integer ? "an integer" : "a number"));
}

inline void checkBool(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* key)
{
	if (!c.keyExists(s, key)) return;
	const std::string v = c.read_string_first_word(s, key, "");
	for (const char* ok : {"true", "false", "1", "0", "yes", "no", "TRUE", "FALSE", "True", "False"})
		if (v == ok) return;
	failInput("[" + s + "] " + key, "'" + v + "' is not a boolean (true/false)");
}

inline void require(bool ok, const std::string& s, const char* key, const std::string& problem)
{
	if (!ok) failInput("[" + s + "] " + key, problem);
}
}  // namespace vlo::loam::detail

// Loads a member named like its INI key after checking the text.
#define VLO_NUM(var, type) \
	::vlo::loam::detail::checkNumber(c, s, #var, std::string(#type) == "int"); \
	MRPT_LOAD_CONFIG_VAR(var, type, c, s)
#define VLO_BOOL(var) \
	::vlo::loam::detail::checkBool(c, s, #var); \
	MRPT_LOAD_CONFIG_VAR(var, bool, c, s)
