#pragma once
// Scan-to-map registration (A-LOAM laserMapping), run every frame: the scan's edge and plane
// points, downsampled, are matched to lines and planes fitted to their nearest map points, the
// pose is refined from the odometry's guess, and the scan is added to the bounded local map.
#include <vlo/loam/degeneracy.h>
#include <vlo/loam/free_space.h>
#include <vlo/loam/options.h>
#include <vlo/loam/pose_prior.h>
#include <vlo/loam/pose_solver.h>
#include <vlo/loam/types.h>
#include <vlo/loam/voxel_map.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace vlo::loam
{
class ScanToMap
{
   public:
	/// A scan's points used for matching, downsampled, in the LiDAR frame.
	struct Input
	{
		std::vector<Eigen::Vector3f> edges, planes;
		std::vector<std::uint8_t> edge_silhouette;  ///< per edge: 1 on a silhouette (FeatureSet)
	};
	struct Result
	{
		Eigen::Isometry3d T_map_curr = Eigen::Isometry3d::Identity();
		bool ok = false;  ///< false: T_map_curr is the guess
		std::string reason;
		int rounds = 0;  ///< correspondence + solve rounds run
		int iterations = 0;
		int n_edges = 0, n_planes = 0;  ///< matches of the last round
		bool used_edges = false;  ///< edge matches were sought (edges = on, or auto and the planes are weak)
		bool used_rough_planes = false;  ///< rough planes were matched too (planes and lines leave the translation free)
		double plane_information = 0;  ///< the planes' translation information at the guess
		double rms = 0;  ///< distance RMS at the solution [m]
		/// With a pose prior: how much it raised the matches' cost (geometryCostOfPrior) [m^2]
		double prior_geometry_cost = 0;
		Degeneracy degeneracy;
		/// Robust-weighted J^T J of the last round at the solution, over [rotation; translation] of
		/// T_map_curr as Degeneracy's (the pose's information up to the residuals' variance).
		Eigen::Matrix<double, 6, 6> JtJ = Eigen::Matrix<double, 6, 6>::Zero();
		std::vector<Eigen::Vector3f> arrived;  ///< points in the previous scan's free space, not matched (map frame)
	};

	explicit ScanToMap(const MappingOptions& o);

	Input prepare(const FeatureSet& f) const;
	/// Refines the pose of the scan in the map from `guess`, with `prior` a residual of the solve
	/// if given; does not change the map.
	Result align(const Input& in, const Eigen::Isometry3d& guess, const PosePrior* prior = nullptr) const;
	/// Adds the scan's less-sharp and less-flat points at pose T_map_curr, except those within
	/// arrival_radius of `arrived` (map frame), and drops the far map.
	void insert(const FeatureSet& f, const Eigen::Isometry3d& T_map_curr, const std::vector<Eigen::Vector3f>& arrived = {});
	/// Removes the map points within free_space_radius that the scan's beams pass by, and keeps
	/// the scan's free space for the next align(); returns how many points went.
	std::size_t carve(const FeatureSet& f, const Eigen::Isometry3d& T_map_curr);
	void clear();

	bool empty() const { return edge_map_.numPoints() == 0 && plane_map_.numPoints() == 0; }
	const VoxelMap& edgeMap() const { return edge_map_; }
	const VoxelMap& planeMap() const { return plane_map_; }

	/// What a round matches besides the planes: lines; and whether the planes may be rough (up to
	/// rough_plane_max_distance off their neighbours rather than plane_max_distance).
	struct MatchKinds
	{
		bool edges = false, rough_planes = false;
	};
	/// One round's matches for `in` at pose T.
	void findMatches(const Input& in, const Eigen::Isometry3d& T, MatchKinds kinds, Matches& out) const;
	/// How well the scan's plane points at pose T fit the map's planes: the sum of their weights
	/// under the robust loss (1 for a point on its plane, less the farther it lies).
	double planeFit(const Input& in, const Eigen::Isometry3d& T) const;

   private:
	/// The scan's edge points downsampled to `leaf`, creases first, then silhouettes: how many are creases.
	std::size_t downsampledEdges(const FeatureSet& f, double leaf, std::vector<Eigen::Vector3f>& out) const;
	/// Whether a flat line (its place depends on the view) has map points seen from beyond the reach.
	bool seenFromTooFar(const Eigen::Vector3d& u, const std::uint32_t* tags, int k, const Eigen::Isometry3d& T) const;
	/// Keeps, in order, those of the n map points nn (with their tags) seen from within
	/// outline_view_change_deg of the direction `here` sees q from; how many.
	int keepSimilarViews(const Eigen::Vector3f& q, const Eigen::Vector3f& here, Eigen::Vector3f* nn, std::uint32_t* tags, int n) const;
	/// Whether some of the k map points nn (with their tags) were seen from a range more than
	/// edge_range_ratio times or less than 1 / edge_range_ratio times the range of scan point p.
	bool seenFromOtherRange(const Eigen::Vector3f& p, const Eigen::Vector3f* nn, const std::uint32_t* tags, int k) const;
	/// Appends the line matches of `in` at pose T to out.edges.
	void findEdgeMatches(const Input& in, const Eigen::Isometry3d& T, Matches& out) const;
	/// Appends the plane matches of `in` at pose T (neighbours within max_distance of their plane) to out.planes.
	void findPlaneMatches(const Input& in, const Eigen::Isometry3d& T, double max_distance, Matches& out) const;
	/// Information on the translation along its weakest direction of these matches at T (robust-weighted
	/// J^T J, rotation marginalised).
	double translationInformation(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes,
		const Eigen::Isometry3d& T) const;
	/// Correspondence + solve rounds from res.T_map_curr until converged; false (res.reason set)
	/// when too few matches.
	bool refine(const Input& in, Result& res, const PosePrior* prior) const;
	/// `in` without the points that lie, at pose T, in the previous scan's free space: something
	/// moved there (they go to res.arrived).
	Input withoutArrivals(const Input& in, const Eigen::Isometry3d& T, Result& res) const;
	/// A plane through the nearest map points of q, all within max_distance of it.
	bool fitPlane(const Eigen::Vector3f& q, double max_distance, Eigen::Vector3f* nn, PlaneMatch& out) const;

	MappingOptions opt_;
	VoxelMap edge_map_, plane_map_;
	std::uint32_t scans_inserted_ = 0;  ///< scan-line tags: (scan << 8) | ring
	/// Where the sensor stood at each scan inserted: edge map tags are (scan << 1) | silhouette.
	std::vector<Eigen::Vector3f> scan_origins_;
	std::optional<FreeSpace> last_free_;  ///< the last carving scan's free space ...
	Eigen::Isometry3d T_map_last_ = Eigen::Isometry3d::Identity();  ///< ... and its pose
};
}  // namespace vlo::loam
