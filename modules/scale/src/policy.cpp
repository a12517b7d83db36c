#include <vlo/scale/policy.h>

#include <algorithm>
#include <cmath>
#include <vector>

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
	: threshold_(opt.correction_threshold),
	  refine_threshold_(opt.initial_refine_threshold),
	  enabled_(opt.correction_enabled),
	  window_(static_cast<std::size_t>(std::max(1, opt.correction_window)))
{
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
	else
	{
		recent_.push_back(e.scale);
		if (recent_.size() > window_) recent_.pop_front();
		if (recent_.size() < window_)
		{
			d.why = "collecting estimates";
			return d;
		}
		std::vector<double> v(recent_.begin(), recent_.end());
		std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
		const double median = v[v.size() / 2];
		// The initial scale came from one frame pair; the first full window refines it more finely.
		const double threshold = refined_ || refine_threshold_ <= 0 ? threshold_ : refine_threshold_;
		refined_ = true;
		if (std::abs(median - 1.0) < threshold)
		{
			d.why = "within threshold";
			return d;
		}
		d.kind = ScaleDecision::Kind::Correction;
		d.why = "|s - 1| >= threshold";
		d.factor = median;
		++corrections_;
		recent_.clear();  // the next estimates measure the corrected map
		cumulative_ *= median;
		return d;
	}
	d.factor = e.scale;
	cumulative_ *= e.scale;
	return d;
}

void ScaleCorrectionPolicy::reset()
{
	initialized_ = false;
	refined_ = false;
	recent_.clear();
	cumulative_ = 1.0;
	corrections_ = 0;
}
}  // namespace vlo::scale
