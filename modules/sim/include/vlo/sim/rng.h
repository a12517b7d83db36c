#pragma once
// Deterministic random numbers. The standard distributions are implementation-defined, so the
// simulator draws from its own: the same seed gives the same world, drive and noise everywhere.
#include <cstdint>
#include <string_view>

namespace vlo::sim
{
class Rng
{
   public:
	explicit Rng(uint64_t seed) : state_(seed) {}
	/// An independent stream per purpose ("buildings", "image noise" of frame k): changing how many
	/// numbers one part draws never changes what another part gets.
	static Rng stream(uint64_t seed, std::string_view purpose, uint64_t index = 0);

	uint64_t next();  ///< splitmix64
	double uniform();  ///< [0, 1)
	double uniform(double a, double b) { return a + (b - a) * uniform(); }
	int integer(int lo, int hi);  ///< inclusive
	double normal();  ///< standard normal (Box-Muller)
	bool chance(double p) { return uniform() < p; }

   private:
	uint64_t state_;
	double spare_ = 0;
	bool has_spare_ = false;
};

/// Stateless hash of integer coordinates to [0, 1): the basis of the procedural textures.
double hash01(int64_t x, int64_t y, uint64_t seed);
/// Smooth value noise in [0, 1) with one lattice cell per unit of x and y.
double valueNoise(double x, double y, uint64_t seed);
}  // namespace vlo::sim
