#pragma once
// LOAM feature extraction: smoothness (curvature) of each point over its neighbours on the same
// ring; per ring sector, the sharpest points are edge features and the smoothest plane features,
// spread out by suppressing neighbours, and unreliable points (occlusion boundaries, surfaces
// grazed by the beam, optionally windows across missing returns) are never picked.
#include <vlo/loam/options.h>
#include <vlo/loam/types.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace vlo::loam
{
class FeatureExtractor
{
   public:
	explicit FeatureExtractor(const FeatureOptions& o);
	FeatureSet extract(const RingScan& scan);

	/// Curvatures of the last ring processed (index into that ring; 0 where undefined). For tests.
	const std::vector<float>& lastCurvatures() const { return curv_; }

   private:
	void extractRing(const ScanPoint* p, int n, FeatureSet& out);
	void markUnreliable(const ScanPoint* p, int n);
	void markAzimuthGaps(const ScanPoint* p, int n);
	void suppressNeighbours(const ScanPoint* p, int n, int i);
	bool isLocalMax(int i, int n) const;
	bool onSilhouette(const ScanPoint* p, int n, int i) const;

	FeatureOptions opt_;
	std::vector<float> curv_;  ///< per point of the current ring
	std::vector<float> coord_[3], diff_[3];  ///< the ring's x, y, z; the curvature's difference vector
	static constexpr std::uint8_t kSuppressed = 1, kUnreliable = 2;
	std::vector<std::uint8_t> picked_;  ///< excluded from further selection (and why)
	std::vector<std::int8_t> label_;  ///< 2 sharp, 1 less sharp, -1 flat, 0 none
	std::vector<std::pair<float, int>> order_;  ///< (curvature, index) of one sector
	std::vector<float> step_, sorted_step_;  ///< azimuth from each point to the next on the ring [rad]
};

/// Voxel downsampling of a sequence of points along one ring: consecutive points in the same voxel
/// merge into their centroid. Order-preserving and O(n), without a hash table, because a ring
/// crosses each voxel in one pass (almost always).
class RingVoxelMerger
{
   public:
	RingVoxelMerger(float leaf, ScanPoints& out) : inv_leaf_(1.0f / leaf), out_(out) {}
	~RingVoxelMerger() { flush(); }
	void add(const ScanPoint& p);
	void flush();

   private:
	float inv_leaf_;
	ScanPoints& out_;
	Eigen::Vector3i key_ = Eigen::Vector3i::Zero();
	Eigen::Vector3f sum_ = Eigen::Vector3f::Zero();
	float time_sum_ = 0;
	int ring_ = 0, count_ = 0;
};
}  // namespace vlo::loam
