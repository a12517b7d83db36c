#include <vlo/core/interrupt.h>
#include <vlo/core/progress.h>

#include <unistd.h>

#include <cstdio>

namespace vlo
{
namespace
{
int g_enabled = -1;  // -1: decide by isatty
bool enabled()
{
	if (g_enabled < 0) g_enabled = isatty(fileno(stderr)) ? 1 : 0;
	return g_enabled == 1;
}
}  // namespace

void ProgressLine::setEnabled(bool on) { g_enabled = on ? 1 : 0; }

ProgressLine::ProgressLine(std::string label, std::size_t total)
	: label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()), last_(start_)
{
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(std::size_t done, double fraction)
{
	throwIfInterrupted();  // every long loop reports progress: the place to stop it
	done_ = done;
	if (!enabled()) return;
	const auto now = std::chrono::steady_clock::now();
	if (printed_ && now - last_ < std::chrono::milliseconds(200)) return;
	last_ = now;
	printed_ = true;
	const double secs = std::chrono::duration<double>(now - start_).count();
	const double rate = secs > 0 ? done / secs : 0;
	if (total_ == 0 && fraction > 0)
		std::fprintf(stderr, "\r%s %zu  %.1f/s  %3.0f%%  ETA %.0f s   ", label_.c_str(), done, rate, 100 * fraction,
			secs * (1 - fraction) / fraction);
	else if (total_ > 0 && rate > 0)
		std::fprintf(stderr, "\r%s %zu/%zu  %.1f/s  ETA %.0f s   ", label_.c_str(), done, total_, rate,
			(total_ - done) / rate);
	else
		std::fprintf(stderr, "\r%s %zu  %.1f/s   ", label_.c_str(), done, rate);
	std::fflush(stderr);
}

void ProgressLine::finish()
{
	if (printed_ && enabled()) std::fprintf(stderr, "\n");
	printed_ = false;
}
}  // namespace vlo
