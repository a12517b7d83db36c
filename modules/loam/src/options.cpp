// [loam.prior] and the aggregate of all sections.
#include "option_checks.h"
#include "vlo/loam/options.h"

#include <cmath>
#include <sstream>

namespace vlo::loam
{
using detail::require;

void PriorOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	source = c.read_string_first_word(s, "source", source);
	VLO_NUM(max_translation, double);
	VLO_NUM(max_rotation_deg, double);
	VLO_NUM(max_deviation, double);
	VLO_NUM(max_deviation_deg, double);
}

void PriorOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(source, "constant_velocity (A-LOAM) | external (e.g. visual odometry)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_translation, "external motion longer than this is rejected [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_rotation_deg, "external motion turning more is rejected [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_deviation, "external motion this far from constant velocity is rejected [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_deviation_deg, "... or turning this differently [deg]");
}

void PriorOptions::validate() const
{
	const std::string s = "loam.prior";
	require(source == "constant_velocity" || source == "external", s, "source",
		"'" + source + "' is not one of constant_velocity, external");
	require(max_translation > 0, s, "max_translation", "must be > 0");
	require(max_rotation_deg > 0, s, "max_rotation_deg", "must be > 0");
	require(max_deviation > 0, s, "max_deviation", "must be > 0");
	require(max_deviation_deg > 0, s, "max_deviation_deg", "must be > 0");
}

std::vector<std::string> LoamOptions::sections()
{
	return {"loam.scan", "loam.features", "loam.odometry", "loam.mapping", "loam.prior"};
}

void LoamOptions::load(const mrpt::config::CConfigFileBase& c)
{
	scan.loadFromConfigFile(c, "loam.scan");
	features.loadFromConfigFile(c, "loam.features");
	odometry.loadFromConfigFile(c, "loam.odometry");
	mapping.loadFromConfigFile(c, "loam.mapping");
	prior.loadFromConfigFile(c, "loam.prior");
}

void LoamOptions::save(mrpt::config::CConfigFileBase& c) const
{
	scan.saveToConfigFile(c, "loam.scan");
	features.saveToConfigFile(c, "loam.features");
	odometry.saveToConfigFile(c, "loam.odometry");
	mapping.saveToConfigFile(c, "loam.mapping");
	prior.saveToConfigFile(c, "loam.prior");
}

void LoamOptions::validate() const
{
	scan.validate();
	features.validate();
	odometry.validate();
	mapping.validate();
	prior.validate();
}
}  // namespace vlo::loam
