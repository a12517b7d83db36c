#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <vlo/batch/execute.h>
#include <vlo/batch/jobs.h>
#include <vlo/batch/process.h>
#include <vlo/batch/words.h>
#include <vlo/core/error.h>

#include <map>

using namespace vlo;
using namespace vlo::batch;
namespace fs = std::filesystem;

TEST(BatchWords, SplitKeepsQuotedBlanksAndEquals)
{
	const std::vector<std::string> w{"a=b", "c d=e f", "", "x"};
	EXPECT_EQ(splitWords("  a=b \"c d=e f\"\t\"\" x ", "w"), w);
	EXPECT_TRUE(splitWords("   ", "w").empty());
	EXPECT_THROW(splitWords("a \"b", "w"), InputError);
	EXPECT_EQ(splitWords(joinWords(w), "w"), w);
}

TEST(BatchWords, ShellQuoting)
{
	EXPECT_EQ(shellQuote("/a/b-c_d.ini"), "/a/b-c_d.ini");
	EXPECT_EQ(shellQuote("pipeline.mode=vo"), "pipeline.mode=vo");
	EXPECT_EQ(shellQuote("a b"), "'a b'");
	EXPECT_EQ(shellQuote(""), "''");
	EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
	EXPECT_EQ(shellQuote("$HOME;rm -rf /"), "'$HOME;rm -rf /'");
	EXPECT_EQ(shellJoin({"echo", "a b", "c"}), "echo 'a b' c");
}

namespace
{
Plan tinyPlan(const std::string& data)
{
	Plan p;
	p.data_dir = data;
	p.kitti_lengths = "5,10";
	Sequence s;
	s.name = "seq";
	s.rawlog = data + "/seq.rawlog";
	s.gt = data + "/seq.gt.tum";
	s.ini = "/ini/sim hdl64.ini";
	s.sim = {"--scenario", "urban", "--frames", "3"};
	p.sequences.push_back(s);
	p.configs.push_back({"vo", {"pipeline.mode=vo", "a.b=x y"}, "sim3", ""});
	p.configs.push_back({"lo", {}, "se3", ""});
	return p;
}

void writeTool(const std::string& path, const std::string& body)
{
	test::writeFile(path, "#!/bin/sh\n" + body);
	chmod(path.c_str(), 0755);
}

/// Stand-ins for vlo-run and vlo-eval that leave files like the real ones, and vlo-sim.
void writeFakeTools(const std::string& bin)
{
	writeTool(bin + "/vlo-run",
		"out=\nwhile [ $# -gt 0 ]; do case \"$1\" in --out) out=\"$2\";; --set) [ \"$2\" = a.b=fail ] && "
		"{ echo 'vlo-run: error: x.ini: asked to fail' >&2; exit 2; };; esac; shift; done\n"
		"echo '0 0 0 0 0 0 0 1' > \"$out/trajectory_lo.tum\"\necho '0 0 0 0 0 0 0 1' > \"$out/trajectory_vo.tum\"\n"
		"echo '{\"ms_per_frame\": 12.5}' > \"$out/summary.json\"\necho vlo-run: done\n");
	writeTool(bin + "/vlo-eval",
		"all=\"$*\"\njson=\nwhile [ $# -gt 0 ]; do case \"$1\" in --json) json=\"$2\";; --write-aligned) cp trajectory_vo.tum \"$2\";; "
		"esac; shift; done\necho \"{\\\"args\\\": \\\"$all\\\"}\" > \"$json\"\n");
	writeTool(bin + "/vlo-sim",
		"while [ $# -gt 0 ]; do case \"$1\" in --out) out=\"$2\";; esac; shift; done\n"
		"echo x > \"$out\"\necho t > \"${out%.rawlog}.gt.tum\"\necho sim >> \"$(dirname \"$out\")/calls\"\n");
}

/// Every file below `dir` with its content, paths relative to `dir`.
std::map<std::string, std::string> tree(const std::string& dir)
{
	std::map<std::string, std::string> t;
	for (const auto& e : fs::recursive_directory_iterator(dir))
		if (e.is_regular_file()) t[fs::relative(e.path(), dir).string()] = test::readFile(e.path().string());
	return t;
}
}  // namespace

