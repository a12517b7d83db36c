#include <vlo/core/stderr_capture.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace vlo
{
StderrCapture::StderrCapture()
{
	std::fflush(stderr);
	char name[] = "/tmp/vlo-stderr-XXXXXX";
	file_ = mkstemp(name);
	if (file_ < 0) return;  // no capture: the library's lines go to stderr as before
	unlink(name);
	saved_ = dup(2);
	if (saved_ < 0 || dup2(file_, 2) < 0)
	{
		close(file_);
		file_ = -1;
	}
}

std::string StderrCapture::restore()
{
	if (file_ < 0) return {};
	std::fflush(stderr);
	dup2(saved_, 2);
	close(saved_);
	std::string text;
	char buf[4096];
	lseek(file_, 0, SEEK_SET);
	for (ssize_t n; (n = read(file_, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
	close(file_);
	file_ = -1;
	return text;
}

StderrCapture::~StderrCapture()
{
	const std::string text = restore();
	if (!text.empty()) std::fputs(text.c_str(), stderr);
}

std::string withReason(const std::string& problem, const std::string& said)
{
	return said.empty() ? problem : problem + " (" + said + ")";
}

std::string StderrCapture::taken()
{
	std::istringstream in(restore());
	std::string line, joined;
	while (std::getline(in, line))
	{
		const auto b = line.find_first_not_of(" \t\r^");
		if (b == std::string::npos) continue;
		joined += (joined.empty() ? "" : "; ") + line.substr(b);
	}
	return joined;
}
}  // namespace vlo
