// The whole corrector on rendered frame pairs of a textured street (synthetic_scene.h) with a known
// VO scale error k: the VO translation is k times the true one, so v_j = k * depth and s = 1 / k.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/scale/scale_corrector.h>

#include <opencv2/core.hpp>

#include <cstdio>
#include <limits>
#include <random>
#include <utility>

#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::scale;
using namespace vlo::scale::test;

namespace
{
const Scene& scene()
{
	static const Scene s = streetScene(3);
	return s;
}

const FramePair& densePair()
{
	static const FramePair p = makePair(scene(), hdl64());
	return p;
}

const FramePair& sparsePair()
{
	static const FramePair p = makePair(scene(), vlp16());
	return p;
}

ScaleOptions vlp16Options()
{
	ScaleOptions o;
	o.keypoint_test = KeypointTest::Fast12Pretest;
	return o;
}

void print(const char* what, const ScaleEstimate& e)
{
	const auto& c = e.counts;
	std::printf("%s: %s s %.4f spread %.4f | projected %d corner %d gradient %d direction %d selected %d tracked %d "
				"epipolar %d gradient %d triangulated %d inliers %d\n",
		what, toString(e.reason), e.scale, e.spread, c.projected, c.corner, c.gradient, c.direction, c.selected, c.tracked,
		c.epipolar_kept, c.gradient_kept, c.triangulated, c.inliers);
}

/// The pair as the pipeline's frames C(i-1) (image, scan, rig) and C(i) (image, rig).
std::pair<Frame, Frame> framesOf(const FramePair& p)
{
	Frame prev, cur;
	prev.has_image = prev.has_scan = cur.has_image = true;
	prev.image = mrpt::img::CImage(p.prev, mrpt::img::SHALLOW_COPY);
	cur.image = mrpt::img::CImage(p.cur, mrpt::img::SHALLOW_COPY);
	prev.scan = p.scan;
	prev.rig = cur.rig = p.rig;
	return {prev, cur};
}

ScaleEstimate run(const FramePair& p, const ScaleOptions& opt, double k, const PointCloud* scan = nullptr)
{
	return ScaleCorrector(opt).estimate(p.prev, scan ? *scan : p.scan, p.cur, p.rig.camera, p.rig.camera_T_lidar(),
		withScaledTranslation(p.cur_T_prev, k));
}

int countStage(const ScaleEstimate& e, Stage s)
{
	int n = 0;
	for (const auto& k : e.keypoints) n += k.rejected_by == s;
	return n;
}
}  // namespace

class KnownScaleError : public ::testing::TestWithParam<double>
{
};

TEST_P(KnownScaleError, Hdl64Fast9RecoversOneOverKWithinOnePercent)
{
	const double k = GetParam();
	const ScaleEstimate e = run(densePair(), ScaleOptions{}, k);
	print("HDL-64 FAST-9", e);
	ASSERT_TRUE(e.valid) << toString(e.reason);
	EXPECT_NEAR(e.scale * k, 1.0, 0.01);
	EXPECT_GE(e.counts.inliers, 50);
	EXPECT_LT(e.spread * k, 0.03);
}

TEST_P(KnownScaleError, Vlp16Fast12PretestRecoversOneOverKWithinOnePercent)
{
	const double k = GetParam();
	const ScaleEstimate e = run(sparsePair(), vlp16Options(), k);
	print("VLP-16 FAST-12 pre-test", e);
	ASSERT_TRUE(e.valid) << toString(e.reason);
	EXPECT_NEAR(e.scale * k, 1.0, 0.01);
	EXPECT_GE(e.counts.inliers, 30);
}

INSTANTIATE_TEST_SUITE_P(Scale, KnownScaleError, ::testing::Values(0.7, 1.0, 1.3));

TEST(ScaleCorrector, SparseLidarThePretestFindsMoreKeypointsThanFast9)
{
	ScaleOptions fast9 = vlp16Options();
	fast9.keypoint_test = KeypointTest::Fast9;
	const ScaleEstimate a = run(sparsePair(), fast9, 1.0), b = run(sparsePair(), vlp16Options(), 1.0);
	print("VLP-16 FAST-9", a);
	EXPECT_GT(b.counts.corner, 3 * a.counts.corner / 2);
	EXPECT_GT(b.counts.inliers, a.counts.inliers);
}

