#include <vlo/loam/pose_solver.h>

#include <vlo/core/robust_pose_solver.h>

#include <cmath>
#include <vector>

namespace vlo::loam
{
namespace
{
RobustWeight robustWeight(const SolverOptions& o)
{
	return RobustWeight(o.loss == "huber" ? RobustWeight::Huber : o.loss == "cauchy" ? RobustWeight::Cauchy
																					 : RobustWeight::None,
		o.loss_scale);
}

Eigen::Vector3d edgeResidual(const EdgeMatch& e, const Eigen::Isometry3d& T)
{
	const Eigen::Vector3d d = T * e.p - e.a;
	return d - e.u * e.u.dot(d);
}

double planeResidual(const PlaneMatch& p, const Eigen::Isometry3d& T) { return p.n.dot(T * p.p) + p.d; }

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d m;
	m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return m;
}

/// The squared distance of every match at T, the edges' first.
void squaredDistances(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes, const Eigen::Isometry3d& T,
	std::vector<double>& s)
{
	s.clear();
	for (const EdgeMatch& e : edges) s.push_back(edgeResidual(e, T).squaredNorm());
	for (const PlaneMatch& p : planes) s.push_back(std::pow(planeResidual(p, T), 2));
}

/// Weighted normal equations of the matches at T over the tangent [rotation (left), translation]:
/// `w`: the weights of the edges, then of the planes.
PoseNormalEquations normalEquations(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes,
	const std::vector<double>& w, const Eigen::Isometry3d& T)
{
	PoseNormalEquations ne;
	const Eigen::Matrix3d& R = T.linear();
	Eigen::Matrix<double, 3, 6> J;
	for (std::size_t i = 0; i < edges.size(); ++i)
	{
		const EdgeMatch& e = edges[i];
		const Eigen::Vector3d Rp = R * e.p;
		const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - e.u * e.u.transpose();
		const Eigen::Vector3d r = P * (Rp + T.translation() - e.a);
		J.leftCols<3>() = -P * skew(Rp);
		J.rightCols<3>() = P;
		ne.H.noalias() += w[i] * J.transpose() * J;
		ne.g.noalias() += w[i] * J.transpose() * r;
		ne.cost += 0.5 * w[i] * r.squaredNorm();
	}
	Eigen::Matrix<double, 6, 1> j;
	const double* wp = w.data() + edges.size();
	for (std::size_t i = 0; i < planes.size(); ++i)
	{
		const PlaneMatch& p = planes[i];
		const Eigen::Vector3d Rp = R * p.p;
		const double r = p.n.dot(Rp + T.translation()) + p.d;
		j.head<3>() = Rp.cross(p.n);
		j.tail<3>() = p.n;
		ne.H.noalias() += (wp[i] * j) * j.transpose();
		ne.g.noalias() += (wp[i] * r) * j;
		ne.cost += 0.5 * wp[i] * r * r;
	}
	return ne;
}

/// The matches as solveRobustPose's problem.
struct MatchProblem
{
	const Matches& m;
	void squaredResiduals(const Eigen::Isometry3d& T, std::vector<double>& s) const { squaredDistances(m.edges, m.planes, T, s); }
	PoseNormalEquations normalEquations(const std::vector<double>& w, const Eigen::Isometry3d& T) const
	{
		return loam::normalEquations(m.edges, m.planes, w, T);
	}
};

/// The matches and a pose prior: the prior's r^T I r is the last squared residual.
struct MatchAndPriorProblem
{
	const Matches& m;
	const PosePrior& prior;
	void squaredResiduals(const Eigen::Isometry3d& T, std::vector<double>& s) const
	{
		squaredDistances(m.edges, m.planes, T, s);
		s.push_back(prior.squaredMahalanobis(T));
	}
	PoseNormalEquations normalEquations(const std::vector<double>& w, const Eigen::Isometry3d& T) const
	{
		PoseNormalEquations ne = loam::normalEquations(m.edges, m.planes, w, T);
		const Vector6d r = prior.residual(T);
		ne.H += prior.information;
		ne.g += prior.information * r;
		ne.cost += 0.5 * r.dot(prior.information * r);
		return ne;
	}
};

/// The matches' robust weights; the prior's residual is weighed by its information alone: a
/// robust loss on it would drop it exactly where the geometry pulls elsewhere.
struct MatchAndPriorWeight
{
	RobustWeight matches;
};

void weigh(const std::vector<double>& s, const MatchAndPriorWeight& weight, std::vector<double>& w)
{
	vlo::weigh(s, weight.matches, w);
	w.back() = 1.0;
}
}  // namespace

bool roundConverged(const Eigen::Isometry3d& before, const Eigen::Isometry3d& after, const SolverOptions& o)
{
	const Eigen::Isometry3d d = before.inverse() * after;
	return d.translation().norm() < o.converged_translation &&
		Eigen::AngleAxisd(d.rotation()).angle() * 180.0 / M_PI < o.converged_rotation_deg;
}

void evaluateMatches(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes, const SolverOptions& o,
	const Eigen::Isometry3d& T, Eigen::Matrix<double, 6, 6>& JtJ, double& rms)
{
	// Weighted as in the solve, so outliers count as little there as here.
	std::vector<double> s, w;
	squaredDistances(edges, planes, T, s);
	weigh(s, robustWeight(o), w);
	JtJ = normalEquations(edges, planes, w, T).H;
	double sum2 = 0;
	for (double si : s) sum2 += si;
	const std::size_t n = edges.size() + planes.size();
	rms = n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0;
}

SolveReport solvePose(const Matches& m, const SolverOptions& o, Eigen::Isometry3d& T, const PosePrior* prior)
{
	SolveReport rep;
	if (m.size() == 0) return rep;
	if (prior)
		rep.iterations = solveRobustPose(MatchAndPriorProblem{m, *prior}, MatchAndPriorWeight{robustWeight(o)}, o.max_solver_iterations, T);
	else
		rep.iterations = solveRobustPose(MatchProblem{m}, robustWeight(o), o.max_solver_iterations, T);
	evaluateMatches(m.edges, m.planes, o, T, rep.JtJ, rep.rms);
	return rep;
}
}  // namespace vlo::loam
