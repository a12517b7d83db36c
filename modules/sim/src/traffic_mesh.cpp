#include "traffic_mesh.h"

#include <vlo/sim/rng.h>
#include <vlo/sim/shapes.h>
#include <vlo/sim/textures.h>

#include <opencv2/core.hpp>

#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kSideShade = 0.8;  // the vehicles' sides are darker than their tops, whatever their heading

uint8_t meanGray(const Texture& t)
{
	const cv::Mat m = t.image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	return static_cast<uint8_t>(std::lround(cv::mean(m)[0]));
}
}  // namespace

TrafficMesh::TrafficMesh(uint64_t seed)
{
	using namespace vehicle_tex;
	Rng rng = Rng::stream(seed, "traffic textures");
	std::vector<Texture> slots(kCount);
	for (int p = 0; p < kPaints; ++p)
	{
		const Texture body = carBodyTexture(rng.next());
		slots[bodySide(p)] = darkened(body, kSideShade), slots[bodyTop(p)] = body;
	}
	slots[kCabinSide] = darkened(carCabinTexture(rng.next()), kSideShade);
	slots[kCargoSide] = darkened(muralTexture(rng.next()), kSideShade);  // posters and lettering: features
	slots[kCargoTop] = roofTexture(rng.next());
	for (Texture& t : slots)
	{
		gray_.push_back(meanGray(t));
		mesh_.addTexture(std::move(t), false);  // shading is in the textures, fixed to the vehicle
	}
	gl_ = mesh_.makeOpenGL(true);
}

void TrafficMesh::update(const Traffic& traffic, double t)
{
	mesh_.clearTriangles();
	for (std::size_t i = 0; i < traffic.vehicles().size(); ++i)
	{
		if (!traffic.present(i, t)) continue;
		const Eigen::Isometry3d pose = traffic.pose(i, t);
		for (const VehiclePart& p : traffic.vehicles()[i].parts)
		{
			Eigen::Isometry3d f = pose;
			f.translate(Eigen::Vector3d(p.x, 0, p.z0));
			addBox(mesh_, f, p.sx, p.sy, p.sz, p.side_tex, p.top_tex);
		}
	}
	mesh_.updateOpenGL(*gl_);
}
}  // namespace vlo::sim
