#pragma once
// The --out folder of vlo-run: a folder that holds another run, or any other file, is refused unless the user
// says --overwrite; then that run's files, and only those, are removed before the new run writes. What a run
// wrote is listed in DIR/.vlo-run-files, so a later --overwrite never touches the user's own files.
#include <set>
#include <string>

namespace vlo::pipeline
{
/// Relative paths of the regular files where a run writes: in dir itself and under dir/snapshots. Nothing else
/// is walked, so a folder such as / (with /proc) or /usr/share costs one listing and raises nothing.
std::set<std::string> filesWhereRunsWrite(const std::string& dir);

class RunFolder
{
   public:
	static constexpr const char* kManifest = ".vlo-run-files";

	/// Throws InputError naming the folder and --overwrite when it holds another run, or other files, and
	/// !overwrite. Changes nothing on disk.
	RunFolder(std::string dir, bool overwrite);
	/// Removes the previous run's files (the folder must exist) and notes what else is there.
	void clearPreviousRun();
	/// Writes the manifest: every file in the folder that was not there at clearPreviousRun().
	void recordWritten() const;
	/// Removes every file this run wrote (those not there at clearPreviousRun()), and the folders it made:
	/// a run that fails while writing (a full disk) leaves no half of itself.
	void removeWritten() const;

	/// True when `dir` holds a manifest or one of the files every vlo-run leaves (summary.json, run.ini,
	/// frames.csv, trajectory_*.tum) from before manifests existed.
	static bool holdsRun(const std::string& dir);

   private:
	std::string dir_;
	std::set<std::string> before_;  ///< relative paths of the files that are not this run's
	std::string first_made_;  ///< the highest folder of dir_ that clearPreviousRun() found missing, if any
};
}  // namespace vlo::pipeline
