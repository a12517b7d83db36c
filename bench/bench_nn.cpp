// vlo's own voxel filter, kd-tree and voxel maps beside PCL's VoxelGrid and KdTreeFLANN and a plain
// nanoflann index, on the synthetic HDL-64E scans of the other LiDAR benchmarks (~125k points):
// build time, and query time of the searches LOAM and ICP make (whether vlo's own are worth keeping).
//   build/bin/bench_nn --benchmark_counters_tabular=true
// The queries are the next scan's points (1 m further on); in each query group every structure indexes the same
// points (the content of LOAM's or ICP's voxel map built from the first scan) and answers the same queries.
#include <benchmark/benchmark.h>
#include <vlo/icp/voxel_map.h>
#include <vlo/loam/kdtree.h>
#include <vlo/loam/voxel_filter.h>
#include <vlo/loam/voxel_map.h>

#include <nanoflann.hpp>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>

#include "urban_street_scans.h"

using namespace vlo;

namespace
{
/// Scan 0 as the indexed set, scan 1 as the queries.
const loam::ScanPoints& scanPoints(int i)
{
	static std::vector<loam::ScanPoints> s;
	if (s.empty())
		for (const auto& cloud : loam::test::urbanStreetScans(true, 2))
		{
			loam::ScanPoints pts;
			for (const auto& p : cloud) pts.push_back({Eigen::Vector3f(p.x, p.y, p.z), 0, 0});
			s.push_back(pts);
		}
	return s[i];
}
pcl::PointCloud<pcl::PointXYZ>::Ptr pclCloud(int i)
{
	auto c = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
	for (const auto& p : scanPoints(i)) c->push_back({p.p.x(), p.p.y(), p.p.z()});
	return c;
}
std::vector<Eigen::Vector3f> vectors(int i)
{
	std::vector<Eigen::Vector3f> v;
	for (const auto& p : scanPoints(i)) v.push_back(p.p);
	return v;
}
/// LOAM's plane map (voxel 2 m, one point per 0.4 m cell, 80 a voxel) and ICP's local map (1 m voxels, 20 a
/// voxel), built from scan 0 with their default options; the kd-trees index the same points.
const loam::VoxelMap& loamMap()
{
	static loam::VoxelMap m(2.0, 0.4, 80);
	if (m.numPoints() == 0) m.insert(vectors(0));
	return m;
}
const icp::VoxelMap& icpMap()
{
	static icp::VoxelMap m(1.0, 20, 100.0);
	if (m.empty())
		for (const auto& p : vectors(0)) m.addPoints({p.cast<double>()});
	return m;
}
std::vector<Eigen::Vector3f> mapPoints(bool loam)
{
	std::vector<Eigen::Vector3f> v;
	if (loam) loamMap().appendPoints(v);
	else
		for (const auto& p : icpMap().points()) v.push_back(p.cast<float>());
	return v;
}
loam::ScanPoints asScan(const std::vector<Eigen::Vector3f>& v)
{
	loam::ScanPoints s;
	for (const auto& p : v) s.push_back({p, 0, 0});
	return s;
}
pcl::PointCloud<pcl::PointXYZ>::Ptr asPcl(const std::vector<Eigen::Vector3f>& v)
{
	auto c = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
	for (const auto& p : v) c->push_back({p.x(), p.y(), p.z()});
	return c;
}
constexpr float kLeaf = 0.4f;  // LOAM's edge_leaf
constexpr int kK = 5;  // LOAM's mapping neighbours
constexpr float kMaxDist = 1.0f;  // LOAM's max_nn_distance

void setQueries(benchmark::State& state) { state.SetItemsProcessed(state.iterations() * scanPoints(1).size()); }

// --- voxel filter ---
void BM_VoxelFilter_Vlo(benchmark::State& state)
{
	for (auto _ : state) benchmark::DoNotOptimize(loam::voxelDownsample(scanPoints(0), kLeaf));
	state.counters["out"] = double(loam::voxelDownsample(scanPoints(0), kLeaf).size());
}
void BM_VoxelFilter_PclVoxelGrid(benchmark::State& state)
{
	const auto in = pclCloud(0);
	pcl::PointCloud<pcl::PointXYZ> out;
	pcl::VoxelGrid<pcl::PointXYZ> grid;
	grid.setLeafSize(kLeaf, kLeaf, kLeaf);
	for (auto _ : state)
	{
		grid.setInputCloud(in);
		grid.filter(out);
	}
	state.counters["out"] = double(out.size());
}
BENCHMARK(BM_VoxelFilter_Vlo)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelFilter_PclVoxelGrid)->Unit(benchmark::kMillisecond);

