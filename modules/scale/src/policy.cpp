#include <vlo/scale/policy.h>

#include <cmath>

namespace vlo::scale
{
const char* toString(ScaleDecision::Kind k)
{
	switch (k)
	{
		case ScaleDecision::Kind::Skip: return "skip";
		case ScaleDecision::Kind::Initial: return "initial";
		case ScaleDecision::Kind::Correction: return "correction";
	}
	return "?";
}

ScaleCorrectionPolicy::ScaleCorrectionPolicy(const ScaleOptions& opt)
	: threshold_(opt.correction_threshold), enabled_(opt.correction_enabled)
{
	opt.validate();
}

ScaleDecision ScaleCorrectionPolicy::decide(const ScaleEstimate& e)
{
	ScaleDecision d;
	if (!e.valid || !(e.scale > 0) || !std::isfinite(e.scale))
	{
		d.why = "no valid estimate";
		return d;
	}
	if (!initialized_)
	{
		initialized_ = true;
		d.kind = ScaleDecision::Kind::Initial;
		d.why = "first estimate sets the metric scale";
	}
	else if (!enabled_)
	{
		d.why = "correction disabled";
		return d;
	}
	else if (std::abs(e.scale - 1.0) < threshold_)
	{
		d.why = "within threshold";
		return d;
	}
	else
	{
		d.kind = ScaleDecision::Kind::Correction;
		d.why = "|s - 1| >= threshold";
		++corrections_;
	}
	d.factor = e.scale;
	cumulative_ *= e.scale;
	return d;
}

void ScaleCorrectionPolicy::reset()
{
	initialized_ = false;
	cumulative_ = 1.0;
	corrections_ = 0;
}
}  // namespace vlo::scale
