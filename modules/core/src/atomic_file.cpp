#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>

#include <cstdio>
#include <cstring>
#include <cerrno>

namespace vlo
{
AtomicOutputFile::AtomicOutputFile(std::string path, bool binary)
	: path_(std::move(path)), tmp_(path_ + ".partial")
{
	out_.open(tmp_, binary ? std::ios::out | std::ios::binary : std::ios::out);
	if (!out_) failInput(path_, std::string("cannot open for writing: ") + std::strerror(errno));
	out_.precision(9);
}

AtomicOutputFile::~AtomicOutputFile()
{
	if (!committed_)
	{
		out_.close();
		std::remove(tmp_.c_str());
	}
}

void AtomicOutputFile::commit()
{
	out_.flush();
	if (!out_) failInput(path_, "write failed (disk full?)");
	out_.close();
	commitFile(tmp_, path_);
	committed_ = true;
}

void commitFile(const std::string& partial, const std::string& final)
{
	if (std::rename(partial.c_str(), final.c_str()) != 0)
		failInput(final, std::string("cannot move output into place: ") + std::strerror(errno));
}
}  // namespace vlo
