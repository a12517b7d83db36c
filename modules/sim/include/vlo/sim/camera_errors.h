#pragma once
// A real camera's image errors (CameraRealism, doc/SIMULATOR.md "Realism"): lens and focus blur,
// auto-exposure changing the gain from frame to frame, signal-dependent (shot) and read noise.
#include <vlo/sim/realism.h>

#include <opencv2/core.hpp>

#include <cstdint>

namespace vlo::sim
{
class Rng;

/// The exposure gain of frame k: exp(x_k), x_k = sum_i a^i e_(k-i) of per-frame draws from `seed`
/// (the AR(1) process unrolled, so any frame can be rendered alone and gets the same gain).
double exposureGain(const CameraRealism& p, uint64_t seed, int k);

/// Blur, then the gain, then noise of variance read^2 + shot_gain * level, on a CV_32F image of grey
/// levels (0..255, not yet rounded).
void applyCameraErrors(cv::Mat& picture, const CameraRealism& p, double gain, Rng& rng);
}  // namespace vlo::sim
