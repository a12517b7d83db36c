// Local bundle adjustment off the tracking path (bundle_job.h): solved on a thread, or split over two
// frames without one, it gives exactly the inline result, it recovers known poses, a map scaled while
// it is pending gets the scaled result, and the VO's outputs are the same with and without the mapping
// thread, the BA entering exactly mapping_delay frames after its keyframe.
#include <gtest/gtest.h>
#include <vlo/vo/bundle_job.h>
#include <vlo/vo/map.h>

#include <random>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
/// Five keyframes along x looking down z at 150 points, observed without noise. Keyframes 0 and 4
/// are fixed (they fix the gauge and the scale); 1-3 and the points start perturbed.
struct SmallWindow
{
	Map map;
	BundleWindow w;
	std::vector<SE3> truth;  ///< Tcw of each keyframe

	/// `outliers`: that many of keyframe 2's keypoints moved 25 px (wrong matches).
	explicit SmallWindow(const PinholeCamera& cam, int outliers = 0)
	{
		std::mt19937 rng(5);
		std::uniform_real_distribution<double> u(-1, 1);
		std::vector<Vec3> X;
		for (int i = 0; i < 150; ++i) X.emplace_back(4 * u(rng), 2 * u(rng), 12 + 6 * u(rng));
		for (int k = 0; k < 5; ++k)
		{
			SE3 Twc = SE3::Identity();
			Twc.translation() = Vec3(0.5 * k, 0.02 * k * k, 0.3 * k);
			truth.push_back(Twc.inverse());
			auto f = std::make_shared<Features>();
			for (const Vec3& p : X)
			{
				const Vec2 px = project(cam, truth.back() * p);
				f->keys.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()), 8.f, 0.f, 0.f, 0);
			}
			if (k == 2)
				for (int i = 0; i < outliers; ++i) f->keys[static_cast<std::size_t>(7 * i)].pt += cv::Point2f(25.f, -18.f);
			f->descriptors = cv::Mat::zeros(static_cast<int>(X.size()), 32, CV_8U);
			SE3 start = truth.back();
			if (k > 0 && k < 4) start.translation() += Vec3(0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng));
			KeyFrame* kf = map.addKeyFrame(k, 0.1 * k, f, start);
			(k > 0 && k < 4 ? w.local : w.fixed).push_back(kf);
		}
		w.anchor = w.local.front();
		for (std::size_t i = 0; i < X.size(); ++i)
		{
			const Vec3 noisy = X[i] + Vec3(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
			MapPoint* mp = map.addPoint(noisy, w.fixed.front());
			for (KeyFrame* kf : map.keyFrames())
			{
				mp->addObservation(kf, static_cast<int>(i));
				kf->points[i] = mp;
			}
			w.points.push_back(mp);
		}
	}
};

/// The world scaled by s about c: camera centres and points move, orientations stay.
void scaleWorld(Map& map, double s, const Vec3& c)
{
	for (KeyFrame* kf : map.keyFrames())
		kf->Tcw.translation() = -kf->Tcw.linear() * (c + s * (kf->centre() - c));
	for (MapPoint* p : map.points()) p->pos = c + s * (p->pos - c);
}

void expectSameMap(const Map& a, const Map& b, double tol)
{
	const auto ka = a.keyFrames(), kb = b.keyFrames();
	ASSERT_EQ(ka.size(), kb.size());
	for (std::size_t i = 0; i < ka.size(); ++i) EXPECT_LE((ka[i]->Tcw.matrix() - kb[i]->Tcw.matrix()).norm(), tol) << "keyframe " << i;
	const auto pa = a.points(), pb = b.points();
	ASSERT_EQ(pa.size(), pb.size());
	for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_LE((pa[i]->pos - pb[i]->pos).norm(), tol) << "point " << i;
}

const BundleSolverSettings kSolver{5, 10, 5.991};
}  // namespace

TEST(BundleJob, SolvedOnAThreadEqualsTheInlineAdjustment)
{
	const auto cam = test::kittiCamera();
	SmallWindow a(cam), b(cam);  // seeded: the same map twice
	const BundleStats sa = bundleAdjust(a.w, cam, ScalePyramid(), kSolver.iterations, kSolver.refine_iterations, kSolver.chi2);
	BundleJob job(b.w, cam, ScalePyramid(), kSolver, 7, true);
	EXPECT_EQ(job.dueFrame(), 7);
	const BundleStats sb = job.apply();
	EXPECT_EQ(sa.observations, 5 * 150);
	EXPECT_EQ(sb.observations, sa.observations);
	EXPECT_EQ(sb.final_cost, sa.final_cost);
	expectSameMap(a.map, b.map, 0.0);
}

