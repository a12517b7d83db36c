#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/scale/epipolar.h>
#include <vlo/scale/keypoint_tests.h>
#include <vlo/scale/projection.h>
#include <vlo/scale/ransac.h>
#include <vlo/scale/scale_corrector.h>
#include <vlo/scale/selection.h>
#include <vlo/scale/tracking.h>
#include <vlo/scale/triangulation.h>

#include <opencv2/imgproc.hpp>

namespace vlo::scale
{
namespace
{
/// Frames' images are grey already (io converts them as it reads): one conversion, not one per user.
const cv::Mat& checkedGrey(const cv::Mat& m, const PinholeCamera& cam, const char* which)
{
	const std::string where = std::string("scale corrector: image ") + which;
	if (m.empty()) failInput(where, "is empty");
	if (m.depth() != CV_8U || m.channels() != 1)
		failInput(where, "is not 8-bit grey (" + std::to_string(m.channels()) + " channels)");
	if (m.cols != cam.width || m.rows != cam.height)
		failInput(where,
			"is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) + " but the camera is " +
				std::to_string(cam.width) + "x" + std::to_string(cam.height));
	return m;
}

bool finitePose(const Eigen::Isometry3d& T) { return T.matrix().allFinite(); }
}  // namespace

ScaleCorrector::ScaleCorrector(const ScaleOptions& opt) : opt_(opt) { opt_.validate(); }

ScaleEstimate ScaleCorrector::estimate(const Frame& prev, const Frame& cur, const Eigen::Isometry3d& cur_T_prev,
	PyramidReuse* reuse, const PointCloud* prev_scan) const
{
	if (!prev.has_image || !cur.has_image || !prev.has_scan)
		failInput("scale corrector", "needs the image and scan of C(i-1) and the image of C(i)");
	if (!prev.rig.has_camera || !prev.rig.has_lidar)
		failInput("scale corrector", "the sensor rig needs a camera and a LiDAR");
	const bool have_prev = reuse && reuse->frame == prev.index && !reuse->pyramid.empty();
	LkPyramid cur_pyramid;
	const ScaleEstimate e = estimate(prev.image.asCvMatRef(), prev_scan ? *prev_scan : prev.scan, cur.image.asCvMatRef(), prev.rig.camera,
		prev.rig.camera_T_lidar(), cur_T_prev, have_prev ? &reuse->pyramid : nullptr, reuse ? &cur_pyramid : nullptr);
	if (reuse) *reuse = {cur.index, std::move(cur_pyramid)};
	return e;
}

ScaleEstimate ScaleCorrector::estimate(const cv::Mat& prev, const PointCloud& prevScan, const cv::Mat& cur,
	const PinholeCamera& cam, const Eigen::Isometry3d& camera_T_lidar, const Eigen::Isometry3d& cur_T_prev) const
{
	return estimate(prev, prevScan, cur, cam, camera_T_lidar, cur_T_prev, nullptr, nullptr);
}

ScaleEstimate ScaleCorrector::estimate(const cv::Mat& prevIn, const PointCloud& prevScan, const cv::Mat& curIn,
	const PinholeCamera& cam, const Eigen::Isometry3d& camera_T_lidar, const Eigen::Isometry3d& cur_T_prev,
	const LkPyramid* prev_pyramid, LkPyramid* cur_pyramid) const
{
	if (!cam.valid()) failInput("scale corrector", "invalid camera intrinsics");
	auto t0 = SteadyClock::now();
	ScaleEstimate e;
	auto finish = [&](Reason r) {
		e.reason = r;
		e.valid = r == Reason::Ok;
		return e;
	};
	const cv::Mat &prev = checkedGrey(prevIn, cam, "C(i-1)"), &cur = checkedGrey(curIn, cam, "C(i)");
	if (!finitePose(cur_T_prev) || !finitePose(camera_T_lidar)) return finish(Reason::BadPose);
	const size_t minN = static_cast<size_t>(opt_.min_inliers);

	// Eq. 1: project L(i-1) into C(i-1).
	const auto projected = projectScan(prevScan, cam, camera_T_lidar, opt_.min_depth, opt_.max_depth, opt_.border);
	e.counts.projected = static_cast<int>(projected.size());
	e.ms.add("project", lapMs(t0));
	if (projected.size() < minN) return finish(Reason::FewProjected);

	// Corner + gradient tests, NMS.
	const Eigen::Matrix3d K = cam.K();
	const Eigen::Vector3d epipole = K * (-(cur_T_prev.linear().transpose() * cur_T_prev.translation()));
	SelectionCounts sc;
	const auto keypoints = selectKeypoints(prev, projected, opt_, &sc, &epipole);
	e.counts.corner = sc.corner, e.counts.gradient = sc.gradient, e.counts.direction = sc.direction;
	e.counts.selected = static_cast<int>(keypoints.size());
	std::vector<cv::Point2f> pts;
	for (const auto& k : keypoints)
	{
		const DepthPixel& p = projected[k.projected];
		KeypointDiag d;
		d.scan_index = p.index, d.prev = p.px, d.cur = p.px, d.d = p.depth;
		e.keypoints.push_back(d);
		pts.push_back(p.px);
	}
	e.ms.add("select", lapMs(t0));
	if (keypoints.size() < minN) return finish(Reason::FewKeypoints);
	if (cur_T_prev.translation().squaredNorm() == 0) return finish(Reason::DegenerateMotion);

	// Lucas-Kanade into C(i).
	cv::Matx33d H = cv::Matx33d::zeros();
	if (opt_.lk_rotation_prior)
	{
		const Eigen::Matrix3d h = K * cur_T_prev.linear() * K.inverse();
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 3; ++c) H(r, c) = h(r, c);
	}
	LkPyramid built_prev, built_cur = buildLkPyramid(cur, opt_);
	if (!prev_pyramid) built_prev = buildLkPyramid(prev, opt_);
	const auto tracks = trackPoints(prev_pyramid ? *prev_pyramid : built_prev, built_cur, cur.size(), pts, opt_, H);
	if (cur_pyramid) *cur_pyramid = std::move(built_cur);
	for (size_t i = 0; i < tracks.size(); ++i)
	{
		auto& d = e.keypoints[i];
		d.cur = tracks[i].cur, d.fb_error = tracks[i].fb_error;
		if (tracks[i].status != TrackStatus::Ok) d.rejected_by = Stage::Tracking;
		else ++e.counts.tracked;
	}
	e.ms.add("track", lapMs(t0));
	if (static_cast<size_t>(e.counts.tracked) < minN) return finish(Reason::FewTracks);

