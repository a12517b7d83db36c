// Ground textures: road, sidewalk, curb, grass, gravel.
#include "texture_canvas.h"

#include <vlo/sim/rng.h>
#include <vlo/sim/textures.h>

#include <cmath>

namespace vlo::sim
{
namespace
{
Texture finish(const TextureCanvas& c, double w, double h) { return {c.toImage(), w, h}; }
}  // namespace

Texture roadTexture(const RoadMarkings& m, uint64_t seed)
{
	const double len = 24.0, wid = 2 * m.half_width;
	TextureCanvas c(2048, 512, 88);
	const double pu = c.width() / len, pv = c.height() / wid;  // pixels per metre
	Rng rng = Rng::stream(seed, "road texture");
	c.addNoise(seed, 6, 14, 3);  // large tone variation
	c.addNoise(seed + 1, 96, 9, 2);  // grain
	// Repairs and stains: patches with a different tone give corners on the road.
	for (int i = 0; i < 10; ++i)
	{
		const int x = rng.integer(0, c.width()), y = rng.integer(0, c.height());
		const int w = rng.integer(40, 260), h = rng.integer(20, 120);
		c.shade(x, y, x + w, y + h, static_cast<float>(rng.uniform(-22, 18)));
	}
	for (int i = 0; i < 14; ++i)  // cracks: dark random walks
	{
		double x = rng.uniform(0, c.width()), y = rng.uniform(0, c.height()), a = rng.uniform(0, 2 * M_PI);
		for (int k = 0; k < 30; ++k)
		{
			const double nx = x + 6 * std::cos(a), ny = y + 6 * std::sin(a);
			c.line(x, y, nx, ny, 1.6, 45, 0.8f);
			x = nx, y = ny, a += rng.uniform(-0.6, 0.6);
		}
	}
	auto paint = [&](double u0, double u1, double vm, double halfw) {
		c.rect(int(u0 * pu), int((vm - halfw) * pv), int(u1 * pu), int((vm + halfw) * pv), 205, 0.9f);
	};
	const double mid = m.half_width;
	if (m.center_line)
		for (double u = 0; u < len; u += 8.0) paint(u, u + 3.0, mid, 0.07);
	paint(0, len, mid - m.lane, 0.07);  // lane edges
	paint(0, len, mid + m.lane, 0.07);
	if (m.parking_bays)
		for (double u = 1; u < len; u += 6.0)
			for (double side : {-1.0, 1.0})
			{
				const double v0 = mid + side * m.lane, v1 = mid + side * m.half_width;
				c.rect(int(u * pu), int(std::min(v0, v1) * pv), int((u + 0.12) * pu), int(std::max(v0, v1) * pv), 200, 0.85f);
			}
	const double mu = rng.uniform(2, len - 2);  // one manhole per repeat
	c.ellipse(mu * pu, (mid - m.lane / 2) * pv, 0.35 * pu, 0.35 * pv, 60);
	c.ellipse(mu * pu, (mid - m.lane / 2) * pv, 0.28 * pu, 0.28 * pv, 105);
	c.addNoise(seed + 2, 128, 5, 1);  // wear over the paint
	return finish(c, len, wid);
}

Texture sidewalkTexture(uint64_t seed)
{
	TextureCanvas c(512, 512, 150);
	Rng rng = Rng::stream(seed, "sidewalk texture");
	const int slab = 512 / 6;  // 0.5 m slabs
	for (int j = 0; j < 6; ++j)
		for (int i = 0; i < 6; ++i)
			c.rect(i * slab, j * slab, (i + 1) * slab, (j + 1) * slab, static_cast<float>(rng.uniform(125, 180)));
	c.addNoise(seed, 8, 10, 3);
	for (int k = 0; k <= 6; ++k)
	{
		c.rect(k * slab - 2, 0, k * slab + 2, 512, 80, 0.8f);
		c.rect(0, k * slab - 2, 512, k * slab + 2, 80, 0.8f);
	}
	for (int i = 0; i < 8; ++i)  // stains
		c.ellipse(rng.uniform(0, 512), rng.uniform(0, 512), rng.uniform(8, 40), rng.uniform(8, 40),
			static_cast<float>(rng.uniform(90, 120)), 0.5f);
	return finish(c, 3.0, 3.0);
}

Texture curbTexture(uint64_t seed)
{
	TextureCanvas c(512, 32, 175);
	c.addNoise(seed, 16, 14, 3);
	for (int x = 0; x < 512; x += 64) c.rect(x, 0, x + 3, 32, 90, 0.8f);  // 1 m stones
	return finish(c, 8.0, 0.5);
}

Texture grassTexture(uint64_t seed, float base)
{
	TextureCanvas c(512, 512, base);
	Rng rng = Rng::stream(seed, "grass texture");
	c.addNoise(seed, 4, 25, 2);
	c.addNoise(seed + 7, 64, 14, 2);
	c.speckle(rng, 600, 2.5, base - 35, 20);  // tufts and stones
	c.speckle(rng, 300, 2.0, base + 40, 20);
	return finish(c, 8.0, 8.0);
}

Texture gravelTexture(uint64_t seed)
{
	TextureCanvas c(256, 256, 120);
	Rng rng = Rng::stream(seed, "gravel texture");
	c.addNoise(seed, 8, 15, 3);
	c.speckle(rng, 500, 2.0, 120, 50);
	return finish(c, 2.0, 2.0);
}
}  // namespace vlo::sim
