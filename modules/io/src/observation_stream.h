#pragma once
// Observations of a rawlog one at a time, whatever its format (observation-only, or action +
// sensory-frame pairs). MRPT's exceptions become one-line InputErrors naming the file.
#include "gz_read_stream.h"

#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CArchive.h>

#include <deque>
#include <string>

namespace vlo::io
{
class ObservationStream
{
   public:
	/// Reads the first object, so a file that is not a rawlog fails here.
	explicit ObservationStream(const std::string& path);

	/// The next observation, or nullptr at the end. Throws InputError if the file is cut off or corrupt.
	mrpt::obs::CObservation::Ptr next();
	double progress() const { return in_.progress(); }
	const std::string& path() const { return path_; }

   private:
	/// Reads one top-level object into pending_; false at the end of the file.
	bool readObject();
	/// A complete gzip file that ends inside an object: a length in it is corrupt, not the file cut short.
	[[noreturn]] void failSizePastTheEnd(const std::string& nth) const;

	std::string path_;
	GzReadStream in_;
	mrpt::serialization::CArchive::UniquePtr ar_;
	std::deque<mrpt::obs::CObservation::Ptr> pending_;
	std::size_t objects_ = 0;
	bool end_ = false;
};

/// The innermost "Message:" of an MRPT exception text, on one printable line.
std::string mrptMessage(const std::string& what);
}  // namespace vlo::io