// --- 1-NN, as LOAM's scan-to-scan matching and ICP's correspondences ---
struct Adaptor
{
	const std::vector<Eigen::Vector3f>* pts;
	std::size_t kdtree_get_point_count() const { return pts->size(); }
	float kdtree_get_pt(std::size_t i, std::size_t d) const { return (*pts)[i][int(d)]; }
	template <class B>
	bool kdtree_get_bbox(B&) const
	{
		return false;
	}
};
using Nanoflann = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Adaptor>, Adaptor, 3, int>;

void BM_Build_VloKdTree(benchmark::State& state)
{
	loam::PointKdTree tree;
	for (auto _ : state) tree.build(scanPoints(0));
}
void BM_Build_PclKdTreeFLANN(benchmark::State& state)
{
	const auto in = pclCloud(0);
	pcl::KdTreeFLANN<pcl::PointXYZ> tree;
	for (auto _ : state) tree.setInputCloud(in);
}
void BM_Build_LoamVoxelMap(benchmark::State& state)
{
	const auto pts = vectors(0);
	for (auto _ : state)
	{
		loam::VoxelMap map(2.0, 0.4, 80);
		benchmark::DoNotOptimize(map.insert(pts));
	}
}
void BM_Build_IcpVoxelMap(benchmark::State& state)
{
	icp::Points pts;
	for (const auto& p : vectors(0)) pts.push_back(p.cast<double>());
	for (auto _ : state)
	{
		icp::VoxelMap map(1.0, 20, 100.0);
		map.addPoints(pts);
	}
}
BENCHMARK(BM_Build_VloKdTree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Build_PclKdTreeFLANN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Build_LoamVoxelMap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Build_IcpVoxelMap)->Unit(benchmark::kMillisecond);

void BM_Nearest_VloKdTree(benchmark::State& state)
{
	const auto pts = asScan(mapPoints(false));
	loam::PointKdTree tree;
	tree.build(pts);
	state.counters["indexed"] = double(pts.size());
	for (auto _ : state)
		for (const auto& q : scanPoints(1))
		{
			float d2;
			benchmark::DoNotOptimize(tree.nearest(q.p, &d2));
		}
	setQueries(state);
}
void BM_Nearest_PclKdTreeFLANN(benchmark::State& state)
{
	pcl::KdTreeFLANN<pcl::PointXYZ> tree;
	tree.setInputCloud(asPcl(mapPoints(false)));
	const auto queries = pclCloud(1);
	std::vector<int> idx(1);
	std::vector<float> d2(1);
	for (auto _ : state)
		for (const auto& q : *queries) benchmark::DoNotOptimize(tree.nearestKSearch(q, 1, idx, d2));
	setQueries(state);
}
void BM_Nearest_IcpVoxelMap(benchmark::State& state)
{
	const icp::VoxelMap& map = icpMap();
	Eigen::Vector3d closest;
	double d2;
	for (auto _ : state)
		for (const auto& q : scanPoints(1)) benchmark::DoNotOptimize(map.nearest(q.p.cast<double>(), closest, d2));
	setQueries(state);
}
BENCHMARK(BM_Nearest_VloKdTree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Nearest_PclKdTreeFLANN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Nearest_IcpVoxelMap)->Unit(benchmark::kMillisecond);

// --- k nearest within a radius, as LOAM's scan-to-map matching ---
void BM_Knn5_LoamVoxelMap(benchmark::State& state)
{
	const loam::VoxelMap& map = loamMap();
	state.counters["indexed"] = double(map.numPoints());
	Eigen::Vector3f nn[kK];
	for (auto _ : state)
		for (const auto& q : scanPoints(1)) benchmark::DoNotOptimize(map.knn(q.p, kK, kMaxDist, nn));
	setQueries(state);
}
void BM_Knn5_PclKdTreeFLANN(benchmark::State& state)
{
	pcl::KdTreeFLANN<pcl::PointXYZ> tree;
	tree.setInputCloud(asPcl(mapPoints(true)));
	const auto queries = pclCloud(1);
	std::vector<int> idx(kK);
	std::vector<float> d2(kK);
	for (auto _ : state)
		for (const auto& q : *queries) benchmark::DoNotOptimize(tree.nearestKSearch(q, kK, idx, d2));
	setQueries(state);
}
void BM_Knn5_Nanoflann(benchmark::State& state)
{
	const auto pts = mapPoints(true);
	Adaptor a{&pts};
	Nanoflann tree(3, a, nanoflann::KDTreeSingleIndexAdaptorParams(10));
	tree.buildIndex();
	int idx[kK];
	float d2[kK];
	for (auto _ : state)
		for (const auto& q : scanPoints(1))
		{
			nanoflann::KNNResultSet<float, int> rs(kK);
			rs.init(idx, d2);
			tree.findNeighbors(rs, q.p.data(), nanoflann::SearchParams());
			benchmark::DoNotOptimize(d2[0]);
		}
	setQueries(state);
}
BENCHMARK(BM_Knn5_LoamVoxelMap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Knn5_PclKdTreeFLANN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Knn5_Nanoflann)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
