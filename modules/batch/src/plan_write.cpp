#include <vlo/batch/plan.h>
#include <vlo/batch/words.h>

#include <sstream>

namespace vlo::batch
{
std::string resolvedPlanText(const Plan& plan)
{
	std::ostringstream o;
	o << "# Resolved copy of " << plan.source << " written by vlo-batch: every path is absolute.\n"
	  << "# vlo-batch --collect reads it; it is also a plan that runs the same jobs from anywhere.\n\n";
	o << "[plan]\nsource = " << plan.source << "\ndata = " << plan.data_dir << "\n";
	if (!plan.kitti_lengths.empty()) o << "kitti_lengths = " << plan.kitti_lengths << "\n";
	if (plan.kitti_step > 0) o << "kitti_step = " << plan.kitti_step << "\n";
	if (plan.revisit_radius) o << "revisit_radius = " << numberWord(*plan.revisit_radius) << "\n";
	if (plan.revisit_min_path) o << "revisit_min_path = " << numberWord(*plan.revisit_min_path) << "\n";
	for (const auto& s : plan.sequences)
	{
		o << "\n[sequence " << s.name << "]\nrawlog = " << s.rawlog << "\n";
		// vlo-sim decides where the ground truth goes: a gt key next to sim would be refused.
		if (s.sim.empty()) o << "gt = " << s.gt << "\n";
		o << "ini = " << s.ini << "\n";
		if (!s.sim.empty()) o << "sim = " << joinWords(s.sim) << "\n";
		if (s.gt_translation_only) o << "gt_translation_only = true\n";
		if (!s.kitti_calib.empty()) o << "kitti_calib = " << s.kitti_calib << "\n";
	}
	for (const auto& c : plan.configs)
	{
		o << "\n[config " << c.name << "]\n";
		if (!c.ini.empty()) o << "ini = " << c.ini << "\n";
		if (!c.overrides.empty()) o << "set = " << joinWords(c.overrides) << "\n";
		o << "align = " << c.align << "\n";
	}
	return o.str();
}
}  // namespace vlo::batch