TEST(BatchJobs, RunCommandLines)
{
	const Plan p = tinyPlan("/data");
	const RunJob j = runJob(p, p.sequences[0], p.configs[0], "/bin dir", "/out");
	EXPECT_EQ(j.name, "seq/vo");
	EXPECT_EQ(j.dir, "/out/runs/seq/vo");
	const std::vector<std::string> run{"/bin dir/vlo-run", "--rawlog", "/data/seq.rawlog", "--ini", "/ini/sim hdl64.ini", "--out",
		"/out/runs/seq/vo", "--gt", "/data/seq.gt.tum", "--quiet", "--overwrite", "--set", "pipeline.mode=vo", "--set", "a.b=x y"};
	EXPECT_EQ(j.run.argv, run);
	const std::vector<std::string> eval{"/bin dir/vlo-eval", "--gt", "/data/seq.gt.tum", "--metric", "all", "--align", "sim3",
		"--kitti-lengths", "5,10", "--est", "trajectory_vo.tum", "--json", "eval_vo.json", "--write-aligned", "aligned_vo.tum"};
	EXPECT_EQ(j.evalStep("vo").argv, eval);
	EXPECT_EQ(j.evalStep("vo").err, "eval_vo.err");
	const std::string line = shellLine(j);
	EXPECT_NE(line.find("'/bin dir/vlo-run' --rawlog /data/seq.rawlog --ini '/ini/sim hdl64.ini' --out /out/runs/seq/vo"),
		std::string::npos)
		<< line;
	EXPECT_NE(line.find("--set pipeline.mode=vo --set 'a.b=x y' > vlo-run.out 2> vlo-run.err"), std::string::npos) << line;
	EXPECT_NE(line.find("--align sim3 --kitti-lengths 5,10 --est \"trajectory_$t.tum\""), std::string::npos) << line;
	EXPECT_EQ(line.find('\n'), std::string::npos);

	const DataJob d = dataJob(p.sequences[0], "/bin", "/out");
	const std::vector<std::string> sim{
		"/bin/vlo-sim", "--scenario", "urban", "--frames", "3", "--out", "/data/seq.rawlog", "--quiet"};
	EXPECT_EQ(d.sim.argv, sim);
	EXPECT_EQ(d.sim.err, "/out/generate/seq.err");
	EXPECT_EQ(runJobs(p, "/bin", "/out").size(), 2u);
	const Config own{"own", {}, "se3", "/ini/vo.ini"};  // a configuration's INI replaces the sequence's
	EXPECT_EQ(runJob(p, p.sequences[0], own, "/bin", "/out").run.argv[4], "/ini/vo.ini");
}

TEST(BatchJobs, RevisitOptionsOfThePlanGoToVloEval)
{
	Plan p = tinyPlan("/data");
	p.revisit_radius = 2.5;
	p.revisit_min_path = 0.1;
	const RunJob j = runJob(p, p.sequences[0], p.configs[1], "/bin", "/out");
	const std::vector<std::string> eval{"/bin/vlo-eval", "--gt", "/data/seq.gt.tum", "--metric", "all", "--align", "se3",
		"--kitti-lengths", "5,10", "--revisit-radius", "2.5", "--revisit-min-path", "0.1", "--est", "trajectory_slam.tum",
		"--json", "eval_slam.json"};
	EXPECT_EQ(j.evalStep("slam").argv, eval);
	EXPECT_NE(shellLine(j).find("--revisit-radius 2.5 --revisit-min-path 0.1 --est"), std::string::npos) << shellLine(j);
	EXPECT_EQ(numberWord(50), "50");
	EXPECT_EQ(numberWord(1.0 / 3), "0.3333333333333333");  // as many digits as read back the same
}

