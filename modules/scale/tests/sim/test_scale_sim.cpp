// The corrector on two consecutive frames of modules/sim (mesh world, KITTI rig, image and range
// noise, dropouts), with the ground-truth relative pose given a known scale error k: s = 1 / k.
#include <gtest/gtest.h>
#include <vlo/scale/scale_corrector.h>
#include <vlo/sim/simulator.h>

#include <cstdio>

using namespace vlo;
using namespace vlo::scale;

namespace
{
struct SimPair
{
	Frame prev, cur;
	Eigen::Isometry3d cur_T_prev;  ///< camera C(i-1) -> C(i), metres
};

SimPair simulate(sim::Scenario scenario, const sim::LidarModel& lidar, int frame)
{
	sim::SimConfig cfg;
	cfg.scenario = scenario, cfg.lidar = lidar, cfg.frames = frame + 2, cfg.seed = 1;
	sim::Simulator s(cfg);
	SimPair p;
	p.prev = s.frame(frame);
	p.cur = s.frame(frame + 1);
	const Eigen::Isometry3d& v_T_c = p.prev.rig.vehicle_T_camera;
	p.cur_T_prev = (s.vehiclePose(frame + 1) * v_T_c).inverse() * (s.vehiclePose(frame) * v_T_c);
	return p;
}

void check(const char* what, const SimPair& p, const ScaleOptions& opt)
{
	for (double k : {0.7, 1.3})
	{
		Eigen::Isometry3d vo = p.cur_T_prev;
		vo.translation() *= k;
		const ScaleEstimate e = ScaleCorrector(opt).estimate(p.prev, p.cur, vo);
		const auto& c = e.counts;
		std::printf("%s k %.1f: %s s*k %.4f spread %.4f | projected %d selected %d tracked %d epipolar %d "
					"gradient %d triangulated %d inliers %d | %.1f ms\n",
			what, k, toString(e.reason), e.scale * k, e.spread * k, c.projected, c.selected, c.tracked,
			c.epipolar_kept, c.gradient_kept, c.triangulated, c.inliers, e.ms.total());
		ASSERT_TRUE(e.valid) << toString(e.reason);
		EXPECT_NEAR(e.scale * k, 1.0, 0.01);
	}
}
}  // namespace

TEST(ScaleOnSimulator, UrbanHdl64Fast9)
{
	check("urban HDL-64", simulate(sim::Scenario::Urban, sim::hdl64(), 5), ScaleOptions{});
}

TEST(ScaleOnSimulator, UrbanVlp16Fast12Pretest)
{
	ScaleOptions opt;  // what a VLP-16 INI sets: the relaxed test and lower thresholds
	opt.keypoint_test = KeypointTest::Fast12Pretest;
	opt.fast_threshold = 8;
	opt.gradient_threshold = 4;
	check("urban VLP-16", simulate(sim::Scenario::Urban, sim::vlp16(), 5), opt);
}
