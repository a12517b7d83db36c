#include "seeds.h"

#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/rawlog_writer.h>
#include <vlo/io/trajectory.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace vlo::fuzz
{
namespace fs = std::filesystem;

namespace
{
/// <work>/<name>, unpacked from VLO_SHARED_DATA/<name>.tar.xz unless there (race-safe: unpack aside, rename).
std::string unpacked(const std::string& name, const std::string& work)
{
	const fs::path dest = fs::path(work) / name;
	if (fs::is_directory(dest)) return dest.string();
	const fs::path tmp = fs::path(work) / (".unpack-" + std::to_string(::getpid()));
	fs::remove_all(tmp);
	fs::create_directories(tmp);
	const std::string cmd = "tar -xJf '" + std::string(VLO_SHARED_DATA) + "/" + name + ".tar.xz' -C '" + tmp.string() + "'";
	if (std::system(cmd.c_str()) != 0) throw std::runtime_error("cannot unpack: " + cmd);
	std::error_code ec;
	fs::rename(tmp / name, dest, ec);  // fails harmlessly if another process won the race
	fs::remove_all(tmp);
	return dest.string();
}

std::string fileBytes(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) throw std::runtime_error("cannot read seed " + path);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The decompressed contents of a gzip file (a plain file comes back as it is).
std::string gunzipped(const std::string& path)
{
	gzFile gz = gzopen(path.c_str(), "rb");
	if (!gz) throw std::runtime_error("cannot read seed " + path);
	std::string out;
	char buf[1 << 16];
	for (int n; (n = gzread(gz, buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(n));
	gzclose(gz);
	return out;
}

std::vector<std::string> gzipAndPlain(const std::string& gz, const std::string& work)
{
	const std::string path = work + "/fuzz_seed_" + std::to_string(::getpid()) + ".gz";
	std::ofstream(path, std::ios::binary) << gz;
	std::vector<std::string> both = {gz, gunzipped(path)};
	fs::remove(path);
	return both;
}

std::string firstLines(const std::string& text, std::size_t n)
{
	std::size_t end = 0;
	for (std::size_t k = 0; k < n && end != std::string::npos; ++k) end = text.find('\n', end == 0 ? 0 : end + 1);
	return end == std::string::npos ? text : text.substr(0, end + 1);
}

/// A 3-frame camera + LiDAR rawlog (vlo's writer, inline images) of kittiSeedFrames.
std::string kittiRawlog(const std::string& work)
{
	const std::string path = work + "/fuzz_seed_kitti_" + std::to_string(::getpid()) + ".rawlog";
	{
		io::RawlogWriter writer(path, false);
		for (const auto& f : kittiSeedFrames(work)) writer.writeFrame(f);
		writer.commit();
	}
	const std::string bytes = fileBytes(path);
	fs::remove(path);
	return bytes;
}

/// The first scan of MRPT's VLP-16 sample cut to its first `packets` data packets (every packet costs
/// a decoding on each fuzzed input), written back by vlo's writer.
std::string velodyneRawlog(const std::string& sample, std::size_t packets, const std::string& work)
{
	mrpt::io::CFileGZInputStream in(sample);
	auto ar = mrpt::serialization::archiveFrom(in);
	mrpt::obs::CObservationVelodyneScan::Ptr scan;
	while (!scan)
	{
		const auto obj = ar.ReadObject();
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			scan = sf->getObservationByClass<mrpt::obs::CObservationVelodyneScan>();
		else
			scan = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(obj);
	}
	scan->scan_packets.resize(std::min(packets, scan->scan_packets.size()));
	const std::string path = work + "/fuzz_seed_velodyne_" + std::to_string(::getpid()) + ".rawlog";
	{
		io::RawlogWriter writer(path);
		writer.write(*scan);
		writer.commit();
	}
	const std::string bytes = fileBytes(path);
	fs::remove(path);
	return bytes;
}

/// KITTI raw timestamps (date and time, nanoseconds), 10 Hz like the recordings.
std::string rawTimestamps()
{
	std::ostringstream s;
	for (int k = 0; k < 20; ++k)
	{
		char line[64];
		std::snprintf(line, sizeof line, "2011-09-26 13:02:%02d.%09d\n", 25 + k / 10, 964389445 % 100000000 + (k % 10) * 100000000);
		s << line;
	}
	return s.str();
}

/// The first 20 ground-truth poses of KITTI 00 in TUM form, written by vlo's own writer.
std::string tumFromKitti(const std::string& work)
{
	const std::string gt = unpacked("kitti_odometry_snippets", work) + "/poses/00.txt";
	const std::string path = work + "/fuzz_seed_" + std::to_string(::getpid()) + ".tum";
	io::writeTum(path, io::readKittiPoses(gt));
	const std::string bytes = fileBytes(path);
	fs::remove(path);
	return bytes;
}
}  // namespace

std::vector<Frame> kittiSeedFrames(const std::string& work)
{
	const std::string seq = unpacked("kitti_odometry_snippets", work) + "/sequences/00";
	const auto calib = io::readKittiOdometryCalib(seq + "/calib.txt", 2);
	std::vector<Frame> frames;
	for (std::size_t k = 0; k < 3; ++k)
	{
		char name[16];
		std::snprintf(name, sizeof name, "%06zu", k);
		Frame f;
		f.index = k;
		f.t = 0.1 * static_cast<double>(k);
		mrpt::img::CImage image;
		if (!image.loadFromFile(seq + "/image_2/" + name + ".png", 0)) throw std::runtime_error("cannot read a seed image");
		image.extract_patch(f.image, 600, 180, 48, 32);
		f.has_image = true;
		PointCloud scan;
		io::readKittiBin(seq + "/velodyne/" + name + ".bin", scan);
		for (std::size_t i = 0; i < scan.size(); i += 200) f.scan.push_back(scan[i]);
		f.has_scan = true;
		f.rig.has_camera = f.rig.has_lidar = true;
		f.rig.camera = io::intrinsicsOf(calib.P, 48, 32);
		f.rig.camera.cx -= 600, f.rig.camera.cy -= 180;
		f.rig.vehicle_T_camera = calib.cam0_T_velo.inverse();
		frames.push_back(f);
	}
	return frames;
}

std::vector<std::string> seedsOf(const std::string& target, const std::string& work)
{
	fs::create_directories(work);
	const std::string samples = std::string(VLO_SHARED_DATA) + "/mrpt_samples";
	// Rawlogs both as written (gzip: mutations mostly meet zlib's checks) and plain (they meet MRPT's).
	if (target == "rawlog") return gzipAndPlain(kittiRawlog(work), work);
	// (rot_scan_velodyne.rawlog is a CObservationRotatingScan, which vlo does not read)
	if (target == "rawlog_velodyne") return gzipAndPlain(velodyneRawlog(samples + "/test_velodyne_VLP16.rawlog", 4, work), work);
	const std::string snippets = unpacked("kitti_odometry_snippets", work);
	if (target == "kitti_calib")
		return {fileBytes(snippets + "/sequences/00/calib.txt"), fileBytes(snippets + "/sequences/04/calib.txt")};
	if (target == "kitti_raw_calib")
	{
		const std::string raw = unpacked("kitti_raw_2011_09_26_sample", work);
		return {fileBytes(raw + "/calib_cam_to_cam.txt") + fileBytes(raw + "/calib_velo_to_cam.txt")};
	}
	if (target == "kitti_times")
		return {fileBytes(snippets + "/sequences/00/times.txt"), fileBytes(snippets + "/sequences/08/times.txt")};
	if (target == "kitti_raw_timestamps") return {rawTimestamps()};
	if (target == "kitti_poses")
		return {fileBytes(snippets + "/poses/00.txt"), firstLines(fileBytes(snippets + "/poses/08.txt"), 3)};
	if (target == "kitti_bin")
	{
		const std::string scan = fileBytes(snippets + "/sequences/00/velodyne/000000.bin");
		return {scan.substr(0, 16 * 256), scan.substr(scan.size() - 16 * 64)};
	}
	if (target == "tum") return {tumFromKitti(work)};
	if (target == "ini")
		return {fileBytes(std::string(VLO_SOURCE_DIR) + "/ini/kitti-hdl64.ini"), fileBytes(std::string(VLO_SOURCE_DIR) + "/ini/vlp16.ini"),
			fileBytes(std::string(VLO_SOURCE_DIR) + "/ini/vo-kitti.ini")};
	throw std::runtime_error("no seeds for fuzz target '" + target + "'");
}
}  // namespace vlo::fuzz