TEST(BundleJob, WithoutAThreadTheSolveIsSplitAndGivesTheSameResult)
{
	// One thread: the robust pass runs on advance() (the frame after the keyframe's), the refine pass
	// when the job is applied (the due frame); the map changes only then, as with a thread.
	const auto cam = test::kittiCamera();
	SmallWindow a(cam), b(cam), c(cam);
	bundleAdjust(a.w, cam, ScalePyramid(), kSolver.iterations, kSolver.refine_iterations, kSolver.chi2);
	BundleJob job(b.w, cam, ScalePyramid(), kSolver, 3, false);
	EXPECT_EQ(job.passesDone(), 0);
	job.advance();
	EXPECT_EQ(job.passesDone(), 1);
	job.advance();  // once only
	EXPECT_EQ(job.passesDone(), 1);
	expectSameMap(b.map, c.map, 0.0);  // nothing entered yet
	job.apply();
	EXPECT_EQ(job.passesDone(), 2);
	expectSameMap(a.map, b.map, 0.0);
	{
		SmallWindow d(cam);  // without advance(): all of it when applied
		BundleJob whole(d.w, cam, ScalePyramid(), kSolver, 3, false);
		whole.apply();
		EXPECT_EQ(whole.passesDone(), 2);
		expectSameMap(a.map, d.map, 0.0);
	}
	BundleJob threaded(c.w, cam, ScalePyramid(), kSolver, 3, true);
	threaded.apply();
	EXPECT_EQ(threaded.passesDone(), 2);
	expectSameMap(a.map, c.map, 0.0);
}

TEST(BundleJob, RecoversTheTruePoses)
{
	const auto cam = test::kittiCamera();
	SmallWindow a(cam);
	BundleJob job(a.w, cam, ScalePyramid(), kSolver, 0, true);
	const BundleStats st = job.apply();
	EXPECT_EQ(st.keyframes, 3);
	EXPECT_EQ(st.fixed, 2);
	EXPECT_EQ(st.outliers, 0);
	const auto kfs = a.map.keyFrames();
	for (std::size_t k = 0; k < kfs.size(); ++k)
		EXPECT_LT((kfs[k]->Tcw.matrix() - a.truth[k].matrix()).norm(), 1e-6) << "keyframe " << k;
}

TEST(BundleJob, RecoversTheTruePosesDespiteWrongMatches)
{
	// The robust pass keeps 12 wrong matches (31 px off) from pulling the poses, marks them, and the
	// refine pass without them lands on the truth.
	const auto cam = test::kittiCamera();
	SmallWindow a(cam, 12);
	BundleJob job(a.w, cam, ScalePyramid(), kSolver, 0, true);
	const BundleStats st = job.apply();
	EXPECT_EQ(st.outliers, 12);
	EXPECT_GT(st.initial_cost, st.final_cost);
	const auto kfs = a.map.keyFrames();
	for (std::size_t k = 0; k < kfs.size(); ++k)
		EXPECT_LT((kfs[k]->Tcw.matrix() - a.truth[k].matrix()).norm(), 1e-6) << "keyframe " << k;
}

TEST(BundleJob, MapScaledWhilePendingGetsTheScaledResult)
{
	const auto cam = test::kittiCamera();
	const Vec3 centres[] = {Vec3::Zero(), Vec3(3, -1, 20)};
	for (const Vec3& c : centres)
	{
		SmallWindow a(cam), b(cam);
		// a: adjusted, then scaled. b: scaled twice while its adjustment is pending (as the scale
		// corrector may do between a keyframe and the frame its mapping is due).
		bundleAdjust(a.w, cam, ScalePyramid(), kSolver.iterations, kSolver.refine_iterations, kSolver.chi2);
		scaleWorld(a.map, 1.7, c);
		scaleWorld(a.map, 0.8, Vec3(-2, 0, 5));
		BundleJob job(b.w, cam, ScalePyramid(), kSolver, 1, true);
		scaleWorld(b.map, 1.7, c);
		job.scale(1.7);
		scaleWorld(b.map, 0.8, Vec3(-2, 0, 5));
		job.scale(0.8);
		job.apply();
		expectSameMap(a.map, b.map, 1e-9);
	}
}

TEST(BundleJob, VoOutputsAreTheSameWithAMappingThread)
{
	const auto cam = test::kittiCamera(0.5);
	for (int delay : {0, 1, 2})
	{
		VoOptions opt;
		opt.mapping.mapping_delay = delay;
		const auto one = test::runStreet(cam, 40, opt, -1, -1, false);
		const auto two = test::runStreet(cam, 40, opt, -1, -1, true);
		ASSERT_EQ(one.infos.size(), two.infos.size());
		int keyframes = 0, adjusted = 0;
		for (std::size_t i = 0; i < one.infos.size(); ++i)
		{
			const auto &x = one.infos[i], &y = two.infos[i];
			ASSERT_EQ(x.pose.has_value(), y.pose.has_value()) << "frame " << i;
			if (x.pose)
			{
				EXPECT_EQ(x.pose->matrix(), y.pose->matrix()) << "frame " << i;
			}
			EXPECT_EQ(x.map_points, y.map_points);
			EXPECT_EQ(x.ba_points, y.ba_points);
			// Keyframe k's BA enters at frame k + delay, with one thread and with two (the initial
			// map's keyframe is adjusted by the map's own BA).
			const VoFrameInfo* k = i >= static_cast<std::size_t>(delay) ? &one.infos[i - static_cast<std::size_t>(delay)] : nullptr;
			const bool due = k && k->keyframe && !k->new_map;
			EXPECT_EQ(x.ba_keyframes > 0, due) << "frame " << i << ", delay " << delay;
			EXPECT_EQ(y.ba_keyframes > 0, due) << "frame " << i << ", delay " << delay;
			keyframes += x.keyframe;
			adjusted += x.ba_keyframes > 0;
		}
		EXPECT_GT(keyframes, 3) << "delay " << delay;
		EXPECT_GT(adjusted, 3) << "delay " << delay;
		EXPECT_EQ(one.lost, 0);
	}
}
