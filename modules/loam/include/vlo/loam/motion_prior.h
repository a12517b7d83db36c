#pragma once
// Where each frame's initial guess comes from. A-LOAM assumes constant velocity; the paper's
// "visual bootstrapping" feeds the visual odometry's motion instead, falling back to constant
// velocity when the visual odometry has nothing (lost) or something implausible.
#include <vlo/loam/options.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

namespace vlo::loam
{
class MotionPrior
{
   public:
	virtual ~MotionPrior() = default;
	/// Guess of the motion from the previous frame to the frame at time t (pose of the current
	/// LiDAR frame in the previous one). `external` is the caller's per-frame motion, if any.
	virtual Eigen::Isometry3d predict(double t, const std::optional<Eigen::Isometry3d>& external) = 0;
	/// Which source the last predict() used: "constant_velocity", "external", or "none".
	virtual std::string lastSource() const = 0;
	/// The motion finally estimated for the frame at time t.
	virtual void update(double t, const Eigen::Isometry3d& T_prev_curr) = 0;
	virtual void reset() = 0;
	/// When the last predict() took an external motion: the constant-velocity prediction it set aside.
	virtual std::optional<Eigen::Isometry3d> setAside() const { return std::nullopt; }
};

/// Repeats the last estimated motion, scaled to the time since the previous frame.
class ConstantVelocityPrior : public MotionPrior
{
   public:
	Eigen::Isometry3d predict(double t, const std::optional<Eigen::Isometry3d>& external) override;
	std::string lastSource() const override { return source_; }
	void update(double t, const Eigen::Isometry3d& T_prev_curr) override;
	void reset() override;
	/// A motion between two frames is known (not only a first frame).
	bool hasVelocity() const { return last_dt_ > 0; }

   private:
	Eigen::Isometry3d last_ = Eigen::Isometry3d::Identity();
	double last_dt_ = 0;  ///< duration of last_; 0 before two frames were seen
	std::optional<double> t_prev_;
	std::string source_ = "none";
};

/// Uses the externally supplied motion when present, plausible, and close either to the
/// constant-velocity prediction (when there is one) or to the external motion of the frame before;
/// else constant velocity.
class ExternalPrior : public MotionPrior
{
   public:
	explicit ExternalPrior(const PriorOptions& o) : opt_(o) {}
	Eigen::Isometry3d predict(double t, const std::optional<Eigen::Isometry3d>& external) override;
	std::string lastSource() const override { return source_; }
	void update(double t, const Eigen::Isometry3d& T_prev_curr) override { fallback_.update(t, T_prev_curr); }
	void reset() override { fallback_.reset(), last_external_.reset(), set_aside_.reset(); }
	std::optional<Eigen::Isometry3d> setAside() const override { return set_aside_; }

	/// Finite, a proper rotation, and within the configured translation/rotation bounds.
	bool plausible(const Eigen::Isometry3d& T) const;
	/// Within max_deviation / max_deviation_deg of the constant-velocity prediction `cv`.
	bool agrees(const Eigen::Isometry3d& external, const Eigen::Isometry3d& cv) const;

   private:
	PriorOptions opt_;
	ConstantVelocityPrior fallback_;
	std::string source_ = "none";
	std::optional<Eigen::Isometry3d> last_external_;  ///< the previous frame's external motion, if any
	std::optional<Eigen::Isometry3d> set_aside_;  ///< the constant-velocity prediction, when external won
};

/// The prior named by o.source.
std::unique_ptr<MotionPrior> makeMotionPrior(const PriorOptions& o);
}  // namespace vlo::loam
