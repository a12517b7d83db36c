#include <vlo/sim/rng.h>
#include <vlo/sim/traffic.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlo::sim
{
namespace
{
constexpr double kStep = 0.05, kPad = 0.5;  // s: the ego's arc length table
// Lateral positions (m left of the centre line). Oncoming traffic keeps to the outer part of its lane
// and overtakers pass astride the centre line, so that neither touches the ego vehicle (1.8 m wide,
// weaving 0.25 m about -1.75 m) nor each other (bodies at most 2.2 m wide, overtakers 1.8 m).
constexpr double kOwnLane = -1.75, kPassing = 0.35, kOncoming = 2.45;
constexpr double kPassNear = 12, kPassFar = 30;  // m of gap to the ego: fully out / back in lane

Vehicle shaped(VehicleKind kind, int paint)
{
	using namespace vehicle_tex;
	Vehicle v;
	v.kind = kind, v.paint = paint;
	const int side = bodySide(paint), top = bodyTop(paint);
	switch (kind)
	{
		case VehicleKind::Car:  // as the parked cars (props.cpp)
			v.length = 4.5, v.width = 1.8;
			v.parts = {{0, 0.15, 4.5, 1.8, 0.85, side, top}, {-0.25, 1.0, 2.6, 1.6, 0.5, kCabinSide, top}};
			break;
		case VehicleKind::Van:
			v.length = 5.2, v.width = 2.0;
			v.parts = {{0, 0.2, 5.2, 2.0, 1.0, side, top}, {-0.3, 1.2, 4.6, 2.0, 1.1, kCargoSide, kCargoTop}};
			break;
		case VehicleKind::Truck:
			v.length = 7.6, v.width = 2.2;
			v.parts = {{2.9, 0.35, 1.8, 2.2, 2.3, kCabinSide, top}, {-1.0, 0.35, 5.6, 1.2, 0.55, side, top},
				{-1.0, 0.9, 5.6, 2.2, 2.6, kCargoSide, kCargoTop}};
			break;
	}
	return v;
}

double smoothstep(double a, double b, double x)
{
	const double u = std::clamp((x - a) / (b - a), 0.0, 1.0);
	return u * u * (3 - 2 * u);
}

/// Arc length of the road point nearest to xy, searched among stations within 40 m of `guess`.
double project(const Road& road, const Eigen::Vector2d& xy, double guess)
{
	const auto& st = road.stations();
	double best = std::numeric_limits<double>::max();
	const Station* nearest = &st.front();
	for (const Station& s : st)
	{
		if (std::abs(s.s - guess) > 40) continue;
		const double d = (s.p.head<2>() - xy).squaredNorm();
		if (d < best) best = d, nearest = &s;
	}
	const Eigen::Vector2d along(std::cos(nearest->heading), std::sin(nearest->heading));
	return nearest->s + along.dot(xy - nearest->p.head<2>());
}

/// Start positions spread over [lo, hi], at least `gap` m apart, sorted by decreasing arc length.
std::vector<double> spread(Rng& rng, int n, double lo, double hi, double gap)
{
	std::vector<double> s;
	for (int i = 0; i < n; ++i) s.push_back(rng.uniform(lo, hi));
	std::sort(s.rbegin(), s.rend());
	for (std::size_t i = 1; i < s.size(); ++i) s[i] = std::min(s[i], s[i - 1] - gap);
	return s;
}
}  // namespace

Traffic::Traffic(const Road& road, const VehicleMotion& ego, double duration, int count, uint64_t seed) : road_(&road)
{
	if (count <= 0 || road.stations().empty()) return;
	const Station* first = road.nearest(ego.pose(-kPad).translation().head<2>(), 30);
	double s = first ? first->s : 0;
	for (double t = -kPad; t <= duration + kPad; t += kStep)
		egoS_.push_back(s = project(road, ego.pose(t).translation().head<2>(), s));
	double vmax = 0;
	for (std::size_t k = 1; k < egoS_.size(); ++k) vmax = std::max(vmax, (egoS_[k] - egoS_[k - 1]) / kStep);
	const double T = std::max(duration, 1.0), s0 = egoArcLength(0);
	const double vbar = std::max(0.0, (egoArcLength(duration) - s0) / T);

	Rng rng = Rng::stream(seed, "traffic");
	const int oncoming = (count + 1) / 2, same = count - oncoming;
	// Same direction: cars faster than the ego's top speed, starting behind it, so every one of them
	// that reaches it within the drive overtakes it. The one in front is the fastest: nobody catches up.
	const double vSameMin = vmax + 1.5, vSameMax = vmax + 5;
	std::vector<double> speeds;
	for (int i = 0; i < same; ++i) speeds.push_back(rng.uniform(vSameMin, vSameMax));
	std::sort(speeds.rbegin(), speeds.rend());
	const double behind = (0.5 * (vSameMin + vSameMax) - vbar) * T + 60;
	const std::vector<double> sameStart = spread(rng, same, s0 - 12 - behind, s0 - 12, 9);
	for (int i = 0; i < same; ++i)
	{
		Vehicle v = shaped(VehicleKind::Car, rng.integer(0, vehicle_tex::kPaints - 1));
		v.s0 = sameStart[i], v.speed = speeds[i], v.direction = 1;
		vehicles_.push_back(v);
	}
	// Oncoming: cars, vans and a few trucks, spread ahead so that they keep meeting the ego vehicle.
	// The one furthest along its way (smallest arc length) is the fastest.
	const double vOnMax = std::max(vmax, 10.0), vOnMin = 0.6 * vOnMax;
	speeds.clear();
	for (int i = 0; i < oncoming; ++i) speeds.push_back(rng.uniform(vOnMin, vOnMax));
	std::sort(speeds.begin(), speeds.end());
	const double ahead = (0.5 * (vOnMin + vOnMax) + vbar) * T + 60;
	const std::vector<double> onStart = spread(rng, oncoming, s0 + 15, s0 + 15 + ahead, 13);
	for (int i = 0; i < oncoming; ++i)
	{
		const double k = rng.uniform();
		const VehicleKind kind = k < 0.6 ? VehicleKind::Car : k < 0.85 ? VehicleKind::Van
																	   : VehicleKind::Truck;
		Vehicle v = shaped(kind, rng.integer(0, vehicle_tex::kPaints - 1));
		v.s0 = onStart[i], v.speed = speeds[i], v.direction = -1;
		vehicles_.push_back(v);
	}
}

double Traffic::egoArcLength(double t) const
{
	const double x = std::clamp((t + kPad) / kStep, 0.0, static_cast<double>(egoS_.size() - 1));
	const std::size_t k = std::min(static_cast<std::size_t>(x), egoS_.size() - 2);
	return egoS_[k] + (x - k) * (egoS_[k + 1] - egoS_[k]);
}

double Traffic::arcLength(std::size_t i, double t) const
{
	const Vehicle& v = vehicles_.at(i);
	return v.s0 + v.direction * v.speed * t;
}

bool Traffic::present(std::size_t i, double t) const
{
	const double s = arcLength(i, t), half = vehicles_[i].length / 2 + 1;
	return s >= half && s <= road_->length() - half;
}

double Traffic::lateral(std::size_t i, double t) const
{
	const Vehicle& v = vehicles_.at(i);
	if (v.direction < 0) return kOncoming;
	const double gap = std::abs(arcLength(i, t) - egoArcLength(t));
	return kOwnLane + (kPassing - kOwnLane) * (1 - smoothstep(kPassNear, kPassFar, gap));
}

Eigen::Isometry3d Traffic::pose(std::size_t i, double t) const
{
	auto at = [&](double tt) { return road_->point(arcLength(i, tt), lateral(i, tt)); };
	constexpr double h = 0.05;
	// Heading along the path actually driven (lane changes included), on the road's grade.
	const Eigen::Vector3d x = (at(t + h) - at(t - h)).normalized();
	const Eigen::Vector3d y = Eigen::Vector3d::UnitZ().cross(x).normalized();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << x, y, x.cross(y);
	T.translation() = at(t);
	return T;
}

std::vector<std::size_t> Traffic::near(const Eigen::Vector3d& p, double radius, double t, double slack) const
{
	std::vector<std::size_t> out;
	for (std::size_t i = 0; i < vehicles_.size(); ++i)
	{
		if (!present(i, t - slack) && !present(i, t + slack)) continue;
		const Vehicle& v = vehicles_[i];
		const double reach = std::hypot(v.length / 2, v.width / 2) + 4 + v.speed * slack;
		const Eigen::Vector3d c = road_->point(arcLength(i, t), lateral(i, t));
		if ((c - p).norm() <= radius + reach) out.push_back(i);
	}
	return out;
}

int Traffic::countWithin(const Eigen::Vector3d& p, double radius, double t) const
{
	int n = 0;
	for (std::size_t i = 0; i < vehicles_.size(); ++i) n += present(i, t) && (pose(i, t).translation() - p).norm() <= radius;
	return n;
}

std::vector<Traffic::Placed> Traffic::placed(const std::vector<std::size_t>& candidates, double t) const
{
	std::vector<Placed> out;
	for (std::size_t i : candidates)
		if (present(i, t)) out.push_back({&vehicles_[i], pose(i, t).inverse()});
	return out;
}

int Traffic::raycast(const std::vector<Placed>& placed, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_range,
	double& range)
{
	double best = max_range;
	int slot = -1;
	for (const Placed& pl : placed)
	{
		const Eigen::Vector3d ov = pl.vehicle_T_world * o, dv = pl.vehicle_T_world.linear() * d;
		for (const VehiclePart& part : pl.vehicle->parts)
		{
			const Eigen::Vector3d lo(part.x - part.sx / 2, -part.sy / 2, part.z0), hi(part.x + part.sx / 2, part.sy / 2, part.z0 + part.sz);
			double t0 = 0, t1 = best;
			int entry = -1;  // axis of the face the ray enters through
			for (int a = 0; a < 3 && t0 <= t1; ++a)
			{
				if (std::abs(dv[a]) < 1e-12)
				{
					if (ov[a] < lo[a] || ov[a] > hi[a]) t0 = t1 + 1;
					continue;
				}
				double ta = (lo[a] - ov[a]) / dv[a], tb = (hi[a] - ov[a]) / dv[a];
				if (ta > tb) std::swap(ta, tb);
				if (ta > t0) t0 = ta, entry = a;
				t1 = std::min(t1, tb);
			}
			if (t0 > t1 || entry < 0 || t0 <= 1e-9 || t0 >= best) continue;  // missed, or starts inside
			best = t0;
			slot = entry == 2 ? part.top_tex : part.side_tex;
		}
	}
	if (slot >= 0) range = best;
	return slot;
}
}  // namespace vlo::sim
