// MRPT 2.5.8 decodes the JPEG images stored inline in a rawlog (CImage::serializeFrom) with libjpeg's
// standard error handler, whose error_exit ends the process on corrupt data: exit code 1 and
// "Not a JPEG file: starts with 0x00 0x00", with no word of which file. MRPT offers no way to pass a
// handler of our own, so this jpeg_std_error takes the place of libjpeg's in the program that links it
// (the executable's symbol wins over libjpeg.so's), sets up the handler by calling libjpeg's own (found
// with dlsym(RTLD_NEXT)), and makes error_exit throw instead, which the rawlog reader turns into its
// one-line "corrupt rawlog" error. OpenCV installs its own error_exit afterwards, as before.
// The exception unwinds through libjpeg's C frames (Debian builds them with unwind tables) up to MRPT's
// C++ caller; the abandoned decompressor's memory is not freed, which is of no matter to a reader that
// then stops with that error.
#include <dlfcn.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include <jpeglib.h>

namespace
{
[[noreturn]] void throwJpegError(j_common_ptr cinfo)
{
	char message[JMSG_LENGTH_MAX];
	(*cinfo->err->format_message)(cinfo, message);
	throw std::runtime_error(std::string("JPEG image: ") + message);
}
}  // namespace

extern "C" struct jpeg_error_mgr* jpeg_std_error(struct jpeg_error_mgr* err)
{
	using StdError = struct jpeg_error_mgr* (*)(struct jpeg_error_mgr*);
	static const auto libjpeg = reinterpret_cast<StdError>(dlsym(RTLD_NEXT, "jpeg_std_error"));
	if (!libjpeg) throw std::logic_error("jpeg_std_error called without libjpeg loaded");
	libjpeg(err);
	err->error_exit = throwJpegError;
	return err;
}
