#pragma once
// Helpers of the options files: a range check that names the INI key.
#include <vlo/core/error.h>

#include <string>

namespace vlo::vo::detail
{
inline void require(bool ok, const char* section, const char* key, const std::string& problem)
{
	if (!ok) failInput(std::string("[") + section + "] " + key, problem);
}
}  // namespace vlo::vo::detail

#define VLO_VO_LOAD(var, type) MRPT_LOAD_CONFIG_VAR(var, type, c, s)
