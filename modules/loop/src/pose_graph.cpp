#include <vlo/core/stopwatch.h>
#include <vlo/loop/pose_graph.h>

#include <ceres/ceres.h>

#include <Eigen/Cholesky>

namespace vlo::loop
{
namespace
{
/// Residual of an edge: the relative pose the nodes give against the measured one, whitened.
class RelativePoseError
{
   public:
	RelativePoseError(const Eigen::Vector3d& p, const Eigen::Quaterniond& q, const Matrix6d& sqrt_information)
		: p_(p), q_(q), sqrt_information_(sqrt_information)
	{
	}

	template <typename T>
	bool operator()(const T* pa, const T* qa, const T* pb, const T* qb, T* out) const
	{
		const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_a(pa), p_b(pb);
		const Eigen::Map<const Eigen::Quaternion<T>> q_a(qa), q_b(qb);
		const Eigen::Quaternion<T> a_inv = q_a.conjugate();
		const Eigen::Quaternion<T> q_ab = a_inv * q_b;
		const Eigen::Matrix<T, 3, 1> p_ab = a_inv * (p_b - p_a);
		// Rotation error as a left perturbation of the measurement: q_ab = exp(e) q_measured.
		const Eigen::Quaternion<T> error = q_ab * q_.template cast<T>().conjugate();
		Eigen::Matrix<T, 6, 1> r;
		r.template head<3>() = p_ab - p_.template cast<T>();
		r.template tail<3>() = T(2.0) * error.vec();
		Eigen::Map<Eigen::Matrix<T, 6, 1>> whitened(out);
		whitened = sqrt_information_.template cast<T>() * r;
		return true;
	}

   private:
	Eigen::Vector3d p_;
	Eigen::Quaterniond q_;
	Matrix6d sqrt_information_;
};
}  // namespace

std::size_t PoseGraph::addNode(const Eigen::Isometry3d& initial)
{
	nodes_.push_back({initial.translation(), Eigen::Quaterniond(initial.linear()).normalized()});
	return nodes_.size() - 1;
}

void PoseGraph::addEdge(std::size_t a, std::size_t b, const Eigen::Isometry3d& a_T_b, const Matrix6d& information, double huber)
{
	// The upper Cholesky factor U (U^T U = information) whitens: |U r|^2 = r^T information r.
	const Matrix6d symmetric = 0.5 * (information + information.transpose());
	const Matrix6d U = symmetric.llt().matrixU();
	edges_.push_back({a, b, a_T_b.translation(), Eigen::Quaterniond(a_T_b.linear()).normalized(), U, huber});
}

PoseGraph::Summary PoseGraph::optimise(int max_iterations)
{
	Summary out;
	if (nodes_.size() < 2 || edges_.empty()) return out;
	const auto t0 = SteadyClock::now();
	const std::vector<Node> before = nodes_;
	ceres::Problem::Options problem_options;
	problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
	problem_options.loss_function_ownership = ceres::TAKE_OWNERSHIP;
	ceres::Problem problem(problem_options);
	ceres::EigenQuaternionManifold quaternion;
	for (const Edge& e : edges_)
	{
		auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 6, 3, 4, 3, 4>(
			new RelativePoseError(e.p, e.q, e.sqrt_information));
		ceres::LossFunction* loss = e.huber > 0 ? new ceres::HuberLoss(e.huber) : nullptr;
		problem.AddResidualBlock(cost, loss, nodes_[e.a].p.data(), nodes_[e.a].q.coeffs().data(), nodes_[e.b].p.data(),
			nodes_[e.b].q.coeffs().data());
	}
	for (Node& n : nodes_)
		if (problem.HasParameterBlock(n.q.coeffs().data())) problem.SetManifold(n.q.coeffs().data(), &quaternion);
	if (problem.HasParameterBlock(nodes_[0].p.data()))
	{
		problem.SetParameterBlockConstant(nodes_[0].p.data());
		problem.SetParameterBlockConstant(nodes_[0].q.coeffs().data());
	}
	ceres::Solver::Options options;
	options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
	options.max_num_iterations = max_iterations;
	options.num_threads = 1;
	options.logging_type = ceres::SILENT;
	ceres::Solver::Summary summary;
	ceres::Solve(options, &problem, &summary);
	out.iterations = static_cast<int>(summary.iterations.size());
	out.initial_cost = summary.initial_cost;
	out.final_cost = summary.final_cost;
	out.usable = summary.IsSolutionUsable();
	if (!out.usable) nodes_ = before;
	for (Node& n : nodes_) n.q.normalize();
	out.seconds = msSince(t0) / 1000.0;
	return out;
}

Eigen::Isometry3d PoseGraph::pose(std::size_t node) const
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = nodes_[node].q.toRotationMatrix();
	T.translation() = nodes_[node].p;
	return T;
}

}  // namespace vlo::loop