TEST(ScaleCorrector, RansacRejectsCorruptedLidarDepths)
{
	// 40 % of the scan's ranges are wrong by -40 % .. +60 % (multipath, mixed pixels, a bad extrinsic).
	PointCloud scan = densePair().scan;
	std::mt19937 rng(5);
	std::uniform_real_distribution<float> u(0, 1), f(0.6f, 1.6f);
	for (auto& p : scan)
	{
		if (u(rng) >= 0.4f) continue;
		const float m = f(rng);
		p.x *= m, p.y *= m, p.z *= m;
	}
	for (double k : {0.7, 1.3})
	{
		const ScaleEstimate e = run(densePair(), ScaleOptions{}, k, &scan);
		print("HDL-64 40 % corrupted", e);
		ASSERT_TRUE(e.valid) << toString(e.reason);
		EXPECT_NEAR(e.scale * k, 1.0, 0.01);
		EXPECT_GT(countStage(e, Stage::Ransac), e.counts.triangulated / 5);  // RANSAC did the work
	}
}

TEST(ScaleCorrector, CullingOffStillRunsAndCullingRemovesTracks)
{
	ScaleOptions off;
	off.cull_epipolar = off.cull_gradient = false;
	const ScaleEstimate a = run(densePair(), off, 1.3), b = run(densePair(), ScaleOptions{}, 1.3);
	ASSERT_TRUE(a.valid);
	EXPECT_EQ(a.counts.gradient_kept, a.counts.tracked);
	EXPECT_LT(b.counts.gradient_kept, b.counts.tracked * 9 / 10);
	EXPECT_NEAR(a.scale * 1.3, 1.0, 0.02);
}

TEST(ScaleCorrector, DiagnosticsAddUp)
{
	const ScaleEstimate e = run(densePair(), ScaleOptions{}, 1.3);
	const auto& c = e.counts;
	EXPECT_EQ(c.selected, static_cast<int>(e.keypoints.size()));
	EXPECT_EQ(c.tracked, c.selected - countStage(e, Stage::Tracking));
	EXPECT_EQ(c.epipolar_kept, c.tracked - countStage(e, Stage::Epipolar));
	EXPECT_EQ(c.gradient_kept, c.epipolar_kept - countStage(e, Stage::Gradient));
	EXPECT_EQ(c.triangulated, c.gradient_kept - countStage(e, Stage::Triangulation));
	EXPECT_EQ(c.inliers, countStage(e, Stage::None));
	EXPECT_EQ(c.inliers, c.triangulated - countStage(e, Stage::Ransac));
	EXPECT_GE(c.projected, c.corner);
	EXPECT_GE(c.corner, c.gradient);
	EXPECT_GE(c.gradient, c.direction);
	EXPECT_GE(c.direction, c.selected);
	for (const auto& k : e.keypoints)
	{
		if (k.rejected_by != Stage::None) continue;
		EXPECT_LT(k.normal_error, 0.5);
		EXPECT_GT(k.abs_cos, 0.5);
		EXPECT_NEAR(k.s, k.d / k.v, 1e-5);
		const auto& p = densePair().scan[k.scan_index];
		EXPECT_NEAR(k.d, (densePair().rig.camera_T_lidar() * Eigen::Vector3d(p.x, p.y, p.z)).z(), 1e-4);
	}
	// The pair reaches the end with keypoints at every stage; the cap holds; the ratio is the counts'.
	EXPECT_TRUE(e.valid);
	EXPECT_GT(c.inliers, 0);
	EXPECT_LE(c.selected, ScaleOptions{}.max_keypoints);
	EXPECT_NEAR(e.inlier_ratio, double(c.inliers) / c.triangulated, 1e-12);
	// A valid estimate ran every stage: each took time, reported in the pipeline's order.
	ASSERT_EQ(e.ms.stages().size(), 6u);
	EXPECT_EQ(e.ms.stages().front().first, "project");
	for (const auto& [stage, ms] : e.ms.stages()) EXPECT_GT(ms, 0.0) << stage;
}

TEST(ScaleCorrector, Deterministic)
{
	const ScaleEstimate a = run(densePair(), ScaleOptions{}, 0.7), b = run(densePair(), ScaleOptions{}, 0.7);
	EXPECT_EQ(a.scale, b.scale);
	ASSERT_EQ(a.keypoints.size(), b.keypoints.size());
	for (size_t i = 0; i < a.keypoints.size(); ++i) EXPECT_EQ(a.keypoints[i].rejected_by, b.keypoints[i].rejected_by);
}

TEST(ScaleCorrector, FrameOverloadMatches)
{
	const FramePair& p = densePair();
	auto [prev, cur] = framesOf(p);
	const ScaleEstimate e = ScaleCorrector().estimate(prev, cur, withScaledTranslation(p.cur_T_prev, 1.3));
	EXPECT_EQ(e.scale, run(p, ScaleOptions{}, 1.3).scale);
	cur.has_image = false;
	EXPECT_THROW(ScaleCorrector().estimate(prev, cur, p.cur_T_prev), InputError);
}