TEST(BatchJobs, ShellLineAndDirectExecutionLeaveTheSameFiles)
{
	// Awkward characters in every path: the shell line must quote them, the direct run needs no quoting.
	test::ScratchDir dir("jobs");
	const std::string bin = dir / "b i'n", data = dir / "da ta";
	writeFakeTools(bin);
	test::writeFile(data + "/seq.gt.tum", "0 0 0 0 0 0 0 1\n");
	Plan p = tinyPlan(data);
	p.configs.push_back({"bad", {"a.b=fail"}, "se3", ""});
	for (const auto& c : p.configs)
	{
		const RunJob viaShell = runJob(p, p.sequences[0], c, bin, dir / "sh $out");
		const RunJob direct = runJob(p, p.sequences[0], c, bin, dir / "exec $out");
		test::writeFile(viaShell.dir + "/eval_old.json", "stale");  // an earlier attempt's file must go
		const int shRc = runStep({{"/bin/sh", "-c", shellLine(viaShell)}, dir / "sh.out", dir / "sh.err"});
		EXPECT_EQ(test::readFile(dir / "sh.err"), "");
		const pid_t pid = fork();
		if (pid == 0) _exit(executeRunJob(direct));  // it changes folder: in a child
		int status = 0;
		waitpid(pid, &status, 0);
		EXPECT_EQ(shRc, WEXITSTATUS(status)) << c.name;
		EXPECT_EQ(shRc, c.name == "bad" ? 2 : 0);
		auto a = tree(viaShell.dir), b = tree(direct.dir);
		EXPECT_EQ(a, b) << c.name;
		EXPECT_EQ(a["exit_code"], c.name == "bad" ? "2\n" : "0\n");
		EXPECT_EQ(a.count("eval_old.json"), 0u);
		if (c.name == "vo")
		{
			EXPECT_EQ(a.count("aligned_lo.tum") + a.count("aligned_vo.tum"), 2u);
			EXPECT_NE(a["eval_lo.json"].find("--align sim3 --kitti-lengths 5,10 --est trajectory_lo.tum --json eval_lo.json"),
				std::string::npos)
				<< a["eval_lo.json"];
		}
		if (c.name == "bad")
		{
			EXPECT_EQ(a["vlo-run.err"], "vlo-run: error: x.ini: asked to fail\n");
		}
	}
}

TEST(BatchJobs, DataLineGeneratesOnlyWhatIsMissing)
{
	test::ScratchDir dir("data");
	const std::string bin = dir / "bin", data = dir / "new data";
	writeFakeTools(bin);
	const Plan p = tinyPlan(data);
	const DataJob d = dataJob(p.sequences[0], bin, dir / "out");
	const Step sh{{"/bin/sh", "-c", shellLine(d)}, dir / "sh.out", dir / "sh.err"};
	EXPECT_EQ(runStep(sh), 0);
	EXPECT_TRUE(fs::is_regular_file(data + "/seq.rawlog"));
	EXPECT_TRUE(fs::is_regular_file(data + "/seq.gt.tum"));
	EXPECT_EQ(test::readFile(data + "/seq.sim.txt"), "--scenario urban --frames 3\n");
	EXPECT_EQ(runStep(sh), 0);
	EXPECT_EQ(executeDataJob(d), 0);
	EXPECT_EQ(test::readFile(data + "/calls"), "sim\n");  // once
	fs::remove(data + "/seq.gt.tum");
	EXPECT_EQ(executeDataJob(d), 0);
	EXPECT_EQ(test::readFile(data + "/calls"), "sim\nsim\n");
	EXPECT_EQ(test::readFile(data + "/seq.sim.txt"), "--scenario urban --frames 3\n");
}

TEST(BatchJobs, ADriveGeneratedWithOtherArgumentsIsRefused)
{
	test::ScratchDir dir("record");
	const std::string data = dir / "data";
	Plan p = tinyPlan(data);
	Sequence& s = p.sequences[0];
	s.sim = {"--scenario", "urban", "--trajectory", data + "/poses/00.txt"};
	EXPECT_EQ(simRecord(s), "--scenario urban --trajectory poses/00.txt");  // relative: the data folder may move
	EXPECT_NO_THROW(requireSameSimArgs(s));  // nothing there yet: it will be generated
	test::writeFile(s.rawlog, "x");
	test::writeFile(s.gt, "t");
	EXPECT_NO_THROW(requireSameSimArgs(s));  // no record: made elsewhere, used as it is
	test::writeFile(data + "/seq.sim.txt", "--scenario urban --trajectory poses/00.txt\n");
	EXPECT_NO_THROW(requireSameSimArgs(s));
	s.sim.push_back("--foliage-depth");
	s.sim.push_back("0.3");
	try
	{
		requireSameSimArgs(s);
		ADD_FAILURE() << "a stale drive was accepted";
	}
	catch (const InputError& e)
	{
		const std::string m = e.what();
		EXPECT_NE(m.find("seq.rawlog"), std::string::npos) << m;
		EXPECT_NE(m.find("--foliage-depth 0.3"), std::string::npos) << m;
	}
}
