#pragma once
// Closest point on given rings of a ring-structured point set: what A-LOAM's scan-to-scan
// matching needs (the first neighbour, then a second point on the same and on nearby rings).
// Each ring is kept sorted by azimuth with a table of 1-degree bins for an O(1) start; the search
// walks outwards both ways from the query's azimuth and stops once the angular offset alone puts
// every further point beyond the best distance found. A ring whose elevations lie too far from the
// query's for any of its points to be closer is not searched at all.
#include <vlo/loam/types.h>

#include <vector>

namespace vlo::loam
{
class RingSearch
{
   public:
	/// A query with its azimuth and horizontal direction computed once for several rings.
	struct Query
	{
		explicit Query(const Eigen::Vector3f& q);
		Eigen::Vector3f p;
		float az, elevation, range;
	};

	/// Indexes `points` (which must outlive the searches) by ring.
	void build(const ScanPoints& points, int n_rings);
	int numRings() const { return n_rings_; }

	/// Index of the point of `ring` closest to q if closer than sqrt(best_d2), else -1; on success
	/// best_d2 becomes its squared distance. The point `exclude` is skipped. Rings outside
	/// [0, numRings) give -1.
	int nearest(int ring, const Query& q, float& best_d2, int exclude = -1) const;

   private:
	static constexpr int kBins = 360;
	struct Entry
	{
		float az;  ///< azimuth [rad]
		float ux, uy;  ///< horizontal unit direction
		float x, y, z;  ///< the point (a copy: no indirection in the search loop)
		int index;  ///< into the indexed points
	};
	static void sortByAzimuth(Entry* b, int n);

	const ScanPoints* points_ = nullptr;
	int n_rings_ = 0;
	std::vector<Entry> entries_;  ///< ring by ring, each sorted by azimuth
	std::vector<std::size_t> begin_;  ///< n_rings + 1 offsets
	std::vector<int> bin_start_;  ///< per ring and bin: first entry (ring-relative) with az >= bin start
	std::vector<float> elevation_lo_, elevation_hi_;  ///< per ring: the span of its points' elevations [rad]
};
}  // namespace vlo::loam
