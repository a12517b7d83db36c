#pragma once
// Errors caused by the user's input (files, options, data) as opposed to bugs.
// Apps print what() as one line and exit non-zero.
#include <stdexcept>
#include <string>

namespace vlo
{
class InputError : public std::runtime_error
{
   public:
	/// `where` is the file (or option, or sensor) at fault; `problem` says what is wrong with it.
	InputError(const std::string& where, const std::string& problem)
		: std::runtime_error(where + ": " + problem)
	{
	}
};

[[noreturn]] inline void failInput(const std::string& where, const std::string& problem)
{
	throw InputError(where, problem);
}
}  // namespace vlo