TEST(ScaleCorrector, TakesThePreviousFramesPyramidOnlyWhenItIsThatFrames)
{
	const FramePair& p = densePair();
	auto [prev, cur] = framesOf(p);
	prev.index = 4, cur.index = 5;
	const ScaleOptions opt;
	const ScaleCorrector sc(opt);
	const auto motion = withScaledTranslation(p.cur_T_prev, 1.3);
	const ScaleEstimate plain = sc.estimate(prev, cur, motion);
	ASSERT_TRUE(plain.valid);
	const auto tracked = [](const ScaleEstimate& e) {
		std::vector<cv::Point2f> v;
		for (const auto& k : e.keypoints) v.push_back(k.cur);
		return v;
	};
	// prev's own pyramid: the same estimate; afterwards the reuse holds cur's.
	PyramidReuse reuse{4, buildLkPyramid(p.prev, opt)};
	const ScaleEstimate same = sc.estimate(prev, cur, motion, &reuse);
	EXPECT_EQ(same.scale, plain.scale);
	EXPECT_EQ(tracked(same), tracked(plain));
	EXPECT_EQ(reuse.frame, 5u);
	EXPECT_FALSE(reuse.pyramid.empty());
	// A pyramid said to be prev's is taken as it is (here a wrong one: other tracks) ...
	reuse = {4, buildLkPyramid(p.cur, opt)};
	EXPECT_NE(tracked(sc.estimate(prev, cur, motion, &reuse)), tracked(plain));
	// ... and one of another frame is not.
	reuse = {3, buildLkPyramid(p.cur, opt)};
	EXPECT_EQ(tracked(sc.estimate(prev, cur, motion, &reuse)), tracked(plain));
}

TEST(ScaleCorrector, NoEstimateWithoutMotionOrWithABackwardTranslation)
{
	const FramePair& p = densePair();
	const ScaleCorrector sc;
	Eigen::Isometry3d still = p.cur_T_prev;
	still.translation().setZero();
	EXPECT_EQ(sc.estimate(p.prev, p.scan, p.cur, p.rig.camera, p.rig.camera_T_lidar(), still).reason,
		Reason::DegenerateMotion);
	// The vehicle creeps 2 cm: the rays are nearly parallel.
	const FramePair creep = makePair(scene(), hdl64(), 0.02, 0.0);
	const ScaleEstimate c = run(creep, ScaleOptions{}, 1.0);
	print("2 cm", c);
	EXPECT_FALSE(c.valid);
	EXPECT_EQ(c.reason, Reason::DegenerateMotion);
	// A VO translation of the wrong sign: the epipolar lines are the same, but every point is behind.
	const ScaleEstimate back = run(p, ScaleOptions{}, -1.0);
	EXPECT_FALSE(back.valid);
	EXPECT_EQ(back.reason, Reason::FewTriangulated);
	Eigen::Isometry3d nan = p.cur_T_prev;
	nan.translation().x() = std::numeric_limits<double>::quiet_NaN();
	EXPECT_EQ(sc.estimate(p.prev, p.scan, p.cur, p.rig.camera, p.rig.camera_T_lidar(), nan).reason, Reason::BadPose);
}

TEST(ScaleCorrector, TooLittleInputIsReportedNotThrown)
{
	const FramePair& p = densePair();
	const ScaleCorrector sc;
	EXPECT_EQ(sc.estimate(p.prev, {}, p.cur, p.rig.camera, p.rig.camera_T_lidar(), p.cur_T_prev).reason,
		Reason::FewProjected);
	const cv::Mat flat(p.prev.size(), CV_8U, cv::Scalar(128));
	EXPECT_EQ(sc.estimate(flat, p.scan, p.cur, p.rig.camera, p.rig.camera_T_lidar(), p.cur_T_prev).reason,
		Reason::FewKeypoints);
}

TEST(ScaleCorrector, ImagesThatDoNotMatchTheCameraThrow)
{
	const FramePair& p = densePair();
	const ScaleCorrector sc;
	const cv::Mat small(100, 100, CV_8U, cv::Scalar(0));
	EXPECT_THROW(sc.estimate(small, p.scan, p.cur, p.rig.camera, p.rig.camera_T_lidar(), p.cur_T_prev), InputError);
	EXPECT_THROW(sc.estimate(p.prev, p.scan, cv::Mat(), p.rig.camera, p.rig.camera_T_lidar(), p.cur_T_prev), InputError);
	cv::Mat bgr;
	cv::merge(std::vector<cv::Mat>{p.cur, p.cur, p.cur}, bgr);
	EXPECT_THROW(sc.estimate(p.prev, p.scan, bgr, p.rig.camera, p.rig.camera_T_lidar(), p.cur_T_prev), InputError);
}
