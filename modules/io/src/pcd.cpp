#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/io/pcd.h>

#include "pcd_header.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace vlo
{
namespace
{
static_assert(sizeof(float) == 4, "PCD F4 fields are IEEE float32");

bool littleEndianHost()
{
	const std::uint16_t one = 1;
	unsigned char b;
	std::memcpy(&b, &one, 1);
	return b == 1;
}

void keep(PointCloud& out, double x, double y, double z, double i)
{
	if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return;
	out.push_back({float(x), float(y), float(z), std::isfinite(i) ? float(i) : 0.f});
}

PointCloud readAscii(std::istream& in, const PcdHeader& h, const std::string& path, size_t lineNo)
{
	PointCloud out;
	out.reserve(h.points);
	std::string line;
	size_t n = 0;
	while (n < h.points && std::getline(in, line))
	{
		++lineNo;
		if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
		std::istringstream ss(line);
		std::vector<double> v;
		std::string tok;
		while (ss >> tok)
		{
			char* end = nullptr;
			const double d = std::strtod(tok.c_str(), &end);  // also accepts "nan"
			if (*end != '\0') failInput(path, "line " + std::to_string(lineNo) + ": '" + tok + "' is not a number");
			v.push_back(d);
		}
		if (v.size() != h.valuesPerPoint())
			failInput(path, "line " + std::to_string(lineNo) + ": expected " + std::to_string(h.valuesPerPoint()) +
					" values, found " + std::to_string(v.size()));
		keep(out, v[h.value(h.x)], v[h.value(h.y)], v[h.value(h.z)], h.i < 0 ? 0.0 : v[h.value(h.i)]);
		++n;
	}
	if (n < h.points)
		failInput(path, "truncated: header says " + std::to_string(h.points) + " points, found " + std::to_string(n));
	return out;
}

PointCloud readBinary(std::istream& in, const PcdHeader& h, const std::string& path)
{
	if (!littleEndianHost()) failInput(path, "binary PCD needs a little-endian host");
	const size_t step = h.bytesPerPoint();
	std::vector<char> buf(step * h.points);
	in.read(buf.data(), std::streamsize(buf.size()));
	if (size_t(in.gcount()) != buf.size())
		failInput(path, "truncated: header says " + std::to_string(h.points) + " points (" +
				std::to_string(buf.size()) + " bytes) but only " + std::to_string(in.gcount()) + " bytes follow");
	PointCloud out;
	out.reserve(h.points);
	for (size_t k = 0; k < h.points; ++k)
	{
		const char* p = buf.data() + k * step;
		keep(out, h.read(p, h.x), h.read(p, h.y), h.read(p, h.z), h.i < 0 ? 0.0 : h.read(p, h.i));
	}
	return out;
}
}  // namespace

void writePcd(const std::string& path, const PointCloud& cloud, PcdFormat format)
{
	const bool binary = format == PcdFormat::Binary;
	if (binary && !littleEndianHost()) failInput(path, "binary PCD needs a little-endian host");
	AtomicOutputFile f(path, true);
	auto& out = f.stream();
	out << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\n"
		<< "TYPE F F F F\nCOUNT 1 1 1 1\nWIDTH " << cloud.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS "
		<< cloud.size() << "\nDATA " << (binary ? "binary" : "ascii") << "\n";
	if (binary)
	{
		std::vector<float> packed;
		packed.reserve(4 * cloud.size());
		for (const auto& p : cloud) packed.insert(packed.end(), {p.x, p.y, p.z, p.intensity});
		out.write(reinterpret_cast<const char*>(packed.data()), std::streamsize(packed.size() * sizeof(float)));
	}
	else
	{
		out.precision(9);  // float32 round-trips exactly with 9 significant digits
		for (const auto& p : cloud) out << p.x << ' ' << p.y << ' ' << p.z << ' ' << p.intensity << '\n';
	}
	f.commit();
}

PointCloud readPcd(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) failInput(path, "cannot open file");
	size_t lineNo = 0;
	const PcdHeader h = readPcdHeader(in, path, lineNo);
	return h.binary ? readBinary(in, h, path) : readAscii(in, h, path, lineNo);
}
}  // namespace vlo
