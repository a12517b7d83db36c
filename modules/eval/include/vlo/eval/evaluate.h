#pragma once
// One evaluation of an estimated trajectory against ground truth: association by time, then ATE/ARE
// and the KITTI metric as requested. What the app prints and writes comes from the EvalReport.
#include <vlo/eval/association.h>
#include <vlo/eval/ate.h>
#include <vlo/eval/kitti_metric.h>
#include <vlo/eval/revisit.h>
#include <vlo/eval/rpe.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace vlo::eval
{
struct EvalOptions
{
	bool ate = true, kitti = true, rpe = true, revisit = true;  ///< which metrics to compute
	Alignment align = Alignment::SE3;  ///< for ATE/ARE only; the KITTI metric is relative and unaligned
	AssociationOptions association;
	/// Ground-truth orientations are meaningless (RTK positions only): ARE and KITTI are skipped.
	bool gt_translation_only = false;
	/// When set, both trajectories (vehicle frame) are moved to camera 0 for the KITTI metric.
	std::optional<Eigen::Isometry3d> cam0_T_vehicle;
	KittiOptions kitti_options;
	RevisitOptions revisit_options;
	std::string gt_name = "ground truth", est_name = "estimate";  ///< for messages (file paths)
};

/// "all" | "ate" | "kitti" | "rpe" | "revisit" -> sets opts.ate / .kitti / .rpe / .revisit; throws InputError otherwise.
void parseMetric(const std::string& s, EvalOptions& opts);

struct EvalReport
{
	EvalOptions options;
	Association association;
	double gt_length_m = 0, est_length_m = 0;  ///< path lengths over the matched poses
	std::optional<AteResult> ate;
	std::string ate_note, are_note;  ///< why ATE / ARE are missing, if they are
	std::optional<KittiResult> kitti;  ///< set when computed, even with no segments
	std::string kitti_note;  ///< why the KITTI numbers are missing, if they are
	std::string kitti_frame;  ///< "camera 0" or "as given"
	std::optional<RpeResult> rpe;
	std::string rpe_note;  ///< why the RPE is missing, if it is
	std::optional<RevisitResult> revisit;  ///< set when computed, even without a revisit
	std::string revisit_note;  ///< why the revisit error is missing (or "no revisit: ..."), if it is
	/// Signs that the ground truth is of another drive (little time overlap, a rotation error of tens of
	/// degrees, a path of another length): one line each, for the user.
	std::vector<std::string> warnings;
};

/// Throws InputError (naming the files in opts) when fewer than 3 poses overlap in time.
EvalReport evaluate(const Trajectory& gt, const Trajectory& est, const EvalOptions& opts);

/// The matched estimate after the ATE alignment (as matched when there is no ATE): a Sim(3) is not an
/// isometry, so positions take the scale and orientations only the rotation.
Trajectory alignedEstimate(const EvalReport& r);

/// The warnings of a report (evaluate() fills EvalReport::warnings with them).
std::vector<std::string> plausibilityWarnings(const EvalReport& r);
}  // namespace vlo::eval
