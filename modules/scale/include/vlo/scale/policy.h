#pragma once
// When to apply a scale estimate to the VO map (paper III-C): the first valid estimate after the VO's
// initialisation sets the metric scale; afterwards a correction only when |s - 1| >= 2 % (option),
// because every correction disturbs the local mapping. The paper applies each estimate as is
// (correction_window = 1); by default the median of the last 15 (correction_window) decides, which also ignores the odd
// outlier (see ScaleOptions).
#include <vlo/scale/diagnostics.h>
#include <vlo/scale/options.h>

#include <deque>

namespace vlo::scale
{
struct ScaleDecision
{
	enum class Kind
	{
		Skip,  ///< nothing to apply (see `why`)
		Initial,  ///< first metric scale of the map
		Correction  ///< drift correction
	};
	Kind kind = Kind::Skip;
	double factor = 1.0;  ///< multiply the VO local map (about its earliest keyframe) by this
	const char* why = "";

	bool apply() const { return kind != Kind::Skip; }
};
const char* toString(ScaleDecision::Kind k);

class ScaleCorrectionPolicy
{
   public:
	/// Uses correction_threshold and correction_enabled. Throws InputError for invalid options.
	explicit ScaleCorrectionPolicy(const ScaleOptions& opt = {});

	/// The caller applies `factor` to the VO map when apply() is true, before the next estimate.
	ScaleDecision decide(const ScaleEstimate& e);

	/// The VO lost its map and re-initialised at an unknown scale: the next estimate is initial again.
	void reset();
	bool hasMetricScale() const { return initialized_; }
	/// Product of every applied factor since the last reset (VO units of the initial map -> metres).
	double cumulative() const { return cumulative_; }
	int corrections() const { return corrections_; }

   private:
	double threshold_;
	double refine_threshold_;  ///< for the first full window after the initial estimate
	double early_sigmas_;  ///< that window corrects before it is full when this sure (0: never)
	bool refined_ = false;  ///< that window has decided since the last reset
	bool enabled_;
	std::size_t window_;
	std::deque<double> recent_;  ///< valid estimates since the last applied factor
	bool initialized_ = false;
	double cumulative_ = 1.0;
	int corrections_ = 0;
};
}  // namespace vlo::scale
