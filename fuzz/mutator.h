#pragma once
// Seeded mutations of a file's bytes, the kinds of damage real files suffer or hostile files carry:
// bit flips, truncations, huge counts, NaN/inf, wrong sizes (chunks cut out, repeated or inserted),
// and, for text, numbers replaced by extreme or malformed ones. Same seed, same mutations.
#include <cstdint>
#include <random>
#include <string>

namespace vlo::fuzz
{
class Mutator
{
   public:
	explicit Mutator(std::uint64_t seed) : rng_(seed) {}
	/// `original` with one to four mutations applied.
	std::string mutate(const std::string& original);

   private:
	std::size_t below(std::size_t n);  ///< uniform in [0, n), 0 when n is 0
	std::size_t offset(const std::string& data);  ///< biased towards the first kilobyte (headers, counts)
	void flipBits(std::string& data);
	void randomBytes(std::string& data);
	void truncate(std::string& data);
	void hugeCount(std::string& data);
	void nanInf(std::string& data);
	void deleteChunk(std::string& data);
	void duplicateChunk(std::string& data);
	void insertBytes(std::string& data);
	void replaceNumber(std::string& data);
	void replaceSeparator(std::string& data);

	std::mt19937_64 rng_;
};
}  // namespace vlo::fuzz
