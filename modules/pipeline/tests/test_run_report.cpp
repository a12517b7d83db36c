// report.md of a vlo-run folder: it embeds what the folder holds and links nothing else.
#include <gtest/gtest.h>
#include <vlo/io/trajectory.h>
#include <vlo/pipeline/run_report.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace vlo;
using namespace vlo::pipeline;
namespace fs = std::filesystem;

namespace
{
/// Targets of the Markdown links and images "[..](target)".
std::vector<std::string> linkTargets(const std::string& md)
{
	std::vector<std::string> out;
	const std::regex link(R"(\]\(([^)]+)\))");
	for (auto it = std::sregex_iterator(md.begin(), md.end(), link); it != std::sregex_iterator(); ++it)
		out.push_back((*it)[1]);
	return out;
}

std::string readAll(const std::string& path)
{
	std::ifstream f(path);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}

/// 40 frames, 0.9 m apart along x at 10 Hz; ms_a grows from 10 to 49 ms, ms_b 20 ms, ms_total 5 ms more.
kernel::FrameTable table()
{
	kernel::FrameTable t;
	for (int i = 0; i < 40; ++i)
	{
		t.newRow();
		t.set("frame", static_cast<long long>(i));
		t.set("ms_a", 10.0 + i, 2);
		t.set("ms_b", 20.0, 2);
		t.set("ms_total", 35.0 + i, 2);
	}
	return t;
}

Trajectory line(std::size_t n, double step)
{
	Trajectory tr(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		tr[i].t = 0.1 * double(i);
		tr[i].pose.translation().x() = step * double(i);
	}
	return tr;
}
}  // namespace

TEST(RunReport, LinksOnlyTheFilesItIsGiven)
{
	RunSummary s;
	s.mode = "vlo";
	s.final_trajectory = "trajectory_vlo.tum";
	s.stage_timings = {{"ms_total", 3, 10, 12, 13}};
	RunRequest req;
	req.rawlog = "drive.rawlog";
	const std::vector<std::string> files{"frames.csv", "snapshots/topdown.png", "snapshots/scale_000020.png", "notes.txt"};
	const std::string md = runReportMarkdown(s, req, files, "");
	const auto targets = linkTargets(md);
	EXPECT_EQ(targets, (std::vector<std::string>{"frames.csv", "snapshots/topdown.png", "snapshots/scale_000020.png"}));
	EXPECT_EQ(md.find("trajectory_vlo.tum"), std::string::npos);  // not in the folder: not named
	EXPECT_EQ(md.find("Accuracy"), std::string::npos);  // no --gt
}

TEST(RunReport, WrittenReportEmbedsPlotsThatExist)
{
	const std::string dir = testing::TempDir() + "/run_report";
	fs::remove_all(dir);
	fs::create_directories(dir + "/snapshots");
	io::writeTum(dir + "/trajectory_vlo.tum", line(40, 0.9 * 1.02));
	io::writeTum(dir + "/gt.tum", line(40, 0.9));
	std::ofstream(dir + "/frames.csv") << "frame\n";
	RunSummary s;
	s.mode = "vlo";
	s.frames = 40;
	s.final_trajectory = "trajectory_vlo.tum";
	s.stage_timings = {{"ms_a", 40, 30, 47, 49}, {"ms_total", 40, 55, 72, 74}};
	RunRequest req;
	req.rawlog = "drive.rawlog";
	req.gt = dir + "/gt.tum";
	writeRunReport(dir, s, req, table(), true);
	const std::string md = readAll(dir + "/report.md");
	ASSERT_FALSE(md.empty());
	for (const auto& t : linkTargets(md)) EXPECT_TRUE(fs::is_regular_file(dir + "/" + t)) << t;
	for (const char* f : {"snapshots/time_per_stage.png", "snapshots/ate_vlo.png", "trajectory_vlo.tum"})
		EXPECT_NE(md.find(std::string("(") + f + ")"), std::string::npos) << f;
	EXPECT_NE(md.find("ATE RMSE"), std::string::npos);
	EXPECT_FALSE(cv::imread(dir + "/snapshots/time_per_stage.png").empty());
}

TEST(RunReport, WithoutPlotsNoPictureIsMade)
{
	const std::string dir = testing::TempDir() + "/run_report_noplots";
	fs::remove_all(dir);
	fs::create_directories(dir);
	RunSummary s;
	s.mode = "lo";
	s.final_trajectory = "trajectory_lo.tum";
	writeRunReport(dir, s, RunRequest{}, table(), false);
	EXPECT_TRUE(fs::is_regular_file(dir + "/report.md"));
	EXPECT_FALSE(fs::exists(dir + "/snapshots"));
}
