// [loam.odometry] and [loam.mapping] with their shared solver keys.
#include "option_checks.h"
#include "vlo/loam/options.h"

#include <cmath>
#include <sstream>

namespace vlo::loam
{
using detail::checkNumber;
using detail::require;

// Nested solver settings share their keys between the odometry and mapping sections.
static void loadSolver(const mrpt::config::CConfigFileBase& c, const std::string& s, SolverOptions& o)
{
	checkNumber(c, s, "outer_iterations", true);
	checkNumber(c, s, "max_solver_iterations", true);
	checkNumber(c, s, "loss_scale", false);
	checkNumber(c, s, "matches_per_block", true);
	checkNumber(c, s, "converged_translation", false);
	checkNumber(c, s, "converged_rotation_deg", false);
	o.outer_iterations = c.read_int(s, "outer_iterations", o.outer_iterations);
	o.max_solver_iterations = c.read_int(s, "max_solver_iterations", o.max_solver_iterations);
	o.loss = c.read_string_first_word(s, "loss", o.loss);
	o.loss_scale = c.read_double(s, "loss_scale", o.loss_scale);
	o.matches_per_block = c.read_int(s, "matches_per_block", o.matches_per_block);
	o.converged_translation = c.read_double(s, "converged_translation", o.converged_translation);
	o.converged_rotation_deg = c.read_double(s, "converged_rotation_deg", o.converged_rotation_deg);
}
static void saveSolver(mrpt::config::CConfigFileBase& c, const std::string& s, const SolverOptions& o)
{
	const int np = mrpt::config::MRPT_SAVE_NAME_PADDING(), vp = mrpt::config::MRPT_SAVE_VALUE_PADDING();
	c.write(s, "outer_iterations", o.outer_iterations, np, vp, "correspondence search + solve rounds");
	c.write(s, "max_solver_iterations", o.max_solver_iterations, np, vp, "Ceres iterations per round");
	c.write(s, "loss", o.loss, np, vp, "robust loss: huber | cauchy | none");
	c.write(s, "loss_scale", o.loss_scale, np, vp, "residual [m] where the robust loss bends");
	c.write(s, "matches_per_block", o.matches_per_block, np, vp,
		"matches per Ceres residual block (1: Ceres applies the loss; >1: same cost, less overhead)");
	c.write(s, "converged_translation", o.converged_translation, np, vp, "a round moving less ends the rounds [m]");
	c.write(s, "converged_rotation_deg", o.converged_rotation_deg, np, vp, "... and turning less [deg]");
}
static void validateSolver(const std::string& s, const SolverOptions& o)
{
	require(o.outer_iterations >= 1, s, "outer_iterations", "must be >= 1");
	require(o.max_solver_iterations >= 1, s, "max_solver_iterations", "must be >= 1");
	require(o.loss == "huber" || o.loss == "cauchy" || o.loss == "none", s, "loss",
		"'" + o.loss + "' is not one of huber, cauchy, none");
	require(o.loss_scale > 0, s, "loss_scale", "must be > 0");
	require(o.converged_translation >= 0, s, "converged_translation", "must be >= 0");
	require(o.converged_rotation_deg >= 0, s, "converged_rotation_deg", "must be >= 0");
	require(o.matches_per_block >= 1 && o.matches_per_block <= 4096, s, "matches_per_block", "must be in [1, 4096]");
}

void OdometryOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_BOOL(enabled);
	loadSolver(c, s, solver);
	VLO_NUM(max_match_distance, double);
	VLO_NUM(nearby_rings, int);
	VLO_BOOL(use_kdtree);
	VLO_NUM(min_correspondences, int);
	VLO_NUM(max_rounds, int);
}

void OdometryOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "scan-to-scan registration (else the prior feeds the mapping)");
	saveSolver(c, s, solver);
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_match_distance, "nearest-neighbour gate [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(nearby_rings, "rings searched on each side for line/plane points");
	MRPT_SAVE_CONFIG_VAR_COMMENT(use_kdtree, "first neighbour from a kd-tree (A-LOAM) instead of the rings near the query");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_correspondences, "fewer: keep the initial guess");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_rounds, "rounds continue past outer_iterations while the pose still moves, up to this many");
}

