#pragma once
// Options of the LiDAR odometry and mapping, one CLoadableOptions struct per stage.
// INI sections: [loam.scan], [loam.features], [loam.odometry], [loam.mapping], [loam.prior].
// Every default below is the value used when the key is absent; saveToConfigFile() writes them all
// with a comment, so a saved file lists every known key.
#include <vlo/core/option_table.h>

#include <string>
#include <vector>

namespace vlo::loam
{
/// Scan preprocessing: ring assignment, range gating, deskew passes.
struct ScanOptions : public OptionSet
{
	std::string ring_model = "uniform";  ///< uniform | hdl64 | table
	int n_rings = 16;  ///< beams of the uniform model
	double vfov_min_deg = -15.0, vfov_max_deg = 15.0;  ///< lowest/highest beam (uniform)
	std::vector<double> elevation_table_deg;  ///< beam elevations (table model), any order
	double fov_margin_deg = 0.5;  ///< accepted beyond the lowest/highest beam
	double min_range = 3.0;  ///< closer returns (vehicle body, noise) are dropped [m]
	double max_range = 150.0;  ///< farther returns are dropped [m]
	/// A scan with point times ([lidar] point_times) is deskewed to the frame's time, and registered
	/// again while the motion found still changes
	int max_deskew_passes = 3;  ///< deskew + register again while the motion found still changes
	/// ... by more than this [m] (a rolling sweep's drift needs it settled to millimetres)
	double deskew_tolerance = 0.002;
	double deskew_tolerance_deg = 0.02;  ///< ... or this [deg]

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Curvature-based feature selection (LOAM section IV-A).
struct FeatureOptions : public OptionSet
{
	int curvature_half_window = 5;  ///< neighbours on each side on the same ring
	int n_sectors = 6;  ///< per ring, for an even spread of features
	int max_sharp = 2, max_less_sharp = 20, max_flat = 4;  ///< per sector
	double sharp_threshold = 0.1;  ///< curvature above: edge candidate [m^2]
	double flat_threshold = 0.1;  ///< curvature below: plane candidate [m^2]
	double suppress_gap_sq = 0.05;  ///< neighbour suppression stops at a gap this large [m^2]
	bool sharp_local_max = true;  ///< edges only where the curvature peaks within the window
	double less_flat_leaf = 0.2;  ///< voxel size of the less-flat downsampling [m]
	double less_flat_threshold = 0.1;  ///< less-flat points: curvature below this [m^2]
	bool reject_occluded = true;
	double occlusion_gap_sq = 0.1;  ///< consecutive points this far apart may be an occlusion [m^2]
	double occlusion_angle = 0.1;  ///< ... if their beams are closer than this [rad]
	bool reject_parallel = true;
	double parallel_ratio = 0.0002;  ///< gap^2 > ratio * range^2 on both sides: beam grazes a surface
	double max_azimuth_gap = 0;  ///< a window spanning a gap wider than this many firing steps is unreliable (0: off)
	int min_rings = 4;  ///< fewer populated rings: the frame is skipped
	int min_sharp = 10, min_flat = 30;  ///< fewer features: the frame is skipped

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Robust nonlinear least squares settings shared by both registrations.
struct SolverOptions
{
	int outer_iterations = 2;  ///< correspondence search + solve rounds
	int max_solver_iterations = 4;  ///< reweighted Levenberg-Marquardt iterations per round
	std::string loss = "huber";  ///< huber | cauchy | none
	double loss_scale = 0.05;  ///< residual scale where the robust loss bends [m]
	double converged_translation = 0.005;  ///< a round moving less than this ends the rounds [m]
	double converged_rotation_deg = 0.02;  ///< ... and turning less than this [deg]
};

/// Scan-to-scan registration against the previous scan's features.
struct OdometryOptions : public OptionSet
{
	bool enabled = true;
	SolverOptions solver;
	double max_match_distance = 5.0;  ///< nearest-neighbour gate [m]
	int nearby_rings = 2;  ///< rings searched on each side for the second/third point
	bool use_kdtree = false;  ///< first neighbour from a kd-tree (A-LOAM) instead of the ring index
	int min_correspondences = 20;  ///< fewer: keep the initial guess
	/// A plane match also needs the reference point next to its third one within this of the plane:
	/// among foliage three points span a "plane" through leaves (0: no check) [m].
	double plane_max_distance = 0.03;
	/// Rounds go on past solver.outer_iterations while a round still moves the pose (a guess far
	/// from the motion: a cold start at speed, a gap), up to this many in all.
	int max_rounds = 30;
	/// The first motion of a drive (no velocity known yet) is searched from translations up to this
	/// far along the LiDAR's x and y axes (a start at speed: doc/LOAM.md), 0: from the zero motion only [m] ...
	double cold_start_range = 3.0;
	double cold_start_step = 0.75;  ///< ... this far apart [m]

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Scan-to-map registration and the bounded local map.
struct MappingOptions : public OptionSet
{
	/// Cauchy: matches to what moved or what the map holds from elsewhere weigh less (doc/LOAM.md step 5).
	MappingOptions() { solver.loss = "cauchy"; }

