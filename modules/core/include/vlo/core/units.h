#pragma once
// Angle units, named by what they convert: angle_deg * kRadPerDeg is in radians, angle_rad *
// kDegPerRad in degrees (one name per direction; "kDeg" meant either).
#include <cmath>

namespace vlo
{
constexpr double kRadPerDeg = M_PI / 180;
constexpr double kDegPerRad = 180 / M_PI;
}  // namespace vlo
