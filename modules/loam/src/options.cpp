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
	external_stage = c.read_string_first_word(s, "external_stage", external_stage);
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
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_deviation, "external motion this far from constant velocity and from its own last motion is rejected [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_deviation_deg, "... or turning this differently [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(external_stage, "odometry: the external motion initialises scan-to-scan | mapping: scan-to-map, scan-to-scan skipped");
}

void PriorOptions::validate() const
{
	const std::string s = "loam.prior";
	require(source == "constant_velocity" || source == "external", s, "source",
		"'" + source + "' is not one of constant_velocity, external");
	require(external_stage == "odometry" || external_stage == "mapping", s, "external_stage",
		"'" + external_stage + "' is not one of odometry, mapping");
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
