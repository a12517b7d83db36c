#include <vlo/core/units.h>
#include <vlo/sim/lidar_errors.h>
#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kMaxTanIncidence = 10;  // 84 deg: beyond, the footprint term stops growing
}  // namespace

LidarErrors::LidarErrors(const LidarRealism& p, int lasers, uint64_t seed) : p_(p)
{
	Rng rng = Rng::stream(seed, "lidar calibration");
	for (int i = 0; i < lasers; ++i)
	{
		elevation_.push_back((p.common_elevation_error_deg + p.elevation_error_deg * rng.normal()) * kRadPerDeg);
		azimuth_.push_back(p.azimuth_error_deg * kRadPerDeg * rng.normal());
		range_.push_back(p.range_offset_m * rng.normal());
		gain_.push_back(std::max(0.0, 1 + p.intensity_gain_error * rng.normal()));
	}
}

double LidarErrors::detectionRange(uint8_t gray, double cos_incidence) const
{
	const double rho = p_.rho_dark + (p_.rho_bright - p_.rho_dark) * gray / 255.0;
	const double c = std::clamp(cos_incidence, 1e-4, 1.0);
	return p_.range_at_10_percent * std::sqrt(rho * std::pow(c, p_.incidence_exponent) / 0.1);
}

double LidarErrors::rangeSigma(double range, double cos_incidence, double detection_range) const
{
	const double weak = range / std::max(detection_range, 1e-6);
	const double echo = p_.base_sigma * (1 + weak * weak);
	// Ranges across the footprint on a tilted surface: uniform over +-r (divergence / 2) tan(incidence).
	const double c = std::clamp(cos_incidence, 1e-4, 1.0);
	const double tan_incidence = std::min(std::sqrt(1 - c * c) / c, kMaxTanIncidence);
	const double footprint = range * p_.divergence_mrad * 1e-3 / 2 * tan_incidence / std::sqrt(3.0);
	return std::hypot(echo, footprint);
}

bool LidarErrors::measure(int laser, const Echo& e, Rng& rng, double& range, float& intensity) const
{
	const double u_lost = rng.uniform(), u_detect = rng.uniform(), u_mixed = rng.uniform(), mix = rng.uniform();
	const double n_range = rng.normal(), n_intensity = rng.normal();
	double r = e.range;
	const double gap = e.edge_range > 0 ? e.edge_range - e.range : 0;
	if (std::abs(gap) > p_.edge_min_gap && std::abs(gap) < p_.mixed_max_gap && u_mixed < p_.mixed_probability) r += mix * gap;
	const double rmax = detectionRange(e.gray, e.cos_incidence);
	const double detect = 1 / (1 + std::exp((r - rmax) / (p_.detection_softness * rmax)));
	if (u_lost < p_.dropout || u_detect >= detect) return false;
	const auto i = static_cast<std::size_t>(laser);
	range = r + range_[i] + rangeSigma(r, e.cos_incidence, rmax) * n_range;
	const double rho = p_.rho_dark + (p_.rho_bright - p_.rho_dark) * e.gray / 255.0;
	const double echo = rho * std::pow(std::clamp(e.cos_incidence, 0.0, 1.0), p_.incidence_exponent);
	intensity = static_cast<float>(std::clamp(gain_[i] * echo + p_.intensity_noise * n_intensity, 0.0, 1.0));
	return true;
}

void dropPointTimes(PointCloud& cloud)
{
	const float scale = cloud.has_time || cloud.has_ring ? 1.0f / 255 : 1.0f;  // a rolling sweep's 8-bit intensity
	for (auto& p : cloud) p.time = 0, p.ring = 0, p.intensity *= scale;
	cloud.has_time = cloud.has_ring = false;
}
}  // namespace vlo::sim
