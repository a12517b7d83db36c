#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <vlo/batch/plan.h>
#include <vlo/core/error.h>

using namespace vlo;
using namespace vlo::batch;

namespace
{
/// A scratch folder with a base INI, one existing sequence (rawlog + ground truth) and KITTI poses.
struct BatchPlan : public ::testing::Test
{
	test::ScratchDir dir{"plan"};
	std::string data = dir / "data";
	void SetUp() override
	{
		test::writeFile(dir / "ini/base.ini", "[pipeline]\nmode = lo\n");
		test::writeFile(dir / "ini/vo.ini", "[pipeline]\nmode = vo\n");
		test::writeFile(data + "/real.rawlog", "x");
		test::writeFile(data + "/real.gt.tum", "0 0 0 0 0 0 0 1\n");
		test::writeFile(data + "/poses/00.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
	}
	Plan parse(const std::string& text) { return parsePlan(text, "p.ini", dir / "ini", data); }
	/// Parses `text` and expects an InputError whose message holds every one of `parts`.
	void expectError(const std::string& text, std::initializer_list<const char*> parts)
	{
		try
		{
			parse(text);
			ADD_FAILURE() << "no error for:\n"
						  << text;
		}
		catch (const InputError& e)
		{
			const std::string msg = e.what();
			EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
			EXPECT_EQ(msg.rfind("p.ini", 0), 0u) << msg;
			for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
		}
	}
};

const std::string kGood = R"(# comment
[plan]
kitti_lengths = 10,20
kitti_step = 5
revisit_radius = 2.5
revisit_min_path = 0.1

[sequence real]
ini = base.ini
gt_translation_only = true

[sequence made]
ini = base.ini
sim = --scenario trees --lidar vlp16 --frames 30 --seed 13 --no-realism --trajectory poses/00.txt

[config vo_mono]
; '=' inside a value is fine: MRPT splits at the first one
set = pipeline.mode=vo vo.orb.detector=anms "pipeline.camera_label=MY CAM"
align = sim3

[config lo]
set = pipeline.mode=lo

[config vo_only]
ini = vo.ini
)";
}  // namespace

TEST_F(BatchPlan, ReadsSectionsInFileOrderWithPathsResolved)
{
	const Plan p = parse(kGood);
	EXPECT_EQ(p.data_dir, data);
	EXPECT_EQ(p.kitti_lengths, "10,20");
	EXPECT_EQ(p.kitti_step, 5);
	EXPECT_EQ(p.revisit_radius, 2.5);
	EXPECT_EQ(p.revisit_min_path, 0.1);
	ASSERT_EQ(p.sequences.size(), 2u);
	EXPECT_EQ(p.sequences[0].name, "real");
	EXPECT_EQ(p.sequences[0].rawlog, data + "/real.rawlog");
	EXPECT_EQ(p.sequences[0].gt, data + "/real.gt.tum");
	EXPECT_EQ(p.sequences[0].ini, dir / "ini/base.ini");
	EXPECT_TRUE(p.sequences[0].gt_translation_only);
	EXPECT_TRUE(p.sequences[0].sim.empty());
	EXPECT_FALSE(p.sequences[0].dataMissing());
	const Sequence& made = p.sequences[1];
	EXPECT_TRUE(made.dataMissing());
	EXPECT_EQ(made.gt, data + "/made.gt.tum");
	const std::vector<std::string> sim{"--scenario", "trees", "--lidar", "vlp16", "--frames", "30", "--seed", "13",
		"--no-realism", "--trajectory", data + "/poses/00.txt"};
	EXPECT_EQ(made.sim, sim);
	ASSERT_EQ(p.configs.size(), 3u);
	EXPECT_EQ(p.configs[0].name, "vo_mono");  // file order, not MRPT's alphabetical order
	EXPECT_EQ(p.configs[0].ini, "");  // the sequence's
	EXPECT_EQ(p.configs[2].ini, dir / "ini/vo.ini");
	EXPECT_TRUE(p.configs[2].overrides.empty());
	const std::vector<std::string> set{"pipeline.mode=vo", "vo.orb.detector=anms", "pipeline.camera_label=MY CAM"};
	EXPECT_EQ(p.configs[0].overrides, set);
	EXPECT_EQ(p.configs[0].align, "sim3");
	EXPECT_EQ(p.configs[1].align, "se3");
}

