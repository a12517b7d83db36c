#include <vlo/sim/rng.h>

#include <cmath>

namespace vlo::sim
{
namespace
{
uint64_t mix(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}
}  // namespace

Rng Rng::stream(uint64_t seed, std::string_view purpose, uint64_t index)
{
	uint64_t h = 1469598103934665603ULL;  // FNV-1a of the purpose
	for (char c : purpose) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
	return Rng(mix(seed ^ mix(h) ^ mix(index + 0x9e3779b97f4a7c15ULL)));
}

uint64_t Rng::next()
{
	state_ += 0x9e3779b97f4a7c15ULL;
	return mix(state_);
}

double Rng::uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0); }

int Rng::integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<uint64_t>(hi - lo + 1)); }

double Rng::normal()
{
	if (has_spare_)
	{
		has_spare_ = false;
		return spare_;
	}
	double u = 0;
	while (u <= 1e-300) u = uniform();
	const double v = uniform(), r = std::sqrt(-2.0 * std::log(u)), a = 2.0 * M_PI * v;
	spare_ = r * std::sin(a);
	has_spare_ = true;
	return r * std::cos(a);
}

double hash01(int64_t x, int64_t y, uint64_t seed)
{
	const uint64_t h = mix(static_cast<uint64_t>(x) * 0x9e3779b97f4a7c15ULL ^ mix(static_cast<uint64_t>(y) + seed));
	return (h >> 11) * (1.0 / 9007199254740992.0);
}

double valueNoise(double x, double y, uint64_t seed)
{
	const double fx = std::floor(x), fy = std::floor(y);
	const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
	double tx = x - fx, ty = y - fy;
	tx = tx * tx * (3 - 2 * tx), ty = ty * ty * (3 - 2 * ty);
	const double a = hash01(ix, iy, seed), b = hash01(ix + 1, iy, seed);
	const double c = hash01(ix, iy + 1, seed), d = hash01(ix + 1, iy + 1, seed);
	return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
}
}  // namespace vlo::sim
