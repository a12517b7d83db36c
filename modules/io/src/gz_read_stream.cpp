#include "gz_read_stream.h"

#include <vlo/core/error.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <stdexcept>

namespace vlo::io
{
namespace fs = std::filesystem;

GzReadStream::GzReadStream(const std::string& path) : path_(path)
{
	std::error_code ec;
	if (!fs::exists(path, ec)) failInput(path, "file not found");
	if (fs::is_directory(path, ec)) failInput(path, "is a directory, expected a file");
	if (!fs::is_regular_file(path, ec)) failInput(path, "not a regular file");
	file_size_ = fs::file_size(path, ec);
	gz_ = gzopen(path.c_str(), "rb");
	if (!gz_) failInput(path, "cannot open file for reading");
	gzbuffer(static_cast<gzFile>(gz_), 1 << 17);
}

GzReadStream::~GzReadStream()
{
	if (gz_) gzclose(static_cast<gzFile>(gz_));
}

size_t GzReadStream::Read(void* buffer, size_t count)
{
	auto* gz = static_cast<gzFile>(gz_);
	size_t done = 0;
	auto* out = static_cast<char*>(buffer);
	while (done < count)
	{
		const unsigned chunk = static_cast<unsigned>(std::min<size_t>(count - done, INT_MAX / 2));
		const int n = gzread(gz, out + done, chunk);
		if (n < 0)
		{
			int err = 0;
			const char* msg = gzerror(gz, &err);
			data_error_ = msg ? msg : "unknown";
			throw std::runtime_error("gzip data error: " + data_error_);
		}
		done += static_cast<size_t>(n);
		if (static_cast<unsigned>(n) < chunk)
		{
			int err = 0;
			const char* msg = gzerror(gz, &err);
			if (err == Z_BUF_ERROR) truncated_ = true;
			// A damaged byte: zlib hands out what it inflated before it and stops with a data error, which
			// must not pass for the end of the data ("empty rawlog").
			else if (err != Z_OK && err != Z_STREAM_END)
				data_error_ = msg ? msg : "unknown";
			end_reached_ = true;
			break;
		}
	}
	return done;
}

bool GzReadStream::compressed() const { return gz_ && gzdirect(static_cast<gzFile>(gz_)) == 0; }

size_t GzReadStream::Write(const void*, size_t) { throw std::logic_error("GzReadStream is read-only"); }

uint64_t GzReadStream::Seek(int64_t, TSeekOrigin) { throw std::logic_error("GzReadStream cannot seek"); }

uint64_t GzReadStream::getPosition() const
{
	const auto p = gztell(static_cast<gzFile>(gz_));
	return p < 0 ? 0 : static_cast<uint64_t>(p);
}

double GzReadStream::progress() const
{
	if (file_size_ == 0) return 1.0;
	const auto p = gzoffset(static_cast<gzFile>(gz_));
	return p < 0 ? 0.0 : std::min(1.0, static_cast<double>(p) / static_cast<double>(file_size_));
}
}  // namespace vlo::io
