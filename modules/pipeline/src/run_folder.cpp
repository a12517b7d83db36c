#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/pipeline/run_folder.h>

#include <filesystem>
#include <fstream>

namespace vlo::pipeline
{
namespace fs = std::filesystem;

std::set<std::string> filesWhereRunsWrite(const std::string& dir_name)
{
	const fs::path dir(dir_name);
	std::set<std::string> files;
	std::error_code ec;
	for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
		if (it->is_regular_file(ec)) files.insert(it->path().filename().string());
	const fs::path snapshots = dir / "snapshots";
	if (!fs::is_directory(snapshots, ec)) return files;
	for (auto it = fs::recursive_directory_iterator(snapshots, ec); !ec && it != fs::recursive_directory_iterator();
		 it.increment(ec))
		if (it->is_regular_file(ec)) files.insert(fs::relative(it->path(), dir, ec).generic_string());
	return files;
}

namespace
{
bool isVloRunFile(const std::string& name)
{
	const bool trajectory = name.rfind("trajectory_", 0) == 0 && name.size() > 15 &&
		name.compare(name.size() - 4, 4, ".tum") == 0;
	return trajectory || name == "summary.json" || name == "run.ini" || name == "frames.csv" || name == "map.pcd";
}

/// The folder as an absolute path without a trailing separator ("out/" and "out" alike).
fs::path absoluteFolder(const std::string& dir)
{
	std::error_code ec;
	fs::path p = fs::absolute(dir, ec).lexically_normal();
	return p.has_filename() ? p : p.parent_path();
}

bool holdsAnything(const std::string& dir)
{
	std::error_code ec;
	return fs::is_directory(dir, ec) && fs::directory_iterator(dir, ec) != fs::directory_iterator();
}

/// The manifest's paths; none that leaves the folder. Before manifests: the files every run leaves
/// (and the snapshots' pictures).
std::set<std::string> previousRunFiles(const fs::path& dir)
{
	std::set<std::string> files;
	std::ifstream manifest(dir / RunFolder::kManifest);
	if (manifest)
	{
		for (std::string line; std::getline(manifest, line);)
		{
			const fs::path p(line);
			if (!line.empty() && p.is_relative() && p.lexically_normal().string().rfind("..", 0) != 0) files.insert(line);
		}
		files.insert(RunFolder::kManifest);
		return files;
	}
	for (const auto& f : filesWhereRunsWrite(dir.string()))
	{
		const fs::path p(f);
		const bool snapshot = p.parent_path() == "snapshots" && p.extension() == ".png";
		if (snapshot || (p.parent_path().empty() && isVloRunFile(f))) files.insert(f);
	}
	return files;
}
}  // namespace

RunFolder::RunFolder(std::string dir, bool overwrite) : dir_(std::move(dir))
{
	std::error_code ec;
	for (fs::path p = absoluteFolder(dir_); !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
		first_made_ = p.string();
	if (overwrite) return;
	if (holdsRun(dir_))
		failInput(dir_, "holds the files of another run: give --overwrite to replace them, or another --out folder");
	if (holdsAnything(dir_))
		failInput(dir_, "is a folder with other files and no run in it: give --overwrite to write the run beside them, "
						"or another --out folder");
}

bool RunFolder::holdsRun(const std::string& dir)
{
	std::error_code ec;
	if (!fs::is_directory(dir, ec)) return false;
	if (fs::exists(fs::path(dir) / kManifest, ec)) return true;
	for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
		if (it->is_regular_file(ec) && isVloRunFile(it->path().filename().string())) return true;
	return false;
}

void RunFolder::clearPreviousRun()
{
	const fs::path root(dir_);
	for (const auto& f : previousRunFiles(root))
	{
		std::error_code ec;
		fs::path p = root / f;
		if (!fs::is_regular_file(p, ec)) continue;
		if (!fs::remove(p, ec) || ec) failInput(p.string(), "cannot remove the previous run's file (" + ec.message() + ")");
		// Folders the previous run made (snapshots/) go with their last file.
		for (p = p.parent_path(); p != root && fs::is_empty(p, ec) && !ec; p = p.parent_path()) fs::remove(p, ec);
	}
	before_ = filesWhereRunsWrite(dir_);
}

void RunFolder::removeWritten() const
{
	std::error_code ec;
	for (const auto& f : filesWhereRunsWrite(dir_))
		if (!before_.count(f)) fs::remove(fs::path(dir_) / f, ec);
	const fs::path snapshots = fs::path(dir_) / "snapshots";
	if (fs::is_directory(snapshots, ec) && fs::is_empty(snapshots, ec)) fs::remove(snapshots, ec);
	if (first_made_.empty()) return;
	for (fs::path p = absoluteFolder(dir_); !p.empty() && fs::is_empty(p, ec) && !ec; p = p.parent_path())
	{
		fs::remove(p, ec);
		if (p == first_made_) break;
	}
}

void RunFolder::recordWritten() const
{
	const std::set<std::string> now = filesWhereRunsWrite(dir_);
	AtomicOutputFile manifest(dir_ + "/" + kManifest);
	for (const auto& f : now)
		if (!before_.count(f) && f != kManifest) manifest.stream() << f << "\n";
	manifest.commit();
}
}  // namespace vlo::pipeline
