#pragma once
// A read-only MRPT stream over a gzip (or plain) file that, unlike CFileGZInputStream, tells a
// cut-off gzip file apart from a complete one: zlib reports the missing end as Z_BUF_ERROR.
#include <mrpt/io/CStream.h>

#include <string>

namespace vlo::io
{
class GzReadStream : public mrpt::io::CStream
{
   public:
	/// Throws InputError naming the file when it is missing or unreadable.
	explicit GzReadStream(const std::string& path);
	~GzReadStream() override;
	GzReadStream(const GzReadStream&) = delete;
	GzReadStream& operator=(const GzReadStream&) = delete;

	/// Short reads mean end of data; a zlib data error throws std::runtime_error.
	size_t Read(void* buffer, size_t count) override;
	size_t Write(const void* buffer, size_t count) override;
	uint64_t Seek(int64_t offset, TSeekOrigin origin = sFromBeginning) override;
	uint64_t getTotalBytesCount() const override { return file_size_; }
	uint64_t getPosition() const override;  ///< in uncompressed bytes
	std::string getStreamDescription() const override { return path_; }

	/// Fraction of the (compressed) file consumed, for progress lines.
	double progress() const;
	/// True once a read found the file ending before the gzip trailer.
	bool truncated() const { return truncated_; }
	/// True for a gzip file (false for a plain one, which zlib reads as it is).
	bool compressed() const;
	/// True once a read got fewer bytes than asked: the data ended (for a plain file, where it may).
	bool endReached() const { return end_reached_; }
	/// zlib's message once a read stopped at damaged compressed data (a flipped byte); empty otherwise.
	const std::string& dataError() const { return data_error_; }

   private:
	std::string path_;
	void* gz_ = nullptr;  // gzFile, kept opaque so that zlib.h stays out of this header
	uint64_t file_size_ = 0;
	bool truncated_ = false;
	bool end_reached_ = false;
	std::string data_error_;
};
}  // namespace vlo::io
