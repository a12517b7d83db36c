#pragma once
// Shared helpers of the io tests: scratch folders, the real data unpacked once, synthetic frames.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/core/frame.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/rawlog_writer.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace vlo::test
{
namespace fs = std::filesystem;

/// Removes the scratch folders of each test that passed (the io tests write ~0.5 GB in all; a failed
/// test's folders stay for a look).
class ScratchCleaner : public ::testing::EmptyTestEventListener
{
   public:
	static void add(const fs::path& dir)
	{
		static auto* cleaner = [] {
			auto* c = new ScratchCleaner;  // owned by gtest's listener list
			::testing::UnitTest::GetInstance()->listeners().Append(c);
			return c;
		}();
		cleaner->dirs_.push_back(dir);
	}
	void OnTestEnd(const ::testing::TestInfo& info) override
	{
		std::error_code ec;
		if (info.result()->Passed())
			for (const auto& d : dirs_) fs::remove_all(d, ec);
		dirs_.clear();
	}

   private:
	std::vector<fs::path> dirs_;
};

/// An empty folder for the running test (removed and recreated), removed after it when it passes.
inline std::string freshDir(const std::string& tag = "")
{
	const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
	const fs::path dir = fs::path(::testing::TempDir()) /
		("vlo_io_" + std::string(info->test_suite_name()) + "_" + info->name() + tag);
	fs::remove_all(dir);
	fs::create_directories(dir);
	ScratchCleaner::add(dir);
	return dir.string();
}

/// Unpacks VLO_SHARED_DATA/<name>.tar.xz into <build>/test_data/ unless already there; returns
/// <build>/test_data/<name>. Safe when several test processes race: unpack aside, then rename.
inline std::string sharedData(const std::string& name)
{
	const fs::path root = fs::path(VLO_BIN_DIR) / ".." / "test_data";
	const fs::path dest = root / name;
	if (fs::is_directory(dest)) return dest.string();
	const fs::path tmp = root / (".unpack-" + std::to_string(::getpid()));
	fs::remove_all(tmp);
	fs::create_directories(tmp);
	const std::string cmd = "tar -xJf '" + std::string(VLO_SHARED_DATA) + "/" + name + ".tar.xz' -C '" + tmp.string() + "'";
	if (std::system(cmd.c_str()) != 0) ADD_FAILURE() << "cannot unpack: " << cmd;
	std::error_code ec;
	fs::rename(tmp / name, dest, ec);  // fails harmlessly if another process won the race
	fs::remove_all(tmp);
	return dest.string();
}

/// Expects f() to throw InputError whose message contains every one of `parts`.
inline void expectInputError(const std::function<void()>& f, const std::vector<std::string>& parts)
{
	try
	{
		f();
		ADD_FAILURE() << "no InputError thrown";
	}
	catch (const InputError& e)
	{
		const std::string msg = e.what();
		for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
		EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
	}
}

/// Writes `text` to `path` byte for byte; returns `path`.
inline std::string writeFile(const std::string& path, const std::string& text)
{
	std::ofstream(path, std::ios::binary) << text;
	return path;
}

/// Writes `text` to `path`, then expects read(path) to throw an InputError naming `path` and holding
/// every one of `parts`.
inline void expectRefused(const std::string& path, const std::string& text,
	const std::function<void(const std::string&)>& read, std::vector<std::string> parts)
{
	writeFile(path, text);
	parts.insert(parts.begin(), path);
	expectInputError([&] { read(path); }, parts);
}

/// A rig with non-trivial camera and LiDAR placements.
inline SensorRig testRig(int w = 64, int h = 48)
{
	SensorRig rig;
	rig.has_camera = rig.has_lidar = true;
	rig.camera = {50.0, 51.0, w / 2.0 - 0.3, h / 2.0 + 0.2, w, h};
	Eigen::Matrix3d axes;  // optical frame looking along vehicle x
	axes << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	rig.vehicle_T_camera.linear() = axes * Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX()).toRotationMatrix();
	rig.vehicle_T_camera.translation() = Eigen::Vector3d(1.1, -0.3, 1.6);
	rig.vehicle_T_lidar.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	rig.vehicle_T_lidar.translation() = Eigen::Vector3d(0.8, 0.0, 1.9);
	return rig;
}

/// A frame with a patterned grayscale image and a small scan (no invalid points).
inline Frame testFrame(std::size_t index, double t, int w = 64, int h = 48)
{
	Frame f;
	f.index = index;
	f.t = t;
	f.image = mrpt::img::CImage(w, h, mrpt::img::CH_GRAY);
	for (int r = 0; r < h; ++r)
		for (int c = 0; c < w; ++c) *f.image.ptr<uint8_t>(c, r) = static_cast<uint8_t>(3 * c + 5 * r + 7 * index);
	f.has_image = true;
	for (int k = 0; k < 10; ++k)
		f.scan.push_back({1.5f * k, -0.25f * k + static_cast<float>(index), 0.1f * k, 0.05f * k});
	f.has_scan = true;
	f.rig = testRig(w, h);
	return f;
}
/// Every frame of a rawlog.
inline std::vector<Frame> readFrames(const std::string& path, io::RawlogReaderOptions opt = {}, io::RawlogStats* stats = nullptr)
{
	io::RawlogReader reader(path, opt);
	std::vector<Frame> frames;
	Frame f;
	while (reader.next(f)) frames.push_back(f);
	if (stats) *stats = reader.stats();
	return frames;
}

/// A rawlog of single-sensor observations (inline images) at the given times.
inline void writeStreams(const std::string& path, const std::vector<double>& image_times, const std::vector<double>& scan_times)
{
	io::RawlogWriter w(path, false);
	std::size_t i = 0, s = 0;
	while (i < image_times.size() || s < scan_times.size())
	{
		const bool image_first = s >= scan_times.size() || (i < image_times.size() && image_times[i] <= scan_times[s]);
		const std::size_t k = image_first ? i++ : s++;
		Frame f = testFrame(k, image_first ? image_times[k] : scan_times[k]);
		(image_first ? f.has_scan : f.has_image) = false;
		w.writeFrame(f);
	}
	w.commit();
}
}  // namespace vlo::test
