#include "vlo/loam/pose_solver.h"

#include <cmath>
#include <vector>

namespace vlo::loam
{
namespace
{
/// The robust loss rho of a squared residual s, as its IRLS weight rho'(s): Huber rho(s) = s inside
/// the scale a, 2 a sqrt(s) - a^2 outside; Cauchy rho(s) = a^2 log(1 + s / a^2); none rho(s) = s.
class RobustWeight
{
   public:
	explicit RobustWeight(const SolverOptions& o)
		: kind_(o.loss == "huber" ? Huber : o.loss == "cauchy" ? Cauchy : None), a_(o.loss_scale), a2_(a_ * a_), inv_a2_(1.0 / a2_)
	{
	}
	double operator()(double s) const
	{
		if (kind_ == Huber) return s > a2_ ? a_ / std::sqrt(s) : 1.0;
		if (kind_ == Cauchy) return 1.0 / (1.0 + s * inv_a2_);
		return 1.0;
	}

   private:
	enum Kind { None, Huber, Cauchy } kind_;
	double a_, a2_, inv_a2_;
};

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

/// The robust weight rho'(s) of each squared distance.
void weigh(const std::vector<double>& s, const RobustWeight& weight, std::vector<double>& w)
{
	w.resize(s.size());
	for (std::size_t i = 0; i < s.size(); ++i) w[i] = weight(s[i]);
}

/// Weighted normal equations of the matches at T over the tangent [rotation (left), translation]:
/// J^T W J, J^T W r and the weighted cost 1/2 sum w r^2.
struct NormalEquations
{
	Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
	Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
	double cost = 0;
};

/// `w`: the weights of the edges, then of the planes.
NormalEquations normalEquations(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes,
	const std::vector<double>& w, const Eigen::Isometry3d& T)
{
	NormalEquations ne;
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

/// Iteratively reweighted least squares: each iteration weighs the matches by rho'(s) at the current
/// pose and takes one Levenberg-Marquardt step on the weighted squares (Marquardt's damping at 1e-4
/// of the diagonal), kept only where the cost drops as the model predicts. Returns the iterations.
int solveReweighted(const Matches& m, const SolverOptions& o, Eigen::Isometry3d& T)
{
	const RobustWeight weight(o);
	std::vector<double> s, s_next, w;  // squared distances at T and at the step's pose; weights at T
	// Poses composed over many frames drift off SO(3), and a transposed inverse amplifies that.
	T.linear() = Eigen::Quaterniond(T.linear()).normalized().toRotationMatrix();
	squaredDistances(m.edges, m.planes, T, s);
	int it = 0;
	while (it < o.max_solver_iterations)
	{
		++it;
		weigh(s, weight, w);
		const NormalEquations ne = normalEquations(m.edges, m.planes, w, T);
		Eigen::Matrix<double, 6, 6> A = ne.H;
		A.diagonal() += 1e-4 * ne.H.diagonal().cwiseMax(1e-6);
		const Eigen::Matrix<double, 6, 1> d = -A.ldlt().solve(ne.g);
		if (!d.allFinite()) break;
		Eigen::Isometry3d next = T;
		next.linear() = (Eigen::AngleAxisd(d.head<3>().norm(), d.head<3>().normalized()) * Eigen::Quaterniond(T.linear())).normalized().toRotationMatrix();
		next.translation() += d.tail<3>();
		squaredDistances(m.edges, m.planes, next, s_next);
		double cost = 0;
		for (std::size_t i = 0; i < s_next.size(); ++i) cost += w[i] * s_next[i];
		cost *= 0.5;
		const double predicted = -(ne.g.dot(d) + 0.5 * d.dot(ne.H * d));
		if (!(predicted > 0) || ne.cost - cost < 1e-3 * predicted) break;
		T = next;
		s.swap(s_next);  // the next iteration's weights come from these
		if (ne.cost - cost <= 1e-6 * ne.cost) break;  // converged: the weights would not change either
	}
	return it;
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
	weigh(s, RobustWeight(o), w);
	JtJ = normalEquations(edges, planes, w, T).H;
	double sum2 = 0;
	for (double si : s) sum2 += si;
	const std::size_t n = edges.size() + planes.size();
	rms = n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0;
}

SolveReport solvePose(const Matches& m, const SolverOptions& o, Eigen::Isometry3d& T)
{
	SolveReport rep;
	if (m.size() == 0) return rep;
	rep.iterations = solveReweighted(m, o, T);
	evaluateMatches(m.edges, m.planes, o, T, rep.JtJ, rep.rms);
	return rep;
}
}  // namespace vlo::loam
