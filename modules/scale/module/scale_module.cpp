// The paper's scale corrector (modules/scale) as the scale-correction module "lidar_depth": per
// frame, the estimate from C(i-1), L(i-1), C(i) and the VO's camera motion, the policy's decision
// (returned to the caller, which applies it), the scale_* columns of frames.csv, and its snapshots.
#include <vlo/core/bounded_sample.h>
#include <vlo/core/sweep_times.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/scale/overlay.h>
#include <vlo/scale/policy.h>
#include <vlo/scale/scale_corrector.h>
#include <vlo/scale/scale_plot.h>
#include <vlo/viz/projected_scan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace vlo::scale
{
namespace
{
struct ScaleSnapshot
{
	Frame prev;  ///< C(i-1) and L(i-1), deep copies
	std::size_t cur_index = 0;
	scale::ScaleEstimate estimate;
};

/// Relative standard error of the estimate's scale, spread / s / sqrt(inliers), for a motion source
/// to weigh the motion by (NaN without a finite estimate of two inliers or more).
double relativeError(const scale::ScaleEstimate& e)
{
	if (!std::isfinite(e.scale) || !std::isfinite(e.spread) || e.scale <= 0 || e.spread <= 0 || e.counts.inliers < 2)
		return std::nan("");
	return e.spread / e.scale / std::sqrt(double(e.counts.inliers));
}

class LidarDepthScaleModule : public kernel::ScaleCorrectionModule
{
   public:
	void configure(kernel::RunConfig& config, int snapshot_every) override
	{
		snapshot_every_ = snapshot_every;
		config.load(opt_, "scale");
		corrector_ = std::make_unique<scale::ScaleCorrector>(opt_);
		policy_ = std::make_unique<scale::ScaleCorrectionPolicy>(opt_);
	}

	kernel::ScaleCorrection process(const Frame* prev, const Frame& cur, const kernel::VisualOdometryStep& vo, kernel::FrameTable& table) override
	{
		if (vo.new_map)  // a fresh map has an arbitrary scale again
		{
			policy_->reset();
			cumulative_ = -1;
		}
		kernel::ScaleCorrection correction;
		if (!vo.camera_motion || !prev || !prev->has_scan || !prev->has_image)
		{
			correction.why = vo.camera_motion ? "no previous scan" : "no VO motion";
			table.set("scale_decision", correction.why);
			return correction;
		}
		// The estimator wants T_{C(i-1)}^{C(i)}; the VO gives the current camera in the previous one.
		// Once the map is metric its units are metres; before, the estimate itself says how long one is.
		const bool metric = cumulative_ >= 0;
		scale::ScaleEstimate e = estimateAt(*prev, cur, *vo.camera_motion, metric ? 1.0 : std::nan(""));
		if (!metric && e.valid && hasTimeSpread(prev->scan)) e = estimateAt(*prev, cur, *vo.camera_motion, e.scale);
		++estimates_;
		valid_ += e.valid ? 1 : 0;
		const scale::ScaleDecision d = policy_->decide(e);
		correction.why = scale::toString(d.kind);
		correction.relative_error = relativeError(e);
		if (d.apply())
		{
			// With a camera motion the VO tracked this frame in its map: the caller applies the factor.
			const bool initial = d.kind == scale::ScaleDecision::Kind::Initial;
			correction.kind = initial ? kernel::ScaleCorrection::Kind::Initial : kernel::ScaleCorrection::Kind::Drift;
			correction.factor = d.factor;
			corrections_ += initial ? 0 : 1;
			cumulative_ = initial ? 1.0 : cumulative_ * d.factor;
		}
		else
			correction.why += std::string(": ") + d.why;
		writeColumns(e, correction, table);
		// Estimates once the map is metric (the initial one says how long a map unit was: off the plot).
		const bool initial = correction.kind == kernel::ScaleCorrection::Kind::Initial;
		history_.add(cur.index, e.valid && !initial ? e.scale : std::nan(""), e.counts.inliers,
			initial ? 1.0 : correction.factor, cumulative_, !e.valid && e.scale > 0 ? e.scale : std::nan(""));
		if (snapshot_every_ > 0 && cur.index % snapshot_every_ == 0)
		{
			Frame copy = *prev;
			copy.image = prev->image.makeDeepCopy();
			snapshots_.offer({std::move(copy), cur.index, e});
		}
		return correction;
	}

	void writeSnapshots(const std::string& dir) const override
	{
		renderScalePlot(history_, dir + "/scale.png");
		for (const auto& snap : snapshots_.items())
		{
			const auto& e = snap.estimate;
			viz::ProjectedScanStyle ps;
			char head[96], estimate[96];
			std::snprintf(head, sizeof(head), "frames %zu->%zu (t = %.3f s): ", snap.prev.index, snap.cur_index,
				snap.prev.t);
			if (e.scale > 0)  // 0: the estimator stopped before it computed a scale
				std::snprintf(estimate, sizeof(estimate), "scale %.3f, %d of %d triangulated points inliers", e.scale,
					e.counts.inliers, e.counts.triangulated);
			else
				std::snprintf(estimate, sizeof(estimate), "no estimate");
			ps.title = std::string(head) + estimate + " (" + scale::toString(e.reason) + ")";
			char name[64];
			std::snprintf(name, sizeof(name), "/scale_%06zu.png", snap.cur_index);
			renderProjectedScan(snap.prev.image, snap.prev.scan, snap.prev.rig, dir + name, scale::scaleOverlay(e), ps);
		}
	}

	std::vector<std::pair<std::string, double>> figures() const override
	{
		return {{"scale_estimates", double(estimates_)}, {"scale_valid", double(valid_)},
			{"scale_corrections", double(corrections_)}};
	}

   private:
	/// The estimate with L(i-1) as C(i-1) saw it: a raw sweep's returns moved to the image's time
	/// along the VO's motion, `metres_per_unit` of it (NaN: unknown, the sweep as it is). At 12 m/s
	/// the returns ahead were taken 0.13 m behind the image's viewpoint (KITTI: the scan's stamp is
	/// 10.5 ms before the camera's), which makes their depths, and the scale, 1-2 % long.
	scale::ScaleEstimate estimateAt(const Frame& prev, const Frame& cur, const Eigen::Isometry3d& camera_motion, double metres_per_unit)
	{
		if (std::isnan(metres_per_unit) || !hasTimeSpread(prev.scan))
			return corrector_->estimate(prev, cur, camera_motion.inverse(), &pyramid_);
		Eigen::Isometry3d m = camera_motion;
		m.translation() *= metres_per_unit;
		const Eigen::Isometry3d T_cl = prev.rig.camera_T_lidar();
		PointCloud at_image = prev.scan;
		moveToFrameTime(at_image, T_cl.inverse() * m * T_cl, cur.t - prev.t);
		return corrector_->estimate(prev, cur, camera_motion.inverse(), &pyramid_, &at_image);
	}

	void writeColumns(const scale::ScaleEstimate& e, const kernel::ScaleCorrection& correction, kernel::FrameTable& table) const
	{
		table.set("scale_reason", std::string(scale::toString(e.reason)));
		table.set("scale_s", e.scale, 4);
		table.set("scale_spread", e.spread, 4);
		table.set("scale_projected", static_cast<long long>(e.counts.projected));
		table.set("scale_selected", static_cast<long long>(e.counts.selected));
		table.set("scale_tracked", static_cast<long long>(e.counts.tracked));
		table.set("scale_culled_kept", static_cast<long long>(e.counts.gradient_kept));
		table.set("scale_triangulated", static_cast<long long>(e.counts.triangulated));
		table.set("scale_inliers", static_cast<long long>(e.counts.inliers));
		table.set("scale_decision", correction.why);
		table.set("scale_applied", correction.factor, 4);
		table.set("scale_cumulative", policy_->cumulative(), 4);
		table.set("ms_scale", e.ms.total(), 2);
	}

	scale::ScaleOptions opt_;
	std::unique_ptr<scale::ScaleCorrector> corrector_;
	scale::PyramidReuse pyramid_;  ///< C(i)'s LK pyramid, C(i-1)'s at the next frame
	std::unique_ptr<scale::ScaleCorrectionPolicy> policy_;
	int snapshot_every_ = 0;
	BoundedSample<ScaleSnapshot> snapshots_{24};  ///< spread over the drive, bounded however long it is
	scale::ScaleHistory history_;
	double cumulative_ = -1;  ///< product of the corrections of the current metric map (< 0: not metric yet)
	int estimates_ = 0, valid_ = 0, corrections_ = 0;
};
VLO_REGISTER_MODULE(kernel::ScaleCorrectionModule, "lidar_depth", LidarDepthScaleModule);
}  // namespace
}  // namespace vlo::scale
