#pragma once
// libjpeg errors as exceptions instead of an exit of the process (see jpeg_errors.cpp).

namespace vlo
{
/// Does nothing at run time: a reader that deserialises MRPT images calls it so that the linker keeps
/// jpeg_errors.cpp, whose jpeg_std_error replaces libjpeg's for the whole program.
void useThrowingJpegErrors();
}  // namespace vlo
