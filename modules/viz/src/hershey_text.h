#pragma once
// OpenCV's Hershey fonts draw ASCII only, and each byte of a UTF-8 character as its own '?': "Köln"
// came out "K??ln". Text for them keeps ASCII, writes accented Latin letters without their accents
// (ß as ss, ° as deg) and any other character as one '?'.
#include <string>

namespace vlo::viz
{
std::string hersheyText(const std::string& utf8);
}  // namespace vlo::viz
