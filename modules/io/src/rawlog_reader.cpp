#include "observation_stream.h"

#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/io/frame_observations.h>
#include <vlo/io/frame_pairing.h>
#include <vlo/io/lidar_observations.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/rawlog_writer.h>

#include <mrpt/system/datetime.h>

#include <optional>
#include <sstream>

namespace vlo::io
{
using namespace mrpt::obs;

namespace
{
std::string secs(double t)
{
	std::ostringstream s;
	s.precision(6);
	s << std::fixed << t << " s";
	return s.str();
}

/// A sensor pose as stored, or InputError: a corrupt one (NaN, a matrix that is no rotation) would
/// silently bend every point or pixel of the run.
Eigen::Isometry3d sensorPose(const mrpt::poses::CPose3D& pose, const std::string& where)
{
	const Eigen::Isometry3d T = toIsometry(pose);
	const Eigen::Matrix3d R = T.linear();
	if (!T.matrix().allFinite() || (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-6 || R.determinant() <= 0)
		failInput(where, "sensor pose is not a rigid transform (not finite, or its rotation is not orthonormal)");
	return T;
}
}  // namespace

struct RawlogReader::Impl
{
	std::string path, images_dir;
	RawlogReaderOptions opt;
	ObservationStream in;
	RawlogStats stats;
	std::deque<double> img_t, scan_t;  // times of the queued observations (for pairStep)
	std::deque<CObservationImage::Ptr> imgs;
	std::deque<CObservation::Ptr> scans;
	std::optional<double> last_img_t, last_scan_t;
	bool eof = false;
	int first_w = -1, first_h = -1;
	SensorRig rig;  // latest known placement of each sensor
	std::optional<Eigen::Isometry3d> vehicle_T_camera0;  // from the rawlog's note, if any

	Impl(const std::string& p, RawlogReaderOptions o)
		: path(p), images_dir(rawlogImagesDir(p)), opt(std::move(o)), in(p)
	{
	}

	double timeOf(const CObservation& obs, std::optional<double>& last)
	{
		if (obs.timestamp == INVALID_TIMESTAMP) failInput(path, "'" + obs.sensorLabel + "' observation without timestamp");
		const double t = toSeconds(obs.timestamp);
		if (last && t <= *last)
			failInput(path, "timestamps out of order: '" + obs.sensorLabel + "' observation at t=" + secs(t) + " follows one at t=" + secs(*last));
		last = t;
		return t;
	}

	void readOne()
	{
		const auto obs = in.next();
		if (!obs)
		{
			eof = true;
			return;
		}
		++stats.observations;
		if (const auto note = std::dynamic_pointer_cast<CObservationComment>(obs); note && isCamera0Note(*note))
		{
			vehicle_T_camera0 = camera0FromNote(*note, path + ": the note of KITTI's camera 0");
			return;  // no sensor's
		}
		++stats.labels[obs->sensorLabel];
		const std::string cls = obs->GetRuntimeClass()->className;
		if (obs->sensorLabel == opt.camera_label)
		{
			auto img = std::dynamic_pointer_cast<CObservationImage>(obs);
			if (!img) failInput(path, "'" + opt.camera_label + "' observation is a " + cls + ", expected CObservationImage");
			img_t.push_back(timeOf(*img, last_img_t));
			imgs.push_back(img);
		}
		else if (obs->sensorLabel == opt.lidar_label)
		{
			if (!isScanObservation(*obs))
				failInput(path,
					"'" + opt.lidar_label + "' observation is a " + cls +
						", expected CObservationPointCloud or CObservationVelodyneScan");
			scan_t.push_back(timeOf(*obs, last_scan_t));
			scans.push_back(obs);
		}
		else
			++stats.other_labels;
	}

	void takeImage(Frame& f)
	{
		const auto obs = imgs.front();
		const double t = img_t.front();
		imgs.pop_front();
		img_t.pop_front();
		mrpt::img::CImage img;
		if (obs->image.isExternallyStored())
		{
			// Resolved here rather than through CImage's global path base, so readers of different
			// rawlogs do not interfere.
			std::string file = obs->image.getExternalStorageFile();
			if (file.empty() || file[0] != '/') file = images_dir + "/" + file;
			if (!img.loadFromFile(file, 0)) failInput(file, "cannot read image referenced by " + path);
		}
		else
			img = toGray(obs->image);
		const std::string where = path + ": '" + opt.camera_label + "' at t=" + secs(t);
		const PinholeCamera cam = fromTCamera(obs->cameraParams, where);
		const int w = static_cast<int>(img.getWidth()), h = static_cast<int>(img.getHeight());
		const std::string size = std::to_string(w) + "x" + std::to_string(h);
		if (w != cam.width || h != cam.height)
			failInput(path,
				"image at t=" + secs(t) + " is " + size + " but its cameraParams say " +
					std::to_string(cam.width) + "x" + std::to_string(cam.height));
		if (first_w < 0)
			first_w = w, first_h = h;
		else if (w != first_w || h != first_h)
			failInput(path,
				"image at t=" + secs(t) + " is " + size + " but the first image was " +
					std::to_string(first_w) + "x" + std::to_string(first_h));
		rig.has_camera = true;
		rig.camera = cam;
		rig.vehicle_T_camera = sensorPose(obs->cameraPose, where);
		f.t = t;
		f.image = img;
		f.has_image = true;
	}

