#include "printable.h"

#include <vlo/core/error.h>
#include <vlo/io/kitti_files.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace vlo::io
{
std::size_t readKittiBin(const std::string& path, PointCloud& out)
{
	std::error_code ec;
	const auto bytes = std::filesystem::file_size(path, ec);
	if (ec) failInput(path, "cannot read Velodyne scan: " + ec.message());
	if (bytes % 16 != 0)
		failInput(path, "size " + std::to_string(bytes) + " bytes is not a multiple of 16 (float32 x, y, z, reflectance)");
	std::ifstream in(path, std::ios::binary);
	std::vector<float> raw(bytes / 4);
	if (!in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(bytes)))
		failInput(path, "cannot read Velodyne scan");
	out.clear();
	out.reserve(raw.size() / 4);
	for (std::size_t i = 0; i + 3 < raw.size(); i += 4)
	{
		const LidarPoint p{raw[i], raw[i + 1], raw[i + 2], raw[i + 3]};
		if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.intensity)) out.push_back(p);
	}
	return raw.size() / 4 - out.size();
}

void writeKittiBin(const std::string& path, const PointCloud& cloud)
{
	std::ofstream f(path, std::ios::binary);
	for (const auto& p : cloud)
	{
		const float v[4] = {p.x, p.y, p.z, p.intensity};
		f.write(reinterpret_cast<const char*>(v), sizeof(v));
	}
	if (!f) failInput(path, "cannot write Velodyne scan");
}

bool parseKittiDate(const std::string& text, double& seconds)
{
	std::tm tm{};
	int n = 0;
	if (std::sscanf(text.c_str(), "%d-%d-%d %d:%d:%d%n", &tm.tm_year, &tm.tm_mon, &tm.tm_mday, &tm.tm_hour, &tm.tm_min,
			&tm.tm_sec, &n) != 6)
		return false;
	// The fraction is parsed on its own: 9 digits would not survive a double holding the full date.
	double frac = 0;
	std::size_t pos = static_cast<std::size_t>(n);
	if (pos < text.size() && text[pos] == '.')
	{
		double scale = 0.1;
		for (++pos; pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos])); ++pos, scale *= 0.1)
			frac += (text[pos] - '0') * scale;
	}
	while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
	if (pos != text.size() || tm.tm_mon < 1 || tm.tm_mon > 12 || tm.tm_mday < 1 || tm.tm_mday > 31 || tm.tm_hour > 23 ||
		tm.tm_min > 59 || tm.tm_sec > 60)
		return false;
	tm.tm_year -= 1900;
	tm.tm_mon -= 1;
	seconds = static_cast<double>(timegm(&tm)) + frac;
	return true;
}

std::vector<double> readKittiRawTimestamps(const std::string& path)
{
	std::ifstream in(path);
	if (!in) failInput(path, "cannot open timestamps file");
	std::vector<double> times;
	std::string line;
	for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo)
	{
		if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
		double t = 0;
		if (!parseKittiDate(line, t))
			failInput(path, "line " + std::to_string(lineNo) + ": '" + printable(line) + "' is not a date like 2011-09-26 13:02:25.964389445");
		if (!times.empty() && t <= times.back())
			failInput(path, "line " + std::to_string(lineNo) + ": time is not after the previous one");
		times.push_back(t);
	}
	return times;
}
}  // namespace vlo::io
