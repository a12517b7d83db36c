#include <vlo/scale/policy.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vlo::scale
{
namespace
{
/// Fewest estimates an early correction rests on: with fewer, one outlier decides.
constexpr std::size_t kEarlyMinEstimates = 5;
/// A single estimate's scatter is at least this (the estimates of a few frames can agree by chance).
constexpr double kMinSingleSpread = 0.01;

double medianOf(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}

/// Standard error of the median of `values`: 1.25 sigma / sqrt(n), sigma from the median absolute
/// deviation (1.4826 MAD) and at least kMinSingleSpread.
double medianError(const std::deque<double>& values, double median)
{
	std::vector<double> dev;
	for (double x : values) dev.push_back(std::abs(x - median));
	const double sigma = std::max(kMinSingleSpread, 1.4826 * medianOf(dev));
	return 1.2533 * sigma / std::sqrt(static_cast<double>(values.size()));
}
}  // namespace

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
	  early_sigmas_(opt.initial_refine_sigmas),
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
		const bool refining = !refined_ && refine_threshold_ > 0;
		const double median = medianOf({recent_.begin(), recent_.end()});
		if (recent_.size() < window_)
		{
			// The initial scale came from one frame pair: while the first window fills, correct as soon
			// as its estimates say with confidence that it is off, not only once the window is full.
			const bool early = refining && early_sigmas_ > 0 && recent_.size() >= kEarlyMinEstimates &&
				std::abs(median - 1.0) >= std::max(refine_threshold_, early_sigmas_ * medianError(recent_, median));
			if (!early)
			{
				d.why = "collecting estimates";
				return d;
			}
			d.why = "first window's estimates off with confidence";
		}
		else
		{
			// The first full window refines the initial scale more finely than later windows correct.
			const double threshold = refining ? refine_threshold_ : threshold_;
			refined_ = true;
			if (std::abs(median - 1.0) < threshold)
			{
				d.why = "within threshold";
				return d;
			}
			d.why = "|s - 1| >= threshold";
		}
		d.kind = ScaleDecision::Kind::Correction;
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
