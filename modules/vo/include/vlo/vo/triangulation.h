#pragma once
// Linear (DLT) triangulation of one point seen by two cameras.
#include <vlo/vo/geometry.h>

namespace vlo::vo
{
/// m1, m2: normalised image coordinates (K^-1 x, z = 1) in cameras with poses T1w, T2w.
/// Returns false for a degenerate (point at infinity or non-finite) solution.
bool triangulate(const SE3& T1w, const SE3& T2w, const Vec3& m1, const Vec3& m2, Vec3& Xw);

/// Cosine of the angle between the rays from c1 and c2 to X.
inline double parallaxCos(const Vec3& X, const Vec3& c1, const Vec3& c2)
{
	const Vec3 a = X - c1, b = X - c2;
	return a.dot(b) / (a.norm() * b.norm());
}
}  // namespace vlo::vo
