#include <vlo/loam/ring_count.h>

#include <vlo/core/error.h>
#include <vlo/core/units.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace vlo::loam
{
namespace
{
constexpr double kColumnDeg = 0.2;  // about one firing of a VLP-16, two of an HDL-64 at 10 Hz
constexpr double kBeamGapDeg = 0.15;  // under half the finest beam spacing (HDL-64: 1/3 deg)
constexpr double kMinRho = 2.0;  // nearer returns: each beam's own origin spreads their elevations
constexpr std::size_t kMinReturns = 5000;
constexpr std::size_t kScansToJudge = 3;

template <class T>
T quantile(std::vector<T> v, double q)
{
	const auto k = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
	std::nth_element(v.begin(), k, v.end());
	return *k;
}

RingEvidence fromRingIds(const PointCloud& scan)
{
	std::set<std::uint16_t> ids;
	for (const auto& p : scan) ids.insert(p.ring);
	RingEvidence e;
	e.rings = static_cast<int>(ids.size());
	e.from_ids = true;
	return e;
}

/// The beams of each azimuth column: its returns sorted by elevation, a new beam at each gap.
RingEvidence fromElevations(const PointCloud& scan)
{
	const int n_columns = static_cast<int>(std::lround(360.0 / kColumnDeg));
	std::vector<std::vector<float>> columns(n_columns);
	std::size_t n = 0;
	for (const auto& p : scan)
	{
		const double rho = std::hypot(p.x, p.y);
		if (!std::isfinite(rho) || !std::isfinite(p.z) || rho < kMinRho) continue;
		const double az = std::atan2(p.y, p.x) * kDegPerRad + 180.0;
		const int c = std::clamp(static_cast<int>(az / kColumnDeg), 0, n_columns - 1);
		columns[c].push_back(static_cast<float>(std::atan2(p.z, rho) * kDegPerRad));
		++n;
	}
	RingEvidence e;
	if (n < kMinReturns) return e;
	std::vector<int> beams;
	std::vector<double> spacing, lowest, highest;
	for (auto& col : columns)
	{
		if (col.empty()) continue;
		std::sort(col.begin(), col.end());
		int b = 1;
		for (std::size_t i = 1; i < col.size(); ++i) b += col[i] - col[i - 1] > kBeamGapDeg ? 1 : 0;
		beams.push_back(b);
		if (b < 4) continue;  // a column with a few beams says little of the spacing
		spacing.push_back((col.back() - col.front()) / (b - 1));
		lowest.push_back(col.front());
		highest.push_back(col.back());
	}
	if (spacing.size() < 100) return e;
	e.spacing_deg = quantile(spacing, 0.5);
	// The 90th percentile: many columns miss beams (sky, dropouts), few gain a spurious one.
	const double span = quantile(highest, 0.98) - quantile(lowest, 0.02);
	e.rings = std::max(quantile(beams, 0.9), static_cast<int>(std::lround(span / e.spacing_deg)) + 1);
	return e;
}
}  // namespace

RingEvidence countRings(const PointCloud& scan)
{
	if (scan.has_ring) return scan.size() < kMinReturns ? RingEvidence{} : fromRingIds(scan);
	return fromElevations(scan);
}

std::string ringModelAdvice(int rings)
{
	if (rings >= 52 && rings <= 80) return "use ini/kitti-hdl64.ini or ring_model = hdl64";
	if (rings >= 13 && rings <= 20) return "use ini/vlp16.ini or ring_model = uniform with n_rings = 16";
	if (rings >= 26 && rings <= 40) return "use ini/hdl32.ini or ring_model = uniform with n_rings = 32";
	return "use ring_model = uniform with n_rings = " + std::to_string(rings) +
		" and the sensor's vfov_min_deg, vfov_max_deg (or ring_model = table)";
}

RingModelCheck::RingModelCheck(std::string ini, const ScanOptions& o, const std::vector<double>& model_elevations_deg)
	: ini_(std::move(ini)),
	  model_(o.ring_model),
	  model_rings_(static_cast<int>(model_elevations_deg.size())),
	  model_spacing_deg_((model_elevations_deg.back() - model_elevations_deg.front()) / (model_rings_ - 1))
{
}

void RingModelCheck::observe(const PointCloud& scan)
{
	if (done_) return;
	const RingEvidence e = countRings(scan);
	if (e.rings > 0) seen_.push_back(e);
	if (seen_.size() < kScansToJudge) return;
	done_ = true;
	std::vector<int> rings;
	std::vector<double> spacing;
	for (const auto& s : seen_) rings.push_back(s.rings), spacing.push_back(s.spacing_deg);
	const int n = quantile(rings, 0.5);
	const bool fewer = e.from_ids ? 2 * n <= model_rings_ : quantile(spacing, 0.5) >= 2 * model_spacing_deg_;
	if (2 * n >= 3 * model_rings_ || fewer)
		failInput(ini_,
			"[loam.scan] ring model " + model_ + " (" + std::to_string(model_rings_) +
				" rings) but the scans have " + std::to_string(n) + " rings (" +
				(e.from_ids ? "their ring ids" : "beams counted per azimuth column") + "): " +
				ringModelAdvice(n));
}
}  // namespace vlo::loam