void OdometryOptions::validate() const
{
	const std::string s = "loam.odometry";
	validateSolver(s, solver);
	require(max_match_distance > 0, s, "max_match_distance", "must be > 0");
	require(nearby_rings >= 1, s, "nearby_rings", "must be >= 1");
	require(min_correspondences >= 6, s, "min_correspondences", "must be >= 6");
	require(max_rounds >= solver.outer_iterations, s, "max_rounds", "must be >= outer_iterations");
}

void MappingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_BOOL(enabled);
	loadSolver(c, s, solver);
	VLO_NUM(edge_leaf, double);
	VLO_NUM(plane_leaf, double);
	VLO_NUM(map_edge_resolution, double);
	VLO_NUM(map_plane_resolution, double);
	VLO_NUM(voxel_size, double);
	VLO_NUM(max_points_per_voxel, int);
	VLO_NUM(map_radius, double);
	VLO_NUM(knn, int);
	VLO_NUM(max_nn_distance, double);
	VLO_NUM(edge_eigen_ratio, double);
	VLO_NUM(plane_max_distance, double);
	VLO_NUM(plane_line_ratio, double);
	VLO_NUM(min_edge_correspondences, int);
	VLO_NUM(min_plane_correspondences, int);
	VLO_NUM(degeneracy_threshold, double);
}

void MappingOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "scan-to-map refinement every frame");
	saveSolver(c, s, solver);
	MRPT_SAVE_CONFIG_VAR_COMMENT(edge_leaf, "downsampling of the scan's edge points [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(plane_leaf, "downsampling of the scan's plane points [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_edge_resolution, "edge map: one point per cell [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_plane_resolution, "plane map: one point per cell [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(voxel_size, "hash voxel edge, >= 2*max_nn_distance [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_points_per_voxel, "cap on map points per voxel");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_radius, "voxels farther from the vehicle are dropped [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(knn, "neighbours for the line/plane fits");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_nn_distance, "all neighbours must be this close [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(edge_eigen_ratio, "line if largest eigenvalue > ratio * middle");
	MRPT_SAVE_CONFIG_VAR_COMMENT(plane_max_distance, "plane if all neighbours are this close to it [m]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(plane_line_ratio, "no plane if largest eigenvalue > ratio * middle (one ring)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_edge_correspondences, "fewer edge matches: keep the odometry pose (0: edges optional)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_plane_correspondences, "fewer plane matches: keep the odometry pose");
	MRPT_SAVE_CONFIG_VAR_COMMENT(degeneracy_threshold, "min eigenvalue of J^T J below: degenerate");
}

void MappingOptions::validate() const
{
	const std::string s = "loam.mapping";
	validateSolver(s, solver);
	require(edge_leaf > 0, s, "edge_leaf", "must be > 0");
	require(plane_leaf > 0, s, "plane_leaf", "must be > 0");
	require(map_edge_resolution > 0, s, "map_edge_resolution", "must be > 0");
	require(map_plane_resolution > 0, s, "map_plane_resolution", "must be > 0");
	require(max_nn_distance > 0, s, "max_nn_distance", "must be > 0");
	require(voxel_size >= 2 * max_nn_distance, s, "voxel_size", "must be >= 2 * max_nn_distance");
	require(voxel_size / map_edge_resolution <= 64 && voxel_size / map_plane_resolution <= 64, s, "voxel_size",
		"must be at most 64 map resolution cells");
	require(max_points_per_voxel >= knn, s, "max_points_per_voxel", "must be >= knn");
	require(map_radius > voxel_size, s, "map_radius", "must exceed voxel_size");
	require(knn >= 3 && knn <= 32, s, "knn", "must be in [3, 32]");
	require(edge_eigen_ratio >= 1, s, "edge_eigen_ratio", "must be >= 1");
	require(plane_max_distance > 0, s, "plane_max_distance", "must be > 0");
	require(plane_line_ratio >= 1, s, "plane_line_ratio", "must be >= 1");
	require(min_edge_correspondences >= 0, s, "min_edge_correspondences", "must be >= 0");
	require(min_plane_correspondences >= 0, s, "min_plane_correspondences", "must be >= 0");
	require(degeneracy_threshold >= 0, s, "degeneracy_threshold", "must be >= 0");
}

}  // namespace vlo::loam
