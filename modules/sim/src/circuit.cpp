#include <vlo/sim/circuit.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kLap = 504;  // m: 21 repeats of the road texture (24 m), 63 of the curb and grass (8 m)
constexpr double kStation = 0.5;  // m between stations
constexpr int kSubsteps = 50;  // integration steps per station
constexpr double kLane = 1.75, kParkingLane = 3.9;  // m off the centre line: driving lane, U-turn
constexpr double kEaseIn = 16;  // m over which the vehicle moves into the parking lane before a U-turn

struct Piece
{
	double length, curvature;
};

/// The lap before it is closed and scaled: `north` and `west` are the two straights the closure
/// solves for (they run along world +y and -x).
std::vector<Piece> layout(double north, double west)
{
	const double quarter = M_PI / 2, eighth = M_PI / 4, twelfth = M_PI / 6;
	return {{50, 0}, {quarter * 13, 1 / 13.0}, {north, 0}, {eighth * 30, 1 / 30.0}, {25, 0}, {eighth * 30, 1 / 30.0}, {west, 0},
		{quarter * 14, 1 / 14.0}, {40, 0}, {twelfth * 40, -1 / 40.0}, {12, 0}, {twelfth * 40, 1 / 40.0}, {30, 0},
		{quarter * 20, 1 / 20.0}, {50, 0}};
}
constexpr int kWest = 6, kParkFirst = 8, kParkLast = 12;  // pieces: the west straight; the park's stretch

double startOf(const std::vector<Piece>& pieces, std::size_t i)
{
	double s = 0;
	for (std::size_t j = 0; j < i; ++j) s += pieces[j].length;
	return s;
}

/// Curvature at s: each change ramps linearly over at most 8 m centred on it, so every corner still
/// turns by its angle.
double curvatureAt(const std::vector<Piece>& pieces, double s)
{
	double start = 0;
	for (std::size_t i = 0; i < pieces.size(); ++i)
	{
		const double end = start + pieces[i].length;
		for (std::size_t j : {i, i + 1})  // the ramps at this piece's two ends
		{
			if (j == 0 || j >= pieces.size()) continue;
			const double b = j == i ? start : end, w = std::min(8.0, 0.8 * std::min(pieces[j - 1].length, pieces[j].length));
			if (std::abs(s - b) <= w / 2)
				return pieces[j - 1].curvature + (s - (b - w / 2)) / w * (pieces[j].curvature - pieces[j - 1].curvature);
		}
		if (s < end || i + 1 == pieces.size()) return pieces[i].curvature;
		start = end;
	}
	return 0;
}

/// Heading and position every 1/n of the lap (n + 1 samples, midpoint integration in between).
struct Sampled
{
	std::vector<double> heading;
	std::vector<Eigen::Vector2d> p;
};

Sampled integrate(const std::vector<Piece>& pieces, int n)
{
	const double length = startOf(pieces, pieces.size()), h = length / (n * kSubsteps);
	Sampled out;
	double heading = 0;
	Eigen::Vector2d p = Eigen::Vector2d::Zero();
	for (int i = 0; i <= n; ++i)
	{
		out.heading.push_back(heading);
		out.p.push_back(p);
		if (i == n) break;
		for (int k = 0; k < kSubsteps; ++k)
		{
			const double dh = curvatureAt(pieces, (i * kSubsteps + k + 0.5) * h) * h;
			p += h * Eigen::Vector2d(std::cos(heading + dh / 2), std::sin(heading + dh / 2));
			heading += dh;
		}
	}
	return out;
}

/// Height of the lap at s: two waves that fit the lap, so the road closes in height too.
double heightAt(double s) { return 1.2 * std::sin(2 * M_PI * s / kLap) + 0.5 * std::sin(4 * M_PI * s / kLap + 1.0) - 0.5 * std::sin(1.0); }
double gradeAt(double s)
{
	return 1.2 * 2 * M_PI / kLap * std::cos(2 * M_PI * s / kLap) + 0.5 * 4 * M_PI / kLap * std::cos(4 * M_PI * s / kLap + 1.0);
}

double ease(double u)
{
	u = std::clamp(u, 0.0, 1.0);
	return 0.5 - 0.5 * std::cos(M_PI * u);
}
}  // namespace

Circuit cityBlockCircuit()
{
	// Lengthening a straight moves the end of the lap along it: two straights at right angles close
	// it (a linear solve, repeated for the integration's small non-linearity).
	const int n = static_cast<int>(kLap / kStation);
	double north = 60, west = 60;
	for (int it = 0; it < 3; ++it)
	{
		const Eigen::Vector2d gap = integrate(layout(north, west), n).p.back();
		north -= gap.y(), west += gap.x();
	}
	const std::vector<Piece> pieces = layout(north, west);
	const Sampled lap = integrate(pieces, n);
	const double scale = kLap / startOf(pieces, pieces.size());
	std::vector<Station> st;
	for (int i = 0; i <= n; ++i)
	{
		Station x;
		x.s = i * kStation;
		const Eigen::Vector2d xy = i == n ? lap.p.front() : lap.p[i];  // the last station lies on the first
		x.p = Eigen::Vector3d(scale * xy.x(), scale * xy.y(), heightAt(x.s));
		x.heading = i == n ? 2 * M_PI : lap.heading[i];
		x.grade = gradeAt(x.s);
		x.curvature = curvatureAt(pieces, x.s / scale) / scale;
		st.push_back(x);
	}
	Circuit c;
	c.road = Road(std::move(st), true);
	c.turning_places = {0, scale * (startOf(pieces, kWest) + pieces[kWest].length / 2)};
	c.park_from = scale * startOf(pieces, kParkFirst), c.park_to = scale * startOf(pieces, kParkLast + 1);
	return c;
}

double turnaroundDistance(const Circuit& c, double laps)
{
	if (laps <= 0) return 0;
	const double L = c.road.length(), want = laps * L;
	double best = 0;
	for (double t : c.turning_places)
		for (double d = t; d <= want + L; d += L)
			if (d >= L / 4 && (best == 0 || std::abs(d - want) < std::abs(best - want))) best = d;
	return best;
}

Road lapPath(const Circuit& c, double distance, double turn_at)
{
	constexpr double kStep = 0.25;
	const Road& r = c.road;
	std::vector<Eigen::Vector3d> pts;
	const bool turns = turn_at > 0 && turn_at < distance;
	const double forward = turns ? turn_at : distance;
	for (double d = 0; d < forward; d += kStep)
	{
		const double swing = turns ? ease((d - (turn_at - kEaseIn)) / kEaseIn) : 0;
		pts.push_back(r.point(d, -kLane - (kParkingLane - kLane) * swing));
	}
	if (turns)
	{
		// A half circle to the left about the centre line, from one parking lane to the other.
		const int n = static_cast<int>(std::ceil(M_PI * kParkingLane / kStep));
		for (int i = 0; i <= n; ++i)
		{
			const double a = M_PI * i / n;
			pts.push_back(r.point(turn_at + kParkingLane * std::sin(a), -kParkingLane * std::cos(a)));
		}
		for (double back = kStep; turn_at + M_PI * kParkingLane + back < distance; back += kStep)
			pts.push_back(r.point(turn_at - back, kParkingLane - (kParkingLane - kLane) * ease(back / kEaseIn)));
	}
	return roadThrough(pts, 0, kStep);
}
}  // namespace vlo::sim
