#include <vlo/core/error.h>
#include <vlo/rosbag/bag_structure.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace vlo::rosbag_io
{
namespace
{
// Record kinds ("op") of the bag format 2.0 (wiki.ros.org/Bags/Format/2.0).
constexpr std::uint8_t kMessageData = 0x02, kBagHeader = 0x03, kIndexData = 0x04, kChunk = 0x05, kChunkInfo = 0x06,
					   kConnection = 0x07;
constexpr std::uint64_t kMaxChunkBytes = 256ull << 20;  // far above rosbag's 768 kB chunks, far below memory
constexpr std::uint64_t kMaxHeaderBytes = 1 << 20;  // record headers hold a few names and numbers

std::uint32_t u32(const char* p)
{
	std::uint32_t v;
	std::memcpy(&v, p, 4);  // little-endian, like the machines that run vlo
	return v;
}

std::uint64_t u64(const char* p)
{
	std::uint64_t v;
	std::memcpy(&v, p, 8);
	return v;
}

struct Record
{
	std::uint64_t pos = 0;  ///< of its header length
	std::map<std::string, std::string> fields;
	std::uint64_t data_pos = 0, data_len = 0;
	std::uint8_t op() const
	{
		const auto it = fields.find("op");
		return it == fields.end() || it->second.size() != 1 ? 0 : static_cast<std::uint8_t>(it->second[0]);
	}
};

/// Reads the records of a bag file without holding more than one record header in memory.
class Walker
{
   public:
	Walker(const std::string& path, std::uint64_t size) : path_(path), in_(path, std::ios::binary), size_(size) {}

	std::uint64_t size() const { return size_; }

	/// `len` bytes at `pos`, which the caller has checked to be inside the file.
	std::string bytes(std::uint64_t pos, std::uint64_t len)
	{
		std::string b(len, '\0');
		in_.clear();
		in_.seekg(static_cast<std::streamoff>(pos));
		if (!in_.read(b.data(), static_cast<std::streamsize>(len))) fail(pos, "a record", "cannot read");
		return b;
	}

	/// The record at `pos` (inside [pos, end)), its header parsed; throws if it does not fit.
	Record read(std::uint64_t pos, std::uint64_t end, const char* where)
	{
		Record r;
		r.pos = pos;
		fits(pos, 4, end, where);
		const std::uint64_t header_len = u32(bytes(pos, 4).data());
		if (header_len > kMaxHeaderBytes) fail(pos, where, "a header of " + std::to_string(header_len) + " bytes");
		fits(pos + 4, header_len + 4, end, where);
		const std::string header = bytes(pos + 4, header_len + 4);
		for (std::uint64_t p = 0; p < header_len;)
		{
			fits(p, 4, header_len, where);
			const std::uint64_t len = u32(header.data() + p);
			fits(p + 4, len, header_len, where);
			const std::string field = header.substr(p + 4, len);
			const auto eq = field.find('=');
			if (eq == std::string::npos) fail(pos, where, "a header field without '='");
			r.fields[field.substr(0, eq)] = field.substr(eq + 1);
			p += 4 + len;
		}
		r.data_pos = pos + 4 + header_len + 4;
		r.data_len = u32(header.data() + header_len);
		fits(r.data_pos, r.data_len, end, where);
		return r;
	}

	std::uint64_t number(const Record& r, const char* name, std::size_t bytes, const char* where) const
	{
		const auto it = r.fields.find(name);
		if (it == r.fields.end() || it->second.size() != bytes)
			fail(r.pos, where, std::string("field '") + name + "' missing or not " + std::to_string(bytes) + " bytes");
		return bytes == 4 ? u32(it->second.data()) : u64(it->second.data());
	}

	[[noreturn]] void fail(std::uint64_t pos, const char* where, const std::string& what) const
	{
		failInput(path_, std::string("not a readable ROS 1 bag (truncated or corrupt?): ") + where + " at byte " + std::to_string(pos) + ": " + what);
	}

   private:
	bool fits(std::uint64_t pos, std::uint64_t len, std::uint64_t end, const char* where) const
	{
		if (pos > end || len > end - pos) fail(pos, where, "a length of " + std::to_string(len) + " bytes runs past its end");
		return true;
	}

	std::string path_;
	std::ifstream in_;
	std::uint64_t size_;
};

/// The records inside an uncompressed chunk (messages, connections) must fit in it.
void checkChunkContents(Walker& w, const Record& chunk)
{
	const std::uint64_t end = chunk.data_pos + chunk.data_len;
	for (std::uint64_t p = chunk.data_pos; p < end;)
	{
		const Record r = w.read(p, end, "a record inside a chunk");
		if (r.op() != kMessageData && r.op() != kConnection) w.fail(p, "a record inside a chunk", "neither a message nor a connection");
		p = r.data_pos + r.data_len;
	}
}
}  // namespace

void checkBagStructure(const std::string& path)
{
	std::error_code ec;
	const std::uint64_t size = std::filesystem::file_size(path, ec);
	if (ec) failInput(path, "cannot open (" + ec.message() + ")");
	Walker w(path, size);
	const std::string magic = "#ROSBAG V2.0\n";
	if (size < magic.size() || w.bytes(0, magic.size()) != magic)
		failInput(path, "not a ROS 1 bag (format 2.0): it does not start with '#ROSBAG V2.0'");
	std::set<std::uint64_t> chunks, records;
	std::uint64_t index_pos = 0, chunk_size = 0;  // of the bag header; of the last chunk
	bool seen_chunk = false;
	for (std::uint64_t p = magic.size(); p < size;)
	{
		const Record r = w.read(p, size, "a record");
		records.insert(p);
		switch (r.op())
		{
			case kBagHeader:
				index_pos = w.number(r, "index_pos", 8, "the bag header");
				break;
			case kChunk:
			{
				const auto c = r.fields.find("compression");
				chunk_size = w.number(r, "size", 4, "a chunk");
				if (c == r.fields.end()) w.fail(p, "a chunk", "no compression field");
				if (c->second == "none" && chunk_size != r.data_len)
					w.fail(p, "a chunk", "uncompressed, but its size field says " + std::to_string(chunk_size) + " bytes");
				if (chunk_size > kMaxChunkBytes) w.fail(p, "a chunk", "unpacks to " + std::to_string(chunk_size) + " bytes");
				if (c->second == "none") checkChunkContents(w, r);
				chunks.insert(p);
				seen_chunk = true;
				break;
			}
			case kIndexData:  // entries (time, offset into the chunk before it) of one connection
			{
				const std::uint64_t count = w.number(r, "count", 4, "an index");
				if (!seen_chunk || count * 12 != r.data_len || r.data_len > chunk_size)
					w.fail(p, "an index", "does not fit its chunk");
				const std::string entries = w.bytes(r.data_pos, r.data_len);
				for (std::uint64_t k = 0; k < count; ++k)
					if (u32(entries.data() + 12 * k + 8) >= chunk_size) w.fail(p, "an index", "an offset past its chunk");
				break;
			}
			case kChunkInfo:
				if (!chunks.count(w.number(r, "chunk_pos", 8, "a chunk info")))
					w.fail(p, "a chunk info", "its chunk_pos is no chunk");
				if (w.number(r, "count", 4, "a chunk info") * 8 != r.data_len) w.fail(p, "a chunk info", "a wrong count");
				break;
			case kConnection:
			case kMessageData:
				break;
			default:
				w.fail(p, "a record", "unknown op");
		}
		p = r.data_pos + r.data_len;
	}
	// A recording that was not closed (the recorder killed, the power lost) has no index; rosbag can rebuild it.
	const std::string reindex = "; 'rosbag reindex " + path + "' rebuilds the index of a bag whose recording was cut short";
	if (index_pos == 0) failInput(path, "the bag has no index (index_pos is 0)" + reindex);
	if (!records.count(index_pos))
		failInput(path, "not a readable ROS 1 bag (truncated or corrupt?): its index position is no record" + reindex);
}
}  // namespace vlo::rosbag_io
