#pragma once
// Output files that appear complete or not at all: written to "<path>.partial" and renamed on
// commit(); removed if destroyed uncommitted (for instance after an exception).
#include <fstream>
#include <string>

namespace vlo
{
class AtomicOutputFile
{
   public:
	explicit AtomicOutputFile(std::string path, bool binary = false);
	~AtomicOutputFile();
	AtomicOutputFile(const AtomicOutputFile&) = delete;
	AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

	std::ofstream& stream() { return out_; }
	const std::string& partialPath() const { return tmp_; }
	/// Flushes, checks for write errors (throws InputError) and renames into place.
	void commit();

   private:
	std::string path_, tmp_;
	std::ofstream out_;
	bool committed_ = false;
};

/// Renames `partial` to `final` or throws InputError naming `final`.
void commitFile(const std::string& partial, const std::string& final);
}  // namespace vlo
