#include <vlo/loop/scan_context.h>

#include <cmath>

namespace vlo::loop
{
ScanContext makeScanContext(const std::vector<Eigen::Vector3f>& points, const ScanContextParams& params, double viewpoint_y)
{
	ScanContext sc = ScanContext::Zero(params.rings, params.sectors);
	const double ring_width = params.range / params.rings, sector_width = 2 * M_PI / params.sectors;
	for (const auto& p : points)
	{
		const double y = double(p.y()) - viewpoint_y;
		const double r = std::hypot(double(p.x()), y);
		if (!(r < params.range)) continue;
		const int ring = std::min(params.rings - 1, static_cast<int>(r / ring_width));
		const double azimuth = std::atan2(y, double(p.x())) + M_PI;  // [0, 2pi]
		const int sector = std::min(params.sectors - 1, static_cast<int>(azimuth / sector_width));
		// Empty bins are 0: points below the ground (height < -sensor_height) leave them empty.
		sc(ring, sector) = std::max(sc(ring, sector), double(p.z()) + params.sensor_height);
	}
	return sc;
}

Eigen::VectorXd ringKey(const ScanContext& sc) { return sc.rowwise().mean(); }

DescriptorMatch compareScanContexts(const ScanContext& query, const ScanContext& candidate)
{
	DescriptorMatch best;
	const int sectors = static_cast<int>(query.cols());
	if (candidate.cols() != sectors || candidate.rows() != query.rows()) return best;
	const Eigen::RowVectorXd qn = query.colwise().norm(), cn = candidate.colwise().norm();
	for (int shift = 0; shift < sectors; ++shift)
	{
		double sum = 0;
		int columns = 0;
		for (int j = 0; j < sectors; ++j)
		{
			const int k = (j + shift) % sectors;
			if (qn(j) == 0 || cn(k) == 0) continue;
			sum += 1.0 - query.col(j).dot(candidate.col(k)) / (qn(j) * cn(k));
			++columns;
		}
		if (columns == 0) continue;
		const double d = sum / columns;
		if (d < best.distance)
		{
			best.distance = d;
			best.shift = shift;
		}
	}
	// Query column j lies at the azimuth of candidate column j + shift: the query frame is turned by
	// shift sectors in the candidate's.
	best.yaw = std::remainder(best.shift * 2 * M_PI / sectors, 2 * M_PI);
	return best;
}
}  // namespace vlo::loop
