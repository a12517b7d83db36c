// [loam.scan], [loam.features], [loam.odometry], [loam.mapping] (with their shared solver keys),
// [loam.prior]: every key with its type, range and help.
#include <vlo/loam/options.h>

namespace vlo::loam
{
namespace
{
// The solver keys are the same in the odometry and mapping sections.
void declareSolver(OptionTable& t, SolverOptions& o)
{
	t.add("outer_iterations", o.outer_iterations, ">= 1", "correspondence search + solve rounds");
	t.add("max_solver_iterations", o.max_solver_iterations, ">= 1", "reweighted Levenberg-Marquardt iterations per round");
	t.add("loss", o.loss, "huber | cauchy | none", "robust loss: huber | cauchy | none");
	t.add("loss_scale", o.loss_scale, "> 0", "residual [m] where the robust loss bends");
	t.add("converged_translation", o.converged_translation, ">= 0", "a round moving less ends the rounds [m]");
	t.add("converged_rotation_deg", o.converged_rotation_deg, ">= 0", "... and turning less [deg]");
}
}  // namespace

void ScanOptions::declare(OptionTable& t)
{
	t.add("ring_model", ring_model, "uniform | hdl64 | table", "uniform | hdl64 (two-block HDL-64E) | table");
	t.add("n_rings", n_rings, "any", "beams of the uniform model, in [2, 256]");
	t.add("vfov_min_deg", vfov_min_deg, "any", "lowest beam elevation (uniform) [deg]");
	t.add("vfov_max_deg", vfov_max_deg, "any", "highest beam elevation (uniform) [deg]");
	t.add("elevation_table_deg", elevation_table_deg, "(-90, 90)", "beam elevations (table model) [deg]");
	t.add("fov_margin_deg", fov_margin_deg, ">= 0", "accepted beyond the extreme beams [deg]");
	t.add("min_range", min_range, ">= 0", "closer returns are dropped [m]");
	t.add("max_range", max_range, "any", "farther returns are dropped [m]");
	t.add("max_deskew_passes", max_deskew_passes, "[1, 10]", "scans with point times ([lidar]): deskew + register again while the motion found changes");
	t.add("deskew_tolerance", deskew_tolerance, ">= 0", "... by more than this [m]");
	t.add("deskew_tolerance_deg", deskew_tolerance_deg, ">= 0", "... or this [deg]");
}

void ScanOptions::checkRelations() const
{
	if (ring_model == "uniform")
	{
		require(n_rings >= 2 && n_rings <= 256, "n_rings", "must be in [2, 256]");
		require(vfov_max_deg > vfov_min_deg, "vfov_max_deg", "must exceed vfov_min_deg");
		require(vfov_min_deg > -90 && vfov_max_deg < 90, "vfov_min_deg", "elevations must be within (-90, 90)");
	}
	if (ring_model == "table") require(elevation_table_deg.size() >= 2, "elevation_table_deg", "needs at least 2 beams");
	require(max_range > min_range, "max_range", "must exceed min_range");
}

void FeatureOptions::declare(OptionTable& t)
{
	t.add("curvature_half_window", curvature_half_window, "[1, 50]", "neighbours per side for the curvature");
	t.add("n_sectors", n_sectors, ">= 1", "sectors per ring");
	t.add("max_sharp", max_sharp, ">= 0", "sharp (edge) points per sector");
	t.add("max_less_sharp", max_less_sharp, ">= 0", "less-sharp points per sector (sharp included)");
	t.add("max_flat", max_flat, ">= 0", "flat (plane) points per sector");
	t.add("sharp_threshold", sharp_threshold, ">= 0", "curvature above: edge candidate [m^2]");
	t.add("flat_threshold", flat_threshold, ">= 0", "curvature below: plane candidate [m^2]");
	t.add("suppress_gap_sq", suppress_gap_sq, ">= 0", "neighbour suppression stops at this gap [m^2]");
	t.add("sharp_local_max", sharp_local_max, "true | false", "edges only at curvature peaks (sparse rings smear edges otherwise)");
	t.add("less_flat_leaf", less_flat_leaf, "> 0", "voxel size of the less-flat downsampling [m]");
	t.add("less_flat_threshold", less_flat_threshold, "> 0", "less-flat (plane) points: curvature below [m^2] (A-LOAM: no limit)");
	t.add("reject_occluded", reject_occluded, "true | false", "drop points next to occlusion boundaries");
	t.add("occlusion_gap_sq", occlusion_gap_sq, ">= 0", "gap between neighbours that may be an occlusion [m^2]");
	t.add("occlusion_angle", occlusion_angle, ">= 0", "... when their beams are closer than this [rad]");
	t.add("reject_parallel", reject_parallel, "true | false", "drop points on surfaces nearly parallel to the beam");
	t.add("parallel_ratio", parallel_ratio, ">= 0", "both gaps^2 > ratio * range^2: parallel");
	t.add("max_azimuth_gap", max_azimuth_gap, ">= 0", "curvature window across missing returns wider than this many of the ring's median azimuth steps: point unreliable (0: off)");
	t.add("min_rings", min_rings, ">= 1", "fewer populated rings: frame skipped");
	t.add("min_sharp", min_sharp, ">= 0", "fewer sharp points: frame skipped");
	t.add("min_flat", min_flat, ">= 0", "fewer flat points: frame skipped");
}

void FeatureOptions::checkRelations() const
{
	require(max_less_sharp >= max_sharp, "max_less_sharp", "must be >= max_sharp");
}

void OdometryOptions::declare(OptionTable& t)
{
	t.add("enabled", enabled, "true | false", "scan-to-scan registration (else the prior feeds the mapping)");
	declareSolver(t, solver);
	t.add("max_match_distance", max_match_distance, "> 0", "nearest-neighbour gate [m]");
	t.add("nearby_rings", nearby_rings, ">= 1", "rings searched on each side for line/plane points");
	t.add("use_kdtree", use_kdtree, "true | false", "first neighbour from a kd-tree (A-LOAM) instead of the rings near the query");
	t.add("min_correspondences", min_correspondences, ">= 6", "fewer: keep the initial guess");
	t.add("plane_max_distance", plane_max_distance, ">= 0", "plane match: a fourth reference point (next to the third) must lie this close to it [m] (0: no check)");
	t.add("max_rounds", max_rounds, ">= 1", "rounds continue past outer_iterations while the pose still moves, up to this many");
	t.add("cold_start_range", cold_start_range, ">= 0", "first motion of a drive: searched from translations up to this far along x and y (0: from zero only) [m]");
	t.add("cold_start_step", cold_start_step, "> 0", "... this far apart [m]");
}

void OdometryOptions::checkRelations() const
{
	require(max_rounds >= solver.outer_iterations, "max_rounds", "must be >= outer_iterations");
}

void MappingOptions::declare(OptionTable& t)
{
	t.add("enabled", enabled, "true | false", "scan-to-map refinement every frame");
	declareSolver(t, solver);
	t.add("edges", edges, "on | off | auto", "edge points matched to lines of the map: on, off (planes only, no edge map), auto (where planes leave the translation weak)");
	t.add("weak_plane_information", weak_plane_information, ">= 0", "planes whose translation information is below this leave it weak: auto seeks edges (at the guess); no rounds past outer_iterations where the matches in use leave it so weak (at the pose reached)");
	t.add("max_rounds", max_rounds, ">= 1", "rounds continue past outer_iterations while the pose still moves and the planes fix the translation, up to this many");
	t.add("edge_leaf", edge_leaf, "> 0", "downsampling of the scan's edge points [m]");
	t.add("plane_leaf", plane_leaf, "> 0", "downsampling of the scan's plane points [m]");
	t.add("map_edge_resolution", map_edge_resolution, "> 0", "edge map: one point per cell [m]");
	t.add("map_plane_resolution", map_plane_resolution, "> 0", "plane map: one point per cell [m]");
	t.add("voxel_size", voxel_size, "> 0", "hash voxel edge, >= 2*max_nn_distance [m]");
	t.add("max_points_per_voxel", max_points_per_voxel, ">= 1", "cap on map points per voxel");
	t.add("map_radius", map_radius, "> 0", "voxels farther from the vehicle are dropped [m]");
	t.add("knn", knn, "[3, 16]", "neighbours for the line/plane fits");
	t.add("max_nn_distance", max_nn_distance, "> 0", "all neighbours must be this close [m]");
	t.add("edge_eigen_ratio", edge_eigen_ratio, ">= 1", "line if largest eigenvalue > ratio * middle");
	t.add("edge_flatness_ratio", edge_flatness_ratio, ">= 0", "no line where its points spread across it within a surface: middle eigenvalue > ratio * max(smallest, 1 cm^2) (0: off, as A-LOAM)");
	t.add("min_line_elevation_deg", min_line_elevation_deg, "[0, 90]", "map lines flatter than this to the LiDAR's horizontal plane depend on the view (where a ring meets them moves with the sensor) [deg]");
	t.add("view_dependent_reach", view_dependent_reach, ">= 0", "lines that depend on the view are matched only against map points seen from within this distance (0: any) [m]");
	t.add("outline_view_change_deg", outline_view_change_deg, "[0, 180]", "lines through outline points only from map points seen from within this angle of the current view [deg] (0: any view, A-LOAM)");
	t.add("edge_range_ratio", edge_range_ratio, ">= 0", "lines are matched only against map points seen from within this factor of the edge point's range (0: any)");
	t.add("plane_max_distance", plane_max_distance, "> 0", "plane if all neighbours are this close to it [m]");
	t.add("rough_plane_max_distance", rough_plane_max_distance, ">= 0", "where planes and lines leave the translation nearly free, planes whose neighbours lie this close count too [m] (<= plane_max_distance: off)");
	t.add("rough_plane_information", rough_plane_information, ">= 0", "... nearly free: its information along the weakest direction at the guess below this");
	t.add("plane_line_ratio", plane_line_ratio, ">= 1", "no plane if largest eigenvalue > ratio * middle (one ring)");
	t.add("min_edge_correspondences", min_edge_correspondences, ">= 0", "fewer edge matches: keep the odometry pose (0: edges optional)");
	t.add("min_plane_correspondences", min_plane_correspondences, ">= 0", "fewer plane matches: keep the odometry pose");
	t.add("degeneracy_threshold", degeneracy_threshold, ">= 0", "min eigenvalue of J^T J below: degenerate");
	t.add("free_space_radius", free_space_radius, ">= 0", "map points this close that a beam passes by and returns from beyond are removed (0: off) [m]");
	t.add("free_space_beam_radius", free_space_beam_radius, "> 0", "... passing within this [m]");
	t.add("free_space_margin", free_space_margin, ">= 0", "... returning from this much farther [m]");
	t.add("free_space_margin_per_metre", free_space_margin_per_metre, ">= 0", "... plus this per metre of range");
	t.add("free_space_azimuth_bins", free_space_azimuth_bins, "[36, 36000]", "azimuth bins of the scan's range image");
	t.add("drop_arrivals", drop_arrivals, "true | false", "the scan's points in the previous scan's free space are not matched");
	t.add("arrival_radius", arrival_radius, ">= 0", "... and scan points this close to them stay out of the map [m]");
}

void MappingOptions::checkRelations() const
{
	require(voxel_size >= 2 * max_nn_distance, "voxel_size", "must be >= 2 * max_nn_distance");
	require(voxel_size / map_edge_resolution <= 64 && voxel_size / map_plane_resolution <= 64, "voxel_size",
		"must be at most 64 map resolution cells");
	require(max_points_per_voxel >= knn, "max_points_per_voxel", "must be >= knn");
	require(edge_range_ratio == 0 || edge_range_ratio >= 1, "edge_range_ratio", "must be 0 (off) or >= 1");
	require(edges == "on" || min_edge_correspondences == 0, "min_edge_correspondences", "must be 0 unless edges is on");
	require(map_radius > voxel_size, "map_radius", "must exceed voxel_size");
	require(max_rounds >= solver.outer_iterations, "max_rounds", "must be >= outer_iterations");
}

void PriorOptions::declare(OptionTable& t)
{
	t.add("source", source, "constant_velocity | external", "constant_velocity (A-LOAM) | external (e.g. visual odometry)");
	t.add("max_translation", max_translation, "> 0", "external motion longer than this is rejected [m]");
	t.add("max_rotation_deg", max_rotation_deg, "> 0", "external motion turning more is rejected [deg]");
	t.add("max_deviation", max_deviation, "> 0", "external motion this far from constant velocity and from its own last motion is rejected [m]");
	t.add("max_deviation_deg", max_deviation_deg, "> 0", "... or turning this differently [deg]");
	t.add("external_stage", external_stage, "odometry | mapping | auto", "odometry: the external motion initialises scan-to-scan | mapping: scan-to-map, scan-to-scan skipped | auto: scan-to-scan unless its result is degenerate");
	t.add("min_translation_information", min_translation_information, ">= 0", "auto: scan-to-scan is degenerate when the smallest eigenvalue of its translation information is below this [plane matches]");
	t.add("min_weakest_ratio", min_weakest_ratio, "[0, 1]", "... or below this fraction of the next smallest (a corridor)");
	t.add("check_deviation", check_deviation, ">= 0", "an external motion this far from constant velocity is checked against the map, constant velocity kept where it fits better (0: no check) [m]");
	t.add("check_deviation_deg", check_deviation_deg, ">= 0", "... or turning this differently [deg]");
	t.add("check_margin", check_margin, ">= 0", "... better by this fraction of the external motion's fit");
	t.add("motion_sigma", motion_sigma, ">= 0", "the external motion is a residual of scan-to-map's solve with this translation standard deviation per frame and axis at full quality (0: off, it only starts the registration) [m]");
	t.add("motion_sigma_deg", motion_sigma_deg, "> 0", "... this roll and pitch standard deviation [deg]");
	t.add("motion_sigma_yaw_deg", motion_sigma_yaw_deg, "> 0", "... and this yaw (about the LiDAR's vertical axis) standard deviation [deg]");
	t.add("full_quality_tracked", full_quality_tracked, ">= 0", "... fewer features tracked by the motion's source scale the variances by this / tracked");
	t.add("max_geometry_cost", max_geometry_cost, ">= 0", "where the prior raises the matches' cost by more than this many squared [loam.mapping] loss_scale, scan-to-map is solved again without it");
}

std::vector<std::pair<std::string, OptionSet*>> LoamOptions::parts()
{
	return {{"loam.scan", &scan}, {"loam.features", &features}, {"loam.odometry", &odometry}, {"loam.mapping", &mapping},
		{"loam.prior", &prior}};
}
}  // namespace vlo::loam
