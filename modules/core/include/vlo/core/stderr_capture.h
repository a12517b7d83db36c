#pragma once
// Libraries that print their own errors to stderr before returning a failure (libpng through OpenCV,
// libfyaml through MRPT's YAML reader) would put lines before the one error line of an app. A call into
// them runs inside a StderrCapture: what they said becomes part of the error line, or, when the call
// succeeds, is passed on to stderr as it was.
#include <string>

namespace vlo
{
class StderrCapture
{
   public:
	StderrCapture();  ///< from now on stderr (fd 2) goes to a temporary file
	~StderrCapture();  ///< passes what was said on, unless taken()
	StderrCapture(const StderrCapture&) = delete;
	StderrCapture& operator=(const StderrCapture&) = delete;

	/// Ends the capture and returns what was said, as one line (blank lines dropped, the rest joined by
	/// "; "); the caller then owns it.
	std::string taken();

   private:
	std::string restore();
	int saved_ = -1;
	int file_ = -1;
};
/// "problem (what the library said)", or the problem alone when it said nothing.
std::string withReason(const std::string& problem, const std::string& said);
}  // namespace vlo