	void takeScan(Frame& f)
	{
		const auto obs = scans.front();
		const double t = scan_t.front();
		scans.pop_front();
		scan_t.pop_front();
		const std::string where = path + ": '" + opt.lidar_label + "' at t=" + secs(t);
		ScanReading scan = readScanObservation(*obs, where);
		stats.invalid_points += scan.dropped;
		stats.default_calibrations += scan.default_calibration;
		if (!f.has_image) f.t = t;
		if (scan.points.has_time && t != f.t)  // point times are relative to the frame's time
			for (auto& p : scan.points) p.time += static_cast<float>(t - f.t);
		f.scan = std::move(scan.points);
		mrpt::poses::CPose3D sensor_pose;
		obs->getSensorPose(sensor_pose);
		rig.has_lidar = true;
		rig.vehicle_T_lidar = sensorPose(sensor_pose, where);
		f.has_scan = true;
	}

	std::string labelsSeen() const
	{
		std::string s;
		for (const auto& [label, n] : stats.labels) s += (s.empty() ? "" : ", ") + ("'" + label + "' x" + std::to_string(n));
		return s.empty() ? "none" : s;
	}

	void finalChecks()
	{
		for (const auto& [need, label] : {std::pair{opt.need_camera, opt.camera_label}, {opt.need_lidar, opt.lidar_label}})
			if (need && !stats.labels.count(label))
				failInput(path, "no observations labelled '" + label + "' (labels seen: " + labelsSeen() + ")");
		if (stats.frames == 0)
			failInput(path,
				"no frames: " + std::to_string(stats.unpaired_images) + " images and " +
					std::to_string(stats.unpaired_scans) + " scans, none within " + secs(opt.max_time_diff) +
					" of a partner");
	}
};

RawlogReader::RawlogReader(const std::string& path, RawlogReaderOptions options)
	: impl_(std::make_unique<Impl>(path, std::move(options)))
{
}

RawlogReader::~RawlogReader() = default;

bool RawlogReader::next(Frame& frame)
{
	auto& d = *impl_;
	for (;;)
	{
		PairStep step = pairStep(d.img_t, d.scan_t, d.opt.max_time_diff, d.eof);
		if (step == PairStep::NeedMore)
		{
			if (d.img_t.size() <= d.opt.max_pending && d.scan_t.size() <= d.opt.max_pending)
			{
				d.readOne();
				continue;
			}
			step = pairStep(d.img_t, d.scan_t, d.opt.max_time_diff, true);  // give up waiting
		}
		if (step == PairStep::Done)
		{
			d.finalChecks();
			return false;
		}
		if (step == PairStep::SkipImage && d.opt.need_lidar)
		{
			d.imgs.pop_front(), d.img_t.pop_front();
			++d.stats.unpaired_images;
			continue;
		}
		if (step == PairStep::SkipScan && d.opt.need_camera)
		{
			d.scans.pop_front(), d.scan_t.pop_front();
			++d.stats.unpaired_scans;
			continue;
		}
		frame = Frame{};
		frame.index = d.stats.frames++;
		if (step != PairStep::SkipScan) d.takeImage(frame);
		if (step != PairStep::SkipImage) d.takeScan(frame);
		frame.rig = d.rig;
		return true;
	}
}

const RawlogStats& RawlogReader::stats() const { return impl_->stats; }

const std::optional<Eigen::Isometry3d>& RawlogReader::vehicleTCamera0() const { return impl_->vehicle_T_camera0; }

double RawlogReader::progress() const { return impl_->in.progress(); }

std::string RawlogReader::statsSummary() const
{
	const auto& s = impl_->stats;
	std::ostringstream o;
	o << s.frames << " frames from " << s.observations << " observations; " << s.unpaired_images << " images and "
	  << s.unpaired_scans << " scans without partner; " << s.other_labels << " with other labels; "
	  << s.invalid_points << " invalid points dropped";
	if (s.default_calibrations > 0) o << "; " << s.default_calibrations << " Velodyne scans decoded with the model's default calibration";
	return o.str();
}
}  // namespace vlo::io