TEST_F(BatchPlan, DataDirFromThePlanRelativeToTheCurrentFolder)
{
	const Plan p = parsePlan("[plan]\ndata = somewhere/x\n[sequence s]\nini = base.ini\nsim = --frames 3\n[config c]\n", "p.ini",
		dir / "ini");
	EXPECT_EQ(p.data_dir, (std::filesystem::current_path() / "somewhere/x").string());
	EXPECT_EQ(p.sequences[0].rawlog, p.data_dir + "/s.rawlog");
	// Without a [plan] data key: rawlogs/experiments under the current folder.
	const Plan q = parsePlan("[sequence s]\nini = base.ini\nsim = --frames 3\n[config c]\n", "p.ini", dir / "ini");
	EXPECT_EQ(q.data_dir, (std::filesystem::current_path() / "rawlogs/experiments").string());
	EXPECT_FALSE(q.revisit_radius || q.revisit_min_path);  // vlo-eval's defaults: no argument
}

TEST_F(BatchPlan, ResolvedCopyReadsBackTheSameFromAnywhere)
{
	const Plan p = parse(kGood);
	test::writeFile(dir / "out/plan.ini", resolvedPlanText(p));
	const Plan q = readPlan(dir / "out/plan.ini");
	EXPECT_EQ(q.source, "p.ini");
	EXPECT_EQ(q.data_dir, p.data_dir);
	EXPECT_EQ(q.kitti_lengths, p.kitti_lengths);
	EXPECT_EQ(q.kitti_step, p.kitti_step);
	EXPECT_EQ(q.revisit_radius, 2.5);
	EXPECT_EQ(q.revisit_min_path, 0.1);  // written back exactly
	ASSERT_EQ(q.sequences.size(), 2u);
	for (std::size_t i = 0; i < 2; ++i)
	{
		EXPECT_EQ(q.sequences[i].rawlog, p.sequences[i].rawlog);
		EXPECT_EQ(q.sequences[i].gt, p.sequences[i].gt);
		EXPECT_EQ(q.sequences[i].ini, p.sequences[i].ini);
		EXPECT_EQ(q.sequences[i].sim, p.sequences[i].sim);
		EXPECT_EQ(q.sequences[i].gt_translation_only, p.sequences[i].gt_translation_only);
	}
	EXPECT_EQ(q.configs[0].overrides, p.configs[0].overrides);
	EXPECT_EQ(q.configs[0].align, "sim3");
	EXPECT_EQ(q.configs[2].ini, p.configs[2].ini);
}

TEST_F(BatchPlan, CollectingNeedsNoFiles)
{
	const std::string text = "[sequence gone]\nini = nowhere.ini\n[config c]\n";
	EXPECT_THROW(parse(text), InputError);
	EXPECT_EQ(parsePlan(text, "p.ini", dir / "ini", data, false).sequences.size(), 1u);
}

