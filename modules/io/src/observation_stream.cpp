#include "observation_stream.h"

#include <vlo/core/error.h>
#include <vlo/io/allocation_limit.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <new>

namespace vlo::io
{
using mrpt::obs::CObservation;

namespace
{
/// No buffer of a real rawlog comes near this (a 64-beam scan is a few MB): a larger one is a corrupt count.
constexpr std::size_t kMaxBufferBytes = std::size_t{256} << 20;
}  // namespace

std::string mrptMessage(const std::string& what)
{
	// MRPT nests "Message: ..." blocks, outermost first; the last one names the actual failure.
	std::string line = what;
	const auto m = what.rfind("Message:");
	if (m != std::string::npos)
	{
		const auto start = what.find_first_not_of(' ', m + 8);
		line = what.substr(start, what.find('\n', start) - start);
	}
	else if (const auto nl = what.find('\n'); nl != std::string::npos)
		line.resize(nl);
	for (char& c : line)
		if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
	return line;
}

ObservationStream::ObservationStream(const std::string& path)
	: path_(path), in_(path), ar_(mrpt::serialization::archiveUniquePtrFrom(in_))
{
	if (!readObject()) failInput(path_, "empty rawlog: no observations");
}

CObservation::Ptr ObservationStream::next()
{
	while (pending_.empty())
		if (!readObject()) return nullptr;
	auto obs = pending_.front();
	pending_.pop_front();
	return obs;
}

void ObservationStream::failSizePastTheEnd(const std::string& nth) const
{
	failInput(path_, "corrupt rawlog at " + nth + ": a size in it runs past the end of the (complete) file");
}

bool ObservationStream::readObject()
{
	if (end_) return false;
	const std::string nth = "object " + std::to_string(objects_ + 1);
	const uint64_t before = in_.getPosition();
	mrpt::serialization::CSerializable::Ptr obj;
	try
	{
		const ScopedAllocationLimit limit(kMaxBufferBytes);
		obj = ar_->ReadObject();
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		if (!in_.dataError().empty()) failInput(path_, "corrupt gzip data in " + nth + " (" + in_.dataError() + ")");
		// A clean end reads nothing; a cut-off file ends inside an object or before the gzip trailer. A
		// complete gzip file (its trailer read) that ends inside an object has a size in it that is wrong.
		if (in_.getPosition() != before && in_.compressed() && !in_.truncated()) failSizePastTheEnd(nth);
		if (in_.getPosition() != before) failInput(path_, "truncated: the file ends inside " + nth);
		if (in_.truncated())
			failInput(path_, "truncated: the gzip stream is cut off after " + std::to_string(objects_) + " objects");
		end_ = true;
		return false;
	}
	catch (const std::bad_alloc&)
	{
		failInput(path_, "corrupt rawlog: absurd size while reading " + nth);
	}
	catch (const std::exception& e)
	{
		if (!in_.dataError().empty()) failInput(path_, "corrupt gzip data in " + nth + " (" + in_.dataError() + ")");
		if (in_.endReached() && in_.getPosition() != before && in_.compressed() && !in_.truncated()) failSizePastTheEnd(nth);
		// A gzip file cut off, or a plain one ending inside the object.
		if (in_.truncated() || (in_.endReached() && in_.getPosition() != before))
			failInput(path_, "truncated: the file ends inside " + nth);
		if (objects_ == 0) failInput(path_, "not an MRPT rawlog (" + mrptMessage(e.what()) + ")");
		failInput(path_, "corrupt rawlog at " + nth + ": " + mrptMessage(e.what()));
	}
	++objects_;
	if (auto obs = std::dynamic_pointer_cast<CObservation>(obj))
		pending_.push_back(obs);
	else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
		for (const auto& o : *sf) pending_.push_back(o);
	else if (!std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
		failInput(path_,
			std::string(objects_ == 1 ? "not an MRPT rawlog" : "unexpected object") + " (" + nth +
				" is a " + obj->GetRuntimeClass()->className + ")");
	return true;
}
}  // namespace vlo::io
