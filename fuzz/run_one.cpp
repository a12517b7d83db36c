#include "targets.h"

#include <vlo/core/error.h>

#include <fstream>
#include <stdexcept>
#include <typeinfo>

namespace vlo::fuzz
{
namespace
{
bool printableLine(const std::string& s)
{
	for (const char c : s)
		if ((static_cast<unsigned char>(c) < 32 && c != '\t') || c == 127) return false;
	return true;
}
}  // namespace

std::string runOne(const Target& t, const std::string& dir, const std::string& bytes)
{
	const std::string path = dir + "/" + t.file_name;
	std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
	try
	{
		t.read(path);
	}
	catch (const InputError& e)
	{
		const std::string msg = e.what();
		if (msg.find(path) == std::string::npos) return "InputError does not name the file: " + msg;
		if (!printableLine(msg)) return "InputError is not one printable line: " + msg;
	}
	catch (const std::exception& e)
	{
		return std::string("threw ") + typeid(e).name() + " instead of InputError: " + e.what();
	}
	catch (...)
	{
		return "threw a non-std exception";
	}
	return "";
}

const Target& findTarget(const std::vector<Target>& among, const std::string& name)
{
	for (const auto& t : among)
		if (t.name == name) return t;
	throw std::invalid_argument("unknown fuzz target '" + name + "'");
}
}  // namespace vlo::fuzz
