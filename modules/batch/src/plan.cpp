#include "plan_keys.h"

#include <vlo/batch/plan.h>
#include <vlo/batch/words.h>
#include <vlo/core/error.h>
#include <vlo/core/ini_text.h>
#include <vlo/io/kitti_import.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace vlo::batch
{
namespace
{
/// Names become folder names and table labels: keep them to safe characters.
void checkName(const std::string& name, const std::string& where)
{
	bool ok = !name.empty() && name != "." && name != "..";
	for (const char c : name)
		if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) ok = false;
	if (!ok) failInput(where, "the name '" + name + "' may only hold letters, digits, '_', '-' and '.'");
}

void checkLengths(const std::string& v, const std::string& where)
{
	std::string tok;
	for (std::istringstream ss(v); std::getline(ss, tok, ',');)
	{
		char* end = nullptr;
		const double d = std::strtod(tok.c_str(), &end);
		if (tok.empty() || *end != '\0' || !(d > 0)) failInput(where, "'" + tok + "' is not a positive length in metres");
	}
}

Sequence readSequence(
	const SectionReader& r, const std::string& name, const std::string& plan_dir, const std::string& data, bool check_files)
{
	SequenceKeys k;
	k.rawlog = name + ".rawlog";
	r.load(k);
	Sequence s;
	s.name = name;
	s.rawlog = absolutePath(k.rawlog, data);
	s.gt = absolutePath(r.has("gt") ? k.gt : io::groundTruthPathFor(s.rawlog), data);
	if (!r.has("ini")) failInput(r.where("ini"), "missing (the base INI of the sensor, e.g. ../sim-hdl64.ini)");
	s.ini = absolutePath(k.ini, plan_dir);
	if (check_files && !fs::is_regular_file(s.ini)) failInput(r.where("ini"), s.ini + " does not exist");
	s.gt_translation_only = k.gt_translation_only;
	if (r.has("kitti_calib"))
	{
		s.kitti_calib = absolutePath(k.kitti_calib, data);
		if (check_files && !fs::is_regular_file(s.kitti_calib))
			failInput(r.where("kitti_calib"), s.kitti_calib + " does not exist");
	}
	const auto sim = splitWords(k.sim, r.where("sim"));
	if (r.has("sim") && sim.empty()) failInput(r.where("sim"), "empty (give vlo-sim arguments or leave the key out)");
	if (!sim.empty())
	{
		if (s.gt != io::groundTruthPathFor(s.rawlog))
			failInput(r.where("gt"), "must be left out with sim: vlo-sim writes " + io::groundTruthPathFor(s.rawlog));
		s.sim = checkSimArgs(sim, data, check_files && s.dataMissing(), r);
	}
	else if (check_files && !fs::is_regular_file(s.rawlog))
		failInput(r.where("rawlog"), s.rawlog + " does not exist (and no sim = to generate it)");
	else if (check_files && !fs::is_regular_file(s.gt))
		failInput(r.where("gt"), s.gt + " does not exist");
	return s;
}

Config readConfig(const SectionReader& r, const std::string& name, const std::string& plan_dir, bool check_files)
{
	ConfigKeys k;
	r.load(k);
	Config c;
	c.name = name;
	if (r.has("ini"))
	{
		c.ini = absolutePath(k.ini, plan_dir);
		if (check_files && !fs::is_regular_file(c.ini)) failInput(r.where("ini"), c.ini + " does not exist");
	}
	c.overrides = splitWords(k.set, r.where("set"));
	for (const auto& o : c.overrides)
	{
		const auto dot = o.find('.'), eq = o.find('=');
		if (dot == std::string::npos || eq == std::string::npos || dot > eq)
			failInput(r.where("set"), "'" + o + "' is not section.key=value");
	}
	c.align = k.align;
	return c;
}
}  // namespace

bool Sequence::dataMissing() const { return !fs::is_regular_file(rawlog) || !fs::is_regular_file(gt); }

Plan parsePlan(const std::string& text, const std::string& origin, const std::string& plan_dir,
	const std::string& data_dir, bool check_files)
{
	const auto sections = scanIniText(text, origin);
	mrpt::config::CConfigFileMemory ini;
	try
	{
		ini.setContent(text);
	}
	catch (const std::exception& e)
	{
		// MRPT rejects an unknown ${VAR}; its message has a stack trace after the first line.
		const std::string msg = e.what();
		failInput(origin, msg.substr(0, msg.find('\n')));
	}
	Plan plan;
	plan.source = origin;
	std::string data = "rawlogs/experiments";
	std::set<std::string> seen;
	for (const auto& s : sections)
	{
		std::istringstream words(s.name);
		std::string kind, name, extra;
		words >> kind >> name >> extra;
		const std::string at = origin + ": [" + s.name + "]";
		const SectionReader r(ini, origin, s.name);
		if (kind == "plan" && name.empty())
		{
			PlanKeys k;
			k.data = data;
			k.kitti_step = plan.kitti_step;
			k.source = plan.source;
			r.load(k);
			data = k.data;
			plan.kitti_lengths = k.kitti_lengths;
			if (r.has("kitti_lengths")) checkLengths(plan.kitti_lengths, r.where("kitti_lengths"));
			plan.kitti_step = k.kitti_step;
			if (r.has("revisit_radius")) plan.revisit_radius = k.revisit_radius;
			if (r.has("revisit_min_path")) plan.revisit_min_path = k.revisit_min_path;
			plan.source = k.source;
			continue;
		}
		if ((kind != "sequence" && kind != "config") || name.empty() || !extra.empty())
			failInput(at, "unknown section (expected [plan], [sequence NAME] or [config NAME])");
		checkName(name, at);
		if (!seen.insert(kind + " " + name).second) failInput(at, "the " + kind + " name '" + name + "' is given twice");
	}
	plan.data_dir = absolutePath(data_dir.empty() ? data : data_dir, ".");
	for (const auto& s : sections)
	{
		std::string kind, name;
		std::istringstream(s.name) >> kind >> name;
		const SectionReader r(ini, origin, s.name);
		if (kind == "sequence") plan.sequences.push_back(readSequence(r, name, plan_dir, plan.data_dir, check_files));
		if (kind == "config") plan.configs.push_back(readConfig(r, name, plan_dir, check_files));
	}
	if (plan.sequences.empty()) failInput(origin, "no [sequence NAME] section");
	if (plan.configs.empty()) failInput(origin, "no [config NAME] section");
	return plan;
}

Plan readPlan(const std::string& path, const std::string& data_dir, bool check_files)
{
	std::ifstream in(path);
	if (!in || fs::is_directory(path)) failInput(path, "cannot open the plan file");
	std::stringstream ss;
	ss << in.rdbuf();
	return parsePlan(ss.str(), path, fs::absolute(path).parent_path().string(), data_dir, check_files);
}
}  // namespace vlo::batch
