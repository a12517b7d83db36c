#include "targets.h"

#include <vlo/core/error.h>
#include <vlo/pipeline/run.h>

#include <filesystem>

namespace vlo::fuzz
{
namespace
{
// vlo-run's INI path through its public entry point: every option is loaded and checked before the
// rawlog is opened, so a good INI ends in the error about the missing rawlog.
void loadRunIni(const std::string& path)
{
	const auto dir = std::filesystem::path(path).parent_path();
	pipeline::RunRequest req;
	req.ini = path;
	req.rawlog = (dir / "missing.rawlog").string();
	req.out = (dir / "out").string();
	try
	{
		pipeline::runPipeline(req);
	}
	catch (const InputError& e)
	{
		if (std::string(e.what()).rfind(req.rawlog + ": ", 0) != 0) throw;
	}
}

}  // namespace

Target iniTarget() { return {"ini", "run.ini", loadRunIni}; }
}  // namespace vlo::fuzz
