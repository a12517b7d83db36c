#include "mutator.h"

#include <cctype>
#include <cstring>
#include <limits>
#include <vector>

namespace vlo::fuzz
{
namespace
{
template <typename T>
void overwrite(std::string& data, std::size_t at, T value)
{
	if (at + sizeof(T) > data.size()) return;
	std::memcpy(&data[at], &value, sizeof(T));
}

/// [begin, end) of every run of characters that can make up a number in text.
std::vector<std::pair<std::size_t, std::size_t>> numberTokens(const std::string& data)
{
	std::vector<std::pair<std::size_t, std::size_t>> tokens;
	const auto numeric = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || std::strchr("+-.eE", c); };
	for (std::size_t i = 0; i < data.size();)
	{
		if (!numeric(data[i]) || !data[i])
		{
			++i;
			continue;
		}
		const std::size_t b = i;
		while (i < data.size() && data[i] && numeric(data[i])) ++i;
		tokens.emplace_back(b, i);
	}
	return tokens;
}
}  // namespace

std::size_t Mutator::below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n); }

std::size_t Mutator::offset(const std::string& data)
{
	return below(rng_() % 2 ? std::min<std::size_t>(data.size(), 1024) : data.size());
}

void Mutator::flipBits(std::string& data)
{
	if (data.empty()) return;
	for (std::size_t k = 1 + below(8); k > 0; --k) data[offset(data)] ^= static_cast<char>(1u << below(8));
}

void Mutator::randomBytes(std::string& data)
{
	if (data.empty()) return;
	const std::size_t at = offset(data);
	for (std::size_t k = 0, n = 1 + below(8); k < n && at + k < data.size(); ++k) data[at + k] = static_cast<char>(rng_());
}

void Mutator::truncate(std::string& data) { data.resize(below(data.size() + 1)); }

void Mutator::hugeCount(std::string& data)
{
	static const std::uint64_t values[] = {0xFFFFFFFFull, 0x7FFFFFFFull, 0x80000000ull, 0x40000000ull, 0x10000000ull,
		0x00FFFFFFull, 0xFFFFull, 0xFFFFFFFFFFFFFFFFull, 1ull << 40, 1ull << 62};
	const std::uint64_t v = values[below(std::size(values))];
	std::size_t at = offset(data);
	if (rng_() % 2) at &= ~std::size_t{3};  // counts are often 4-byte aligned
	if (rng_() % 2 || v > 0xFFFFFFFFull)
		overwrite<std::uint64_t>(data, at, v);
	else
		overwrite<std::uint32_t>(data, at, static_cast<std::uint32_t>(v));
}

void Mutator::nanInf(std::string& data)
{
	const std::size_t at = offset(data) & ~std::size_t{3};
	switch (below(6))
	{
		case 0: overwrite(data, at, std::numeric_limits<float>::quiet_NaN()); break;
		case 1: overwrite(data, at, std::numeric_limits<float>::infinity()); break;
		case 2: overwrite(data, at, -std::numeric_limits<float>::max()); break;
		case 3: overwrite(data, at, std::numeric_limits<float>::denorm_min()); break;
		case 4: overwrite(data, at, std::numeric_limits<double>::quiet_NaN()); break;
		default: overwrite(data, at, -std::numeric_limits<double>::infinity()); break;
	}
}

void Mutator::deleteChunk(std::string& data)
{
	const std::size_t at = offset(data);
	data.erase(at, 1 + below(64));
}

void Mutator::duplicateChunk(std::string& data)
{
	const std::size_t at = offset(data);
	const std::string chunk = data.substr(at, 1 + below(256));
	data.insert(below(data.size() + 1), chunk);
}

void Mutator::insertBytes(std::string& data)
{
	std::string bytes(1 + below(16), '\0');
	for (char& c : bytes) c = static_cast<char>(rng_());
	data.insert(offset(data), bytes);
}

void Mutator::replaceNumber(std::string& data)
{
	static const char* const values[] = {"nan", "-nan", "inf", "-inf", "1e400", "-1e400", "1e-400", "4294967295",
		"-2147483649", "99999999999999999999999", "1e308", "0", "-0", "", "1..2", "0x1p3", "+", "e"};
	const auto tokens = numberTokens(data);
	if (tokens.empty()) return;
	const auto [b, e] = tokens[below(tokens.size())];
	data.replace(b, e - b, values[below(std::size(values))]);
}

void Mutator::replaceSeparator(std::string& data)
{
	static const char separators[] = {' ', '\t', '\n', '\r', ':', '=', '[', ']', '#', ',', '\0'};
	for (int tries = 0; tries < 16 && !data.empty(); ++tries)
	{
		const std::size_t at = below(data.size());
		if (std::strchr(" \t\n:=[]#,", data[at]) && data[at])
		{
			data[at] = separators[below(std::size(separators))];
			return;
		}
	}
}

std::string Mutator::mutate(const std::string& original)
{
	std::string data = original;
	for (std::size_t k = 1 + below(4); k > 0; --k)
	{
		switch (below(11))
		{
			case 0: flipBits(data); break;
			case 1: randomBytes(data); break;
			case 2: truncate(data); break;
			case 3: hugeCount(data); break;
			case 4: nanInf(data); break;
			case 5: deleteChunk(data); break;
			case 6: duplicateChunk(data); break;
			case 7: insertBytes(data); break;
			case 8: replaceSeparator(data); break;
			default: replaceNumber(data); break;  // twice as likely: text readers are mostly numbers
		}
	}
	return data;
}
}  // namespace vlo::fuzz
