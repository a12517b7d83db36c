#include <vlo/core/error.h>

#include "pcd_header.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace vlo::io
{
namespace
{
std::size_t parseCount(const std::string& tok, const std::string& where)
{
	char* end = nullptr;
	const long long v = std::strtoll(tok.c_str(), &end, 10);
	if (tok.empty() || *end != '\0' || v < 0) failInput(where, "'" + tok + "' is not a non-negative integer");
	return std::size_t(v);
}
}  // namespace

std::size_t PcdHeader::bytesPerPoint() const
{
	std::size_t n = 0;
	for (const auto& f : fields) n += std::size_t(f.size) * f.count;
	return n;
}

PcdHeader readPcdHeader(std::istream& in, const std::string& path, std::size_t& lineNo)
{
	std::map<std::string, std::vector<std::string>> kv;
	std::string line, data;
	while (data.empty())
	{
		if (!std::getline(in, line)) failInput(path, "no DATA line: not a PCD file or truncated header");
		++lineNo;
		const std::string where = path + ": line " + std::to_string(lineNo);
		if (line.size() > 4096) failInput(where, "header line too long: not a PCD file");
		std::istringstream ss(line);
		std::string key, tok;
		if (!(ss >> key) || key[0] == '#') continue;
		static const std::string kKeys[] = {
			"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
		if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys))
			failInput(where, "'" + key.substr(0, 40) + "' is not a PCD header keyword");
		if (kv.count(key)) failInput(where, key + " given twice");
		auto& vals = kv[key];
		while (ss >> tok) vals.push_back(tok);
		if (vals.empty()) failInput(where, key + " has no value");
		if (key == "DATA") data = vals[0];
	}
	const std::string where = path + ": PCD header";
	for (const char* k : {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT"})
		if (!kv.count(k)) failInput(where, std::string("missing ") + k);
	if (data != "ascii" && data != "binary" && data != "binary_compressed")
		failInput(where, "DATA '" + data + "' is neither ascii, binary nor binary_compressed");

	PcdHeader h;
	h.binary = data == "binary";
	h.compressed = data == "binary_compressed";
	const auto& names = kv["FIELDS"];
	const std::size_t n = names.size();
	std::vector<std::string> counts = kv.count("COUNT") ? kv["COUNT"] : std::vector<std::string>(n, "1");
	if (kv["SIZE"].size() != n || kv["TYPE"].size() != n || counts.size() != n)
		failInput(where, std::to_string(n) + " FIELDS but SIZE, TYPE or COUNT has a different number of entries");
	std::size_t offset = 0, value = 0;
	for (std::size_t k = 0; k < n; ++k)
	{
		PcdField f;
		f.name = names[k];
		f.size = int(parseCount(kv["SIZE"][k], where + " SIZE"));
		const std::string& t = kv["TYPE"][k];
		f.type = t.size() == 1 ? t[0] : '?';
		f.count = int(parseCount(counts[k], where + " COUNT"));
		if (f.type != 'F' && f.type != 'I' && f.type != 'U')
			failInput(where, "field '" + f.name + "': TYPE '" + t + "' is not F, I or U");
		if ((f.size != 1 && f.size != 2 && f.size != 4 && f.size != 8) || (f.type == 'F' && f.size != 4 && f.size != 8))
			failInput(where, "field '" + f.name + "': SIZE " + std::to_string(f.size) + " is invalid for TYPE " + t);
		if (f.count < 1) failInput(where, "field '" + f.name + "': COUNT must be at least 1");
		f.offset = offset, f.value = value;
		offset += std::size_t(f.size) * f.count, value += f.count;
		if (f.name == "x")
			h.x = int(k);
		else if (f.name == "y")
			h.y = int(k);
		else if (f.name == "z")
			h.z = int(k);
		else if ((f.name == "intensity" || f.name == "i") && h.i < 0)
			h.i = int(k);
		h.fields.push_back(f);
	}
	if (h.x < 0 || h.y < 0 || h.z < 0) failInput(where, "FIELDS lacks x, y or z");
	const std::size_t wh =
		parseCount(kv["WIDTH"][0], where + " WIDTH") * parseCount(kv["HEIGHT"][0], where + " HEIGHT");
	h.points = kv.count("POINTS") ? parseCount(kv["POINTS"][0], where + " POINTS") : wh;
	if (h.points != wh)
		failInput(where, "POINTS " + std::to_string(h.points) + " differs from WIDTH x HEIGHT = " + std::to_string(wh));
	return h;
}
}  // namespace vlo::io
