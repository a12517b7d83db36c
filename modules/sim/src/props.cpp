#include <vlo/sim/props.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/shapes.h>

#include <cmath>

namespace vlo::sim
{
namespace
{
Eigen::Isometry3d raised(const Eigen::Isometry3d& f, double x, double y, double z)
{
	Eigen::Isometry3d r = f;
	r.translate(Eigen::Vector3d(x, y, z));
	return r;
}
}  // namespace

void addBuilding(World& w, const Eigen::Isometry3d& frame, double length, double depth, double height, int facade_tex,
	int roof_tex, double u_offset)
{
	addBox(w, raised(frame, 0, 0, -0.5), length, depth, height + 0.5, facade_tex, roof_tex, u_offset, -0.5);
}

void addCar(World& w, const Eigen::Isometry3d& frame, int body_tex, int cabin_tex)
{
	addBox(w, raised(frame, 0, 0, 0.15), 4.5, 1.8, 0.85, body_tex, body_tex);
	addBox(w, raised(frame, -0.25, 0, 1.0), 2.6, 1.6, 0.5, cabin_tex, body_tex);
}

void addPole(World& w, const Eigen::Isometry3d& frame, double height, int pole_tex, int sign_tex)
{
	addPrism(w, frame, 0.09, height, 16, pole_tex);
	// Lamp arm over the road (towards -y) and the lamp head.
	addBox(w, raised(frame, 0, -0.7, height - 0.1), 0.08, 1.4, 0.08, pole_tex, pole_tex);
	addBox(w, raised(frame, 0, -1.3, height - 0.25), 0.35, 0.5, 0.15, pole_tex, pole_tex);
	if (sign_tex >= 0)
		addBox(w, raised(frame, 0, -0.08, 2.2), 0.8, 0.04, 0.8, sign_tex, pole_tex);
}

void addTree(World& w, const Eigen::Vector3d& base, double size, int bark_tex, int foliage_tex, Rng& rng)
{
	Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
	f.translation() = base - Eigen::Vector3d(0, 0, 0.3);
	f.rotate(Eigen::AngleAxisd(rng.uniform(0, M_PI), Eigen::Vector3d::UnitZ()));
	const double trunk = size * rng.uniform(2.2, 3.5), r = size * rng.uniform(0.12, 0.22);
	addPrism(w, f, r, trunk + 0.3 + size, 24, bark_tex);
	const double R = size * rng.uniform(1.5, 2.6);
	const Eigen::Vector3d c = base + Eigen::Vector3d(0, 0, trunk + R * 0.8);
	addBlob(w, c, Eigen::Vector3d(R, R * rng.uniform(0.8, 1.0), R * rng.uniform(0.75, 1.0)), 0.22, foliage_tex, rng);
	if (rng.chance(0.5))  // a second lobe makes the crown irregular
	{
		const double a = rng.uniform(0, 2 * M_PI), R2 = R * rng.uniform(0.5, 0.8);
		const Eigen::Vector3d c2 = c + Eigen::Vector3d(std::cos(a), std::sin(a), rng.uniform(-0.2, 0.5)) * R * 0.6;
		addBlob(w, c2, Eigen::Vector3d(R2, R2, R2 * 0.9), 0.25, foliage_tex, rng);
	}
}

void addWall(World& w, const Eigen::Isometry3d& frame, double length, double height, double thickness, int tex)
{
	addBox(w, raised(frame, 0, 0, -0.4), length, thickness, height + 0.4, tex, tex, 0, -0.4);
}
}  // namespace vlo::sim
