#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/io/frame_observations.h>
#include <vlo/io/lidar_observations.h>

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/VelodyneCalibration.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

namespace vlo::io
{
using namespace mrpt::obs;

namespace
{
bool finite3(float x, float y, float z) { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }

CObservation::Ptr toPointCloudObservation(const Frame& frame)
{
	auto obs = CObservationPointCloud::Create();
	auto map = mrpt::maps::CPointsMapXYZI::Create();
	map->reserve(frame.scan.size());
	for (const auto& p : frame.scan) map->insertPointRGB(p.x, p.y, p.z, p.intensity, 0, 0);
	obs->pointcloud = map;
	obs->sensorPose = toCPose3D(frame.rig.vehicle_T_lidar);
	return obs;
}

CObservation::Ptr toVelodyneObservation(const Frame& frame)
{
	auto obs = CObservationVelodyneScan::Create();
	auto& pc = obs->point_cloud;
	const auto& scan = frame.scan;
	pc.reserve(scan.size());
	const auto t0 = toTimestamp(frame.t);
	for (const auto& p : scan)
	{
		pc.x.push_back(p.x), pc.y.push_back(p.y), pc.z.push_back(p.z);
		pc.intensity.push_back(static_cast<uint8_t>(std::clamp(std::lround(p.intensity), 0L, 255L)));
		if (scan.has_time) pc.timestamp.push_back(t0 + mrpt::Clock::duration(std::llround(p.time * 1e7)));  // 100 ns ticks
		if (scan.has_ring) pc.laser_id.push_back(static_cast<int16_t>(p.ring));
	}
	obs->sensorPose = toCPose3D(frame.rig.vehicle_T_lidar);
	return obs;
}

// Velodyne models by the product id in their data packets, with their default calibration's name.
struct VelodyneModel
{
	const char* calibration;
	std::size_t lasers;
};
std::optional<VelodyneModel> modelOf(const CObservationVelodyneScan& obs)
{
	switch (obs.scan_packets.front().velodyne_model_ID)
	{
		case 0x21: return VelodyneModel{"HDL32", 32};
		case 0x22: return VelodyneModel{"VLP16", 16};
		default: return std::nullopt;
	}
}

/// The calibration the observation carries, unless it is missing or contradicts the packets' model
/// (MRPT 2.5.8's rawlog-grabber stores VLP-16's for HDL-32 captures): then the model's default.
void chooseCalibration(CObservationVelodyneScan& obs, const std::string& where, ScanReading& r)
{
	const auto model = modelOf(obs);
	const std::size_t carried = obs.calibration.laser_corrections.size();
	if (carried > 0 && (!model || carried == model->lasers)) return;
	if (!model)
		failInput(where,
			"Velodyne scan without calibration and of unknown model (packet product id " +
				std::to_string(obs.scan_packets.front().velodyne_model_ID) +
				"; known: 0x21 HDL-32E, 0x22 VLP-16): record it with its calibration");
	obs.calibration = VelodyneCalibration::LoadDefaultCalibration(model->calibration);
	r.default_calibration = true;
}

ScanReading fromVelodyne(CObservationVelodyneScan& obs, const std::string& where)
{
	ScanReading r;
	if (obs.point_cloud.size() == 0 && !obs.scan_packets.empty())
	{
		chooseCalibration(obs, where, r);
		CObservationVelodyneScan::TGeneratePointCloudParameters params;
		params.generatePerPointTimestamp = true;
		params.minDistance = static_cast<float>(obs.minRange);
		obs.generatePointCloud(params);
	}
	const auto& pc = obs.point_cloud;
	const std::size_t n = pc.size();
	if (pc.y.size() != n || pc.z.size() != n || (!pc.intensity.empty() && pc.intensity.size() != n))
		failInput(where, "CObservationVelodyneScan with point fields of different lengths");
	r.points.has_time = pc.timestamp.size() == n && n > 0;
	r.points.has_ring = pc.laser_id.size() == n && n > 0;
	r.points.reserve(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		if (!finite3(pc.x[i], pc.y[i], pc.z[i]))
		{
			++r.dropped;
			continue;
		}
		LidarPoint p;
		p.x = pc.x[i], p.y = pc.y[i], p.z = pc.z[i];
		p.intensity = pc.intensity.empty() ? 0.0f : pc.intensity[i];
		if (r.points.has_time) p.time = static_cast<float>(mrpt::system::timeDifference(obs.timestamp, pc.timestamp[i]));
		if (r.points.has_ring)
		{
			if (pc.laser_id[i] < 0) failInput(where, "CObservationVelodyneScan with a negative laser id");
			p.ring = static_cast<std::uint16_t>(pc.laser_id[i]);
		}
		r.points.push_back(p);
	}
	if (r.points.has_ring && !obs.calibration.empty())
	{
		// Laser ids are firing order: the calibration's vertical angles give each one's ring.
		const auto& lasers = obs.calibration.laser_corrections;
		std::vector<std::uint16_t> ring_of(lasers.size());
		std::vector<std::size_t> ids(lasers.size());
		std::iota(ids.begin(), ids.end(), 0);
		std::stable_sort(ids.begin(), ids.end(),
			[&](auto a, auto b) { return lasers[a].verticalCorrection < lasers[b].verticalCorrection; });
		for (std::size_t k = 0; k < ids.size(); ++k) ring_of[ids[k]] = static_cast<std::uint16_t>(k);
		for (auto& p : r.points)
		{
			if (p.ring >= ring_of.size()) failInput(where, "CObservationVelodyneScan with a laser id beyond its calibration");
			p.ring = ring_of[p.ring];
		}
	}
	if (r.points.has_ring) orderRingsByElevation(r.points);
	return r;
}

ScanReading fromPointsMap(const mrpt::maps::CPointsMap& map)
{
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto* xyzi = dynamic_cast<const mrpt::maps::CPointsMapXYZI*>(&map);
	ScanReading r;
	r.points.reserve(xs.size());
	for (std::size_t i = 0; i < xs.size(); ++i)
	{
		if (!finite3(xs[i], ys[i], zs[i]))
		{
			++r.dropped;
			continue;
		}
		const float in = xyzi ? xyzi->getPointIntensity_fast(i) : 0.0f;
		LidarPoint p;
		p.x = xs[i], p.y = ys[i], p.z = zs[i], p.intensity = std::isfinite(in) ? in : 0.0f;
		r.points.push_back(p);
	}
	return r;
}
}  // namespace

CObservation::Ptr toScanObservation(const Frame& frame, const std::string& label)
{
	auto obs = frame.scan.has_time || frame.scan.has_ring ? toVelodyneObservation(frame) : toPointCloudObservation(frame);
	obs->sensorLabel = label;
	obs->timestamp = toTimestamp(frame.t);
	return obs;
}

bool isScanObservation(const CObservation& obs)
{
	return dynamic_cast<const CObservationVelodyneScan*>(&obs) || dynamic_cast<const CObservationPointCloud*>(&obs);
}

ScanReading readScanObservation(CObservation& obs, const std::string& where)
{
	if (auto* velodyne = dynamic_cast<CObservationVelodyneScan*>(&obs)) return fromVelodyne(*velodyne, where);
	if (auto* pc = dynamic_cast<CObservationPointCloud*>(&obs))
	{
		pc->load();  // no-op unless the cloud is stored externally
		if (!pc->pointcloud) failInput(where, "CObservationPointCloud without a point cloud");
		return fromPointsMap(*pc->pointcloud);
	}
	failInput(where,
		std::string("LiDAR observation is a ") + obs.GetRuntimeClass()->className +
			", which vlo does not read (CObservationPointCloud or CObservationVelodyneScan)");
}

void orderRingsByElevation(PointCloud& cloud)
{
	// Per ring id: sum of elevations and count, in flat arrays indexed by id (a map lookup per
	// point was most of the reader's own time on a 120 000-point HDL-64 scan).
	std::uint16_t max_id = 0;
	for (const auto& p : cloud) max_id = std::max(max_id, p.ring);
	std::vector<double> sum(max_id + 1u, 0.0);
	std::vector<std::size_t> count(max_id + 1u, 0);
	for (const auto& p : cloud)
	{
		sum[p.ring] += std::atan2(p.z, std::hypot(p.x, p.y));
		++count[p.ring];
	}
	std::vector<std::uint16_t> ids;  // the ids present, increasing
	std::vector<double> mean;  // by increasing id
	for (std::size_t id = 0; id <= max_id; ++id)
		if (count[id] > 0)
		{
			ids.push_back(static_cast<std::uint16_t>(id));
			mean.push_back(sum[id] / double(count[id]));
		}
	if (std::is_sorted(mean.begin(), mean.end())) return;  // already 0 = lowest (gaps kept)
	if (std::is_sorted(mean.rbegin(), mean.rend()))  // top-down numbering (Ouster): flip, gaps kept
	{
		const std::uint16_t top = ids.back();
		for (auto& p : cloud) p.ring = static_cast<std::uint16_t>(top - p.ring);
		return;
	}
	std::vector<std::pair<double, std::uint16_t>> order;  // interleaved ids: rank by elevation
	for (std::size_t i = 0; i < ids.size(); ++i) order.push_back({mean[i], ids[i]});
	std::sort(order.begin(), order.end());
	std::vector<std::uint16_t> renumber(max_id + 1u, 0);
	for (std::size_t i = 0; i < order.size(); ++i) renumber[order[i].second] = static_cast<std::uint16_t>(i);
	for (auto& p : cloud) p.ring = renumber[p.ring];
}
}  // namespace vlo::io
