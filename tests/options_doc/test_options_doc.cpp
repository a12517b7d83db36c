// doc/OPTIONS.md lists every INI option as the modules declare it (vlo/core/option_table.h). This test
// renders the list from the declarations of every registered module and fails when the doc differs;
// VLO_UPDATE_DOC=1 writes the rendered list into doc/OPTIONS.md instead.
#include <gtest/gtest.h>
#include <vlo/kernel/lidar_odometry.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>
#include <vlo/loop/options.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/lidar_options.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace vlo;

namespace
{
std::string cell(std::string text)
{
	for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
	return text;
}

/// Every section that vlo-run can load: [pipeline] and those of each registered module.
kernel::RunConfig loadEverySection()
{
	auto config = kernel::RunConfig::fromString("", "none.ini");
	pipeline::PipelineOptions pipeline;
	config.load(pipeline, "pipeline");
	pipeline::LidarOptions times;
	config.load(times, "lidar");
	loop::LoopOptions loop;
	config.load(loop, "loop");
	for (auto& [name, m] : kernel::registry<kernel::VisualOdometryModule>().createAll()) m->configure(config);
	for (auto& [name, m] : kernel::registry<kernel::ScaleCorrectionModule>().createAll()) m->configure(config, 0);
	for (auto& [name, m] : kernel::registry<kernel::LidarOdometryModule>().createAll()) m->configure(config);
	return config;
}

std::string render(const kernel::RunConfig& config)
{
	std::ostringstream md;
	md << "# INI options\n\n"
	   << "Every option of every module, as its options struct declares it (`declare()` in the module's\n"
	   << "options file, read and checked by `vlo/core/option_table.h`). Generated: `VLO_UPDATE_DOC=1\n"
	   << "build/bin/test_options_doc` rewrites this file; the test fails while it differs from the declarations.\n"
	   << "Allowed: a range (`> 0`, `[1, 16]`, `(0, 1]`), the words a value may be, or `any`.\n\n"
	   << "A value that does not parse as its type or lies outside its range stops the run with one line naming\n"
	   << "where it came from: `--set loam.mapping.map_radius=abc: expects a number, got 'abc'`, or\n"
	   << "`run.ini: [loam.mapping] map_radius: expects a number, got 'abc'`. An unknown section or key is an error\n"
	   << "too, with the nearest known name suggested (`did you mean map_radius?`). Checks between keys (\"max_range\n"
	   << "must exceed min_range\") are in each struct's `checkRelations()` and are not listed here.\n";
	for (const auto& [section, rows] : config.declared())
	{
		md << "\n## [" << section << "]\n\n| key | default | allowed | meaning |\n|---|---|---|---|\n";
		for (const auto& r : rows)
			md << "| `" << r.key << "` | " << cell(r.default_text) << " | " << cell(r.allowed) << " | " << cell(r.help) << " |\n";
	}
	return md.str();
}
}  // namespace

TEST(OptionsDoc, ListsEveryDeclaredOption)
{
	const std::string path = std::string(VLO_SOURCE_DIR) + "/doc/OPTIONS.md";
	const std::string rendered = render(loadEverySection());
	if (std::getenv("VLO_UPDATE_DOC"))
	{
		std::ofstream(path) << rendered;
		return;
	}
	std::ifstream in(path);
	std::stringstream doc;
	doc << in.rdbuf();
	EXPECT_EQ(doc.str(), rendered) << path << " differs from the declarations: VLO_UPDATE_DOC=1 build/bin/test_options_doc";
}

TEST(OptionsDoc, CoversEveryModuleFamily)
{
	const auto config = loadEverySection();
	for (const char* section : {"pipeline", "vo.orb", "vo.mapping", "scale", "loam.scan", "loam.prior", "icp", "loop"})
		EXPECT_EQ(config.declared().count(section), 1u) << section;
	EXPECT_GE(config.declared().at("loam.mapping").size(), 20u);
}