	// Culling: eqs. 2-4.
	const Eigen::Matrix3d F = fundamentalMatrix(K, cur_T_prev);
	for (auto& d : e.keypoints)
	{
		if (d.rejected_by != Stage::None) continue;
		const CullResult c = cullMatch(F, d.prev, d.cur, gradientAt(cur, d.cur), opt_);
		d.normal_error = static_cast<float>(c.normal_error), d.abs_cos = static_cast<float>(c.abs_cos);
		d.rejected_by = c.rejected_by;
		e.counts.epipolar_kept += c.rejected_by != Stage::Epipolar;
		e.counts.gradient_kept += c.rejected_by == Stage::None;
	}
	e.ms.add("cull", lapMs(t0));
	if (static_cast<size_t>(e.counts.gradient_kept) < minN) return finish(Reason::FewCulled);

	// Triangulation and eq. 5.
	const Eigen::Matrix3d Kinv = K.inverse();
	std::vector<double> s;
	std::vector<size_t> owner;
	int lowParallax = 0;
	for (size_t i = 0; i < e.keypoints.size(); ++i)
	{
		auto& d = e.keypoints[i];
		if (d.rejected_by != Stage::None) continue;
		const Triangulated tr = triangulateMidpoint(Kinv, cur_T_prev, d.prev, d.cur, opt_.min_parallax_deg);
		d.parallax_deg = static_cast<float>(tr.parallax_deg);
		if (tr.status != TriangulationStatus::Ok)
		{
			lowParallax += tr.status == TriangulationStatus::LowParallax;
			d.rejected_by = Stage::Triangulation;
			continue;
		}
		d.v = static_cast<float>(tr.depth);
		d.s = d.d / d.v;
		s.push_back(static_cast<double>(d.d) / tr.depth);
		owner.push_back(i);
	}
	e.counts.triangulated = static_cast<int>(s.size());
	e.ms.add("triangulate", lapMs(t0));
	if (s.size() < minN)
		return finish(2 * lowParallax > e.counts.gradient_kept ? Reason::DegenerateMotion : Reason::FewTriangulated);

	// RANSAC, mean of the inliers.
	const RansacResult r = ransacMean(s, opt_.ransac_tolerance, opt_.ransac_iterations,
		static_cast<std::uint32_t>(opt_.ransac_seed));
	for (size_t k = 0; k < s.size(); ++k)
		if (!r.inlier[k]) e.keypoints[owner[k]].rejected_by = Stage::Ransac;
	e.counts.inliers = r.n_inliers;
	e.scale = r.mean, e.spread = r.stddev;
	e.inlier_ratio = static_cast<double>(r.n_inliers) / static_cast<double>(s.size());
	e.ms.add("ransac", lapMs(t0));
	const bool enough = static_cast<size_t>(r.n_inliers) >= minN && e.inlier_ratio >= opt_.min_inlier_ratio;
	return finish(enough ? Reason::Ok : Reason::FewInliers);
}
}  // namespace vlo::scale