	bool enabled = true;
	SolverOptions solver;
	/// Edge points matched to lines of the map: "on" (A-LOAM), "off" (planes only, no edge map), or
	/// "auto": only in frames where the planes alone leave the translation weak (a corridor, trees),
	/// since lines bias the pose where planes suffice (curbs: pitch; vehicles: the step; doc/LOAM.md).
	std::string edges = "auto";
	/// The planes leave the translation weak when its information along the weakest direction
	/// (robust-weighted J^T J of the plane matches, rotation marginalised, as [loam.prior]) is below
	/// this: edges = auto seeks lines where it is at the guess; and no round goes past
	/// solver.outer_iterations where the matches in use (planes, and lines when sought) leave it so
	/// weak at the pose reached.
	double weak_plane_information = 30;
	/// Rounds go on past solver.outer_iterations while a round still moves the pose and the planes
	/// fix the translation (a guess centimetres off that skipped scan-to-scan), up to this many in
	/// all; along a corridor further rounds would slide off the guess, so A-LOAM's two stay there.
	int max_rounds = 10;
	double edge_leaf = 0.4, plane_leaf = 0.8;  ///< downsampling of the scan's features [m]
	double map_edge_resolution = 0.2, map_plane_resolution = 0.4;  ///< one map point per cell [m]
	double voxel_size = 2.0;  ///< hash voxel edge; >= 2 * max_nn_distance keeps the search exact [m]
	int max_points_per_voxel = 80;
	double map_radius = 150.0;  ///< voxels farther from the vehicle are dropped [m]
	int knn = 8;  ///< A-LOAM: 5; 8 lets fewer false lines through (doc/LOAM.md step 4)
	double max_nn_distance = 1.0;  ///< all knn neighbours must be this close [m]
	double edge_eigen_ratio = 3.0;  ///< line if largest eigenvalue > ratio * middle one
	/// no line where its points spread across it within a surface: middle eigenvalue > ratio * smallest
	/// (floored at 1 cm squared); 0: off, as A-LOAM
	double edge_flatness_ratio = 5.0;
	/// Lines that depend on the view are matched only against map points seen from nearby
	/// (doc/LOAM.md "Known limits"): a ring (a cone about the spin axis) meets a line at most as
	/// steeply as the line rises out of the plane normal to that axis, so where it meets a flat line
	/// (a curb, a sill) moves with the sensor. Seen from within a few metres (as scan-to-scan sees
	/// them) such lines hold; from the map's whole past they pulled a real drive short. Flat: below
	/// this elevation [deg] ...
	double min_line_elevation_deg = 53.0;
	double view_dependent_reach = 3.0;  ///< ... nearby: within this of the current position [m] (0: any)
	/// A line through outline points (silhouettes: the beam leaves a body for a farther surface,
	/// FeatureSet) is fit only from map points seen from within this angle of the direction the
	/// point is seen from now (horizontal bearing from the sensor) [deg]: on a rounded body (a
	/// trunk, a pole, a hedge, a car) the outline lies where the view grazes it and moves round the
	/// body as the view turns; fit from views all round, such lines pulled a real drive short
	/// (doc/LOAM.md step 4). 0: from any view, as A-LOAM.
	double outline_view_change_deg = 45.0;
	/// An edge's apparent place depends on the range it is seen from (a real beam's footprint grows
	/// with range and the nearest surface within it answers, so outlines and corners bloom; which
	/// laser sees it changes with range): lines are matched only against map points seen from
	/// within this factor of the edge point's own range (0: any; doc/LOAM.md "Known limits").
	double edge_range_ratio = 0.0;
	double plane_max_distance = 0.05;  ///< plane if every neighbour is this close to it [m]
	/// Where the planes and lines at the guess leave the translation nearly free (its information
	/// along the weakest direction, as weak_plane_information, below rough_plane_information), planes
	/// whose neighbours lie up to rough_plane_max_distance off them count too (A-LOAM: 0.2 m
	/// everywhere): among trees a 16-beam scan's only other surfaces are canopies and hedges
	/// (doc/LOAM.md step 4). <= plane_max_distance: off.
	double rough_plane_max_distance = 0.25;
	double rough_plane_information = 3.0;
	double plane_line_ratio = 10.0;  ///< not a plane if largest eigenvalue > ratio * middle (a line)
	int min_edge_correspondences = 0, min_plane_correspondences = 50;  ///< fewer: keep the odometry pose (edges are optional: some scenes have none)
	double degeneracy_threshold = 10.0;  ///< min eigenvalue of J^T J below: degenerate
	/// Moving things (doc/LOAM.md "Moving things"), from the free space each scan sees: map points
	/// within this distance that a beam of the scan passes by and returns from beyond are removed,
	/// and the next scan's points in that free space are not matched (0: off) [m] ...
	double free_space_radius = 50.0;
	double free_space_beam_radius = 0.1;  ///< ... passing within this [m] ...
	double free_space_margin = 0.5;  ///< ... returning from this much farther [m] ...
	double free_space_margin_per_metre = 0.1;  ///< ... plus this per metre of range
	int free_space_azimuth_bins = 900;  ///< azimuth bins of the scan's range image
	bool drop_arrivals = false;  ///< the scan's points in the previous scan's free space are not matched ...
	double arrival_radius = 1.0;  ///< ... and its points this close to them stay out of the map [m]

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Source of the initial guess of each frame's motion.
struct PriorOptions : public OptionSet
{
	std::string source = "constant_velocity";  ///< constant_velocity | external
	double max_translation = 5.0;  ///< an external motion longer than this is rejected [m]
	double max_rotation_deg = 30.0;  ///< ... or turning more than this [deg]
	/// An external motion this far both from the constant-velocity prediction and from the previous
	/// frame's external motion is rejected [m] (a vehicle's speed changes by < 0.1 m per 0.1 s frame;
	/// a lost visual odometry jumps by more).
	double max_deviation = 0.5;
	double max_deviation_deg = 3.0;  ///< ... or turning this much differently [deg]
	/// Where an accepted external motion enters: "odometry" = it initialises scan-to-scan odometry,
	/// whose result initialises scan-to-map (A-LOAM's chain, the constant-velocity guess replaced);
	/// "mapping" = it initialises scan-to-map directly and scan-to-scan is skipped for that frame;
	/// "auto" = per frame: scan-to-scan runs from it, and where its result is degenerate (below) the
	/// external motion initialises scan-to-map instead.
	std::string external_stage = "auto";
	/// auto: scan-to-scan is degenerate when the smallest eigenvalue of its translation information
	/// (J^T J with the rotation marginalised; doc/LOAM.md) is below this, i.e. fewer than this many
	/// unit-weight plane matches' worth of constraint along its weakest direction ...
	double min_translation_information = 150;
	/// ... or below this fraction of the next smallest: one direction distinctly weaker than the
	/// others, as along a corridor.
	double min_weakest_ratio = 0.5;
	/// An accepted external motion this far from the constant-velocity prediction (or turning by
	/// check_deviation_deg) is checked against the map: where the constant-velocity guess fits the map
	/// better by check_margin (a fraction of the external one's fit), LOAM starts from it instead, so
	/// that the visual guess never leaves LOAM worse off than its own prediction (0: no check) [m] ...
	double check_deviation = 0.05;
	double check_deviation_deg = 0.3;  ///< ... [deg]
	double check_margin = 0.05;  ///< ... by this fraction
	/// An accepted external motion is also a residual of scan-to-map's solve (doc/LOAM.md "The external
	/// motion as a prior"), with this standard deviation of its translation per frame along each axis
	/// when the source tracked full_quality_tracked features (0: off, it only starts the registration;
	/// ini/vlp16.ini and ini/sim-hdl64.ini: 0.02) [m] ...
	double motion_sigma = 0;
	double motion_sigma_deg = 0.005;  ///< ... of its roll and pitch [deg]
	/// ... and of its yaw, about the LiDAR's vertical axis [deg]: looser, as the VO's yaw scatters by
	/// about this much a frame, and a LiDAR's heading does not drift with its lasers' elevation errors
	/// the way its roll and pitch do (ground matches tilted alike).
	double motion_sigma_yaw_deg = 0.05;
	/// ... fewer tracked features scale its variances up by full_quality_tracked / tracked, and the
	/// source's relative error of the motion's length (a scale corrector's) adds along it. A line or
	/// plane match counts with the standard deviation [loam.mapping] loss_scale.
	double full_quality_tracked = 100;
	/// Where the prior raises the matches' cost by more than this many squared loss scales (it pulls
	/// against directions the map constrains), scan-to-map is solved again without it.
	double max_geometry_cost = 100;

   protected:
	void declare(OptionTable& t) override;
};

/// All of the above, read from / written to their default sections.
struct LoamOptions : public OptionGroup
{
	ScanOptions scan;
	FeatureOptions features;
	OdometryOptions odometry;
	MappingOptions mapping;
	PriorOptions prior;

	/// [loam.scan], [loam.features], [loam.odometry], [loam.mapping], [loam.prior]
	std::vector<std::pair<std::string, OptionSet*>> parts() override;
};
}  // namespace vlo::loam