TEST_F(BatchPlan, BadPlansNameFileSectionAndKey)
{
	const std::string seq = "[sequence real]\nini = base.ini\n", cfg = "[config lo]\nset = pipeline.mode=lo\n";
	expectError(seq + "rawlgo = x.rawlog\n" + cfg, {"p.ini: [sequence real]: unknown key 'rawlgo' (did you mean rawlog?)"});
	expectError(seq + cfg + "allign = sim3\n", {"[config lo]", "unknown key 'allign'"});
	expectError("[plan]\njobs = 3\n" + seq + cfg, {"[plan]", "unknown key 'jobs'"});
	expectError(seq + cfg + "[configs x]\n", {"[configs x]", "unknown section"});
	expectError(seq + cfg + "[config]\n", {"[config]", "unknown section"});
	expectError(seq + "[config lo]\nset = pipeline.mode=lo\nset = loam.scan.ring_model=hdl64\n",
		{"line 5", "[config lo] set", "given twice"});
	expectError(seq + cfg + "[sequence real]\nini = base.ini\n", {"line 5", "section [sequence real] given twice"});
	expectError(seq + cfg + "[sequence  real]\nini = base.ini\n", {"sequence name 'real' is given twice"});
	expectError(seq + cfg + "just words\n", {"line 5", "is not 'key = value'"});
	expectError("set = x\n" + seq + cfg, {"line 1", "comes before any [section]"});
	expectError(cfg, {"no [sequence NAME] section"});
	expectError(seq, {"no [config NAME] section"});
	expectError("[sequence real]\n" + cfg, {"[sequence real] ini", "missing"});
	expectError("[sequence real]\nini = nope.ini\n" + cfg, {"[sequence real] ini", "nope.ini does not exist"});
	expectError("[sequence other]\nini = base.ini\n" + cfg,
		{"[sequence other] rawlog", "other.rawlog does not exist (and no sim"});
	expectError("[sequence real]\nini = base.ini\ngt = none.tum\n" + cfg, {"[sequence real] gt", "none.tum does not exist"});
	expectError(seq + "gt_translation_only = maybe\n" + cfg, {"[sequence real] gt_translation_only: expects true or false, got 'maybe'"});
	expectError(seq + "[config lo]\nset = pipeline.mode\n", {"[config lo] set", "'pipeline.mode' is not section.key=value"});
	expectError(seq + "[config lo]\nset = \"pipeline.mode=lo\n", {"[config lo] set", "unterminated"});
	expectError(seq + "[config lo]\nini = nope.ini\n", {"[config lo] ini", "nope.ini does not exist"});
	expectError(seq + "[config lo]\nalign = sim\n", {"p.ini: [config lo] align: 'sim' is not one of se3, sim3, none (did you mean sim3?)"});
	expectError("[plan]\nkitti_lengths = 10,x\n" + seq + cfg, {"[plan] kitti_lengths", "'x'"});
	expectError("[plan]\nkitti_step = 0\n" + seq + cfg, {"[plan] kitti_step: must be in [1, 1000000]"});
	expectError("[plan]\nrevisit_radius = 0\n" + seq + cfg, {"[plan] revisit_radius: must be in (0, 1000]"});
	expectError("[plan]\nrevisit_min_path = -1\n" + seq + cfg, {"[plan] revisit_min_path: must be in [0, 1000000]"});
	expectError("[sequence a/b]\nini = base.ini\n" + cfg, {"[sequence a/b]", "letters, digits"});
	expectError("[sequence n]\nini = base.ini\nsim = --frames 3 --out x.rawlog\n" + cfg,
		{"[sequence n] sim", "'--out' is not allowed"});
	expectError("[sequence n]\nini = base.ini\nsim = --frames\n" + cfg, {"[sequence n] sim", "'--frames' needs a value"});
	expectError("[sequence n]\nini = base.ini\nsim = frames 3\n" + cfg, {"[sequence n] sim", "unexpected word 'frames'"});
	expectError("[sequence n]\nini = base.ini\nsim = --trajectory kitti/00.txt\n" + cfg,
		{"[sequence n] sim", "kitti/00.txt does not exist", "doc/BATCH.md"});
	expectError("[sequence n]\nini = base.ini\ngt = other.tum\nsim = --frames 3\n" + cfg,
		{"[sequence n] gt", "left out with sim"});
	expectError(seq + "[config lo]\nset = ${NOPE}\n", {"NOPE"});
}

TEST(BatchPlanFile, MissingPlanFile)
{
	try
	{
		readPlan("no/such/plan.ini");
		FAIL();
	}
	catch (const InputError& e)
	{
		EXPECT_STREQ(e.what(), "no/such/plan.ini: cannot open the plan file");
	}
}
