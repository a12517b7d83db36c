#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/core/input_file.h>
#include <vlo/io/pcd.h>

#include "pcd_header.h"

#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace vlo::io
{
namespace
{
/// PCL reports problems on stderr as well as in its return codes; vlo reports them once, as InputError.
void quietPcl() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }

/// The first element of `f` in the point at `p`, whatever its PCL type.
double readField(const std::uint8_t* p, const pcl::PCLPointField& f)
{
	auto as = [&](auto v) {
		std::memcpy(&v, p + f.offset, sizeof v);
		return double(v);
	};
	switch (f.datatype)
	{
		case pcl::PCLPointField::INT8: return as(std::int8_t());
		case pcl::PCLPointField::UINT8: return as(std::uint8_t());
		case pcl::PCLPointField::INT16: return as(std::int16_t());
		case pcl::PCLPointField::UINT16: return as(std::uint16_t());
		case pcl::PCLPointField::INT32: return as(std::int32_t());
		case pcl::PCLPointField::UINT32: return as(std::uint32_t());
		case pcl::PCLPointField::FLOAT32: return as(float());
		case pcl::PCLPointField::FLOAT64: return as(double());
		default: return NAN;
	}
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& c, const std::string& name)
{
	for (const auto& f : c.fields)
		if (f.name == name) return &f;
	return nullptr;
}

/// Checks the header strictly, and that a binary file holds all its points: PCL's reader trusts both.
void checkBeforePcl(const std::string& path)
{
	auto in = openInputFile(path, std::ios::binary);
	std::size_t lineNo = 0;
	const PcdHeader h = readPcdHeader(in, path, lineNo);
	if (!h.binary) return;
	const std::uint64_t bytes = h.bytesPerPoint() * std::uint64_t(h.points);
	const std::uint64_t follow = std::filesystem::file_size(path) - std::uint64_t(in.tellg());
	if (follow < bytes)
		failInput(path,
			"truncated: header says " + std::to_string(h.points) + " points (" + std::to_string(bytes) +
				" bytes) but only " + std::to_string(follow) + " bytes follow");
}

/// Binary PCD, byte for byte what PCL's writeBinary gives, but written in slices: no copy of the cloud in
/// PCL's 32-byte point and no file mapped in memory. A run's whole-drive map is the largest thing it holds;
/// writing it cost 48 bytes a point more at the end of the run (bench/output_memory.cpp).
void writeBinaryPcd(const std::string& path, const PointCloud& cloud)
{
	pcl::PointCloud<pcl::PointXYZI> shape;  // PCL's header for a cloud of this size, without its points
	shape.width = static_cast<std::uint32_t>(cloud.size());
	shape.height = 1;
	AtomicOutputFile f(path, true);
	f.stream() << pcl::PCDWriter().generateHeader(shape, static_cast<int>(cloud.size())) << "DATA binary\n";
	constexpr std::size_t kSlice = 65536;
	std::vector<float> slice;
	slice.reserve(4 * kSlice);
	for (std::size_t i = 0; i < cloud.size(); i += kSlice)
	{
		slice.clear();
		for (std::size_t k = i; k < std::min(cloud.size(), i + kSlice); ++k)
			slice.insert(slice.end(), {cloud[k].x, cloud[k].y, cloud[k].z, cloud[k].intensity});
		f.stream().write(reinterpret_cast<const char*>(slice.data()), static_cast<std::streamsize>(slice.size() * sizeof(float)));
	}
	f.commit();
}
}  // namespace

void writePcd(const std::string& path, const PointCloud& cloud, PcdFormat format)
{
	quietPcl();
	if (format == PcdFormat::Binary) return writeBinaryPcd(path, cloud);
	pcl::PointCloud<pcl::PointXYZI> pc;
	pc.reserve(cloud.size());
	for (const auto& p : cloud)
	{
		pcl::PointXYZI q;
		q.x = p.x, q.y = p.y, q.z = p.z, q.intensity = p.intensity;
		pc.push_back(q);
	}
	AtomicOutputFile f(path, true);
	pcl::PCDWriter writer;
	if (pc.empty())
	{
		// PCL writes no data section for an empty cloud: the header alone is a valid PCD.
		f.stream() << writer.generateHeader(pc) << "DATA ascii\n";
		f.commit();
		return;
	}
	f.stream().close();
	int rc = -1;
	try
	{
		rc = writer.writeASCII(f.partialPath(), pc, 9);
	}
	catch (const pcl::PCLException& e)
	{
		failInput(path, std::string("cannot write: ") + e.detailedMessage());
	}
	if (rc != 0) failInput(path, "cannot write");
	commitFile(f.partialPath(), path);
}

PointCloud readPcd(const std::string& path)
{
	quietPcl();
	checkBeforePcl(path);
	pcl::PCDReader reader;
	pcl::PCLPointCloud2 c;
	Eigen::Vector4f origin;
	Eigen::Quaternionf orientation;
	int version = 0;
	try
	{
		if (reader.read(path, c, origin, orientation, version) != 0)
			failInput(path, "malformed or truncated PCD data");
	}
	catch (const pcl::PCLException& e)
	{
		failInput(path, e.detailedMessage());
	}
	const auto *x = findField(c,
				   "x"),
			   *y = findField(c, "y"), *z = findField(c, "z"), *i = findField(c, "intensity") ? findField(c, "intensity") : findField(c, "i");
	if (!x || !y || !z) failInput(path, "FIELDS lacks x, y or z");
	const std::size_t n = std::size_t(c.width) * c.height;
	if (c.data.size() < n * c.point_step) failInput(path, "truncated: fewer bytes than the header's points");
	PointCloud out;
	out.reserve(n);
	for (std::size_t k = 0; k < n; ++k)
	{
		const std::uint8_t* p = c.data.data() + k * c.point_step;
		const double px = readField(p, *x), py = readField(p, *y), pz = readField(p, *z);
		const double pi = i ? readField(p, *i) : 0.0;
		// PCL's organised clouds hold NaN for no return.
		if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(pz)) continue;
		out.push_back({float(px), float(py), float(pz), std::isfinite(pi) ? float(pi) : 0.f});
	}
	return out;
}
}  // namespace vlo::io
