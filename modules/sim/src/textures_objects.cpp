// Textures of objects: facades, cars, trees, poles, signs, walls, corridor murals.
#include "texture_canvas.h"

#include <vlo/sim/rng.h>
#include <vlo/sim/textures.h>

#include <cmath>

namespace vlo::sim
{
Texture facadeTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "facade texture");
	const double W = 16, H = 24, pm = 64;  // 64 px per metre
	const float wall = static_cast<float>(rng.uniform(110, 205));
	TextureCanvas c(int(W * pm), int(H * pm), wall);
	c.addNoise(seed, 4, 16, 4);
	const int cols = rng.integer(5, 7);
	const double floorH = rng.uniform(3.0, 3.6), winW = rng.uniform(0.9, 1.5), winH = rng.uniform(1.2, 1.8);
	const double colW = W / cols;  // divides the width: the facade tiles
	const bool bars = rng.chance(0.6);
	const float glass = static_cast<float>(rng.uniform(35, 75));
	// Ground floor: shop windows and doors; the image's row 0 is the texture's v = 0 (street level).
	for (int i = 0; i < cols; ++i)
	{
		const double x0 = i * colW + 0.25, x1 = (i + 1) * colW - 0.25;
		if (rng.chance(0.3))
			c.rect(int((x0 + 0.5) * pm), int(0.0 * pm), int((x0 + 1.6) * pm), int(2.3 * pm), 55);  // door
		else
			c.rect(int(x0 * pm), int(0.5 * pm), int(x1 * pm), int(2.6 * pm), glass + 10);
	}
	c.rect(0, int(3.0 * pm), c.width(), int(3.25 * pm), wall - 45);  // cornice
	for (double y = floorH + 0.9; y + winH < H; y += floorH)
		for (int i = 0; i < cols; ++i)
		{
			const double x0 = (i + 0.5) * colW - winW / 2;
			const int px0 = int(x0 * pm), py0 = int(y * pm), px1 = int((x0 + winW) * pm), py1 = int((y + winH) * pm);
			c.rect(px0 - 5, py0 - 5, px1 + 5, py1 + 5, wall + 30);  // frame
			const float g = glass + static_cast<float>(rng.uniform(-20, 40));
			c.rect(px0, py0, px1, py1, g);
			if (rng.chance(0.35))  // blinds half down
				c.rect(px0, py0 + int((py1 - py0) * rng.uniform(0.3, 0.8)), px1, py1, g + 80, 0.9f);
			if (bars)
			{
				c.rect((px0 + px1) / 2 - 3, py0, (px0 + px1) / 2 + 3, py1, wall + 20);
				c.rect(px0, py0 + (py1 - py0) / 3 - 3, px1, py0 + (py1 - py0) / 3 + 3, wall + 20);
			}
			c.rect(px0 - 10, py0 - 14, px1 + 10, py0 - 5, wall - 40);  // sill (image rows grow upwards here)
		}
	c.addNoise(seed + 3, 64, 8, 2);
	return {c.toImage(), W, H};
}

Texture roofTexture(uint64_t seed)
{
	TextureCanvas c(256, 256, 90);
	c.addNoise(seed, 4, 20, 4);
	return {c.toImage(), 8, 8};
}

Texture carBodyTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "car body texture");
	const float body = static_cast<float>(rng.uniform(40, 210));
	TextureCanvas c(512, 96, body);  // 4.5 m x 0.85 m; v = 0 at the bottom of the body
	c.addNoise(seed, 8, 8, 2);
	const double pm = 512 / 4.5;
	for (double x : {0.85, 3.55})  // wheels (centre 0.3 m above the body's bottom edge)
	{
		c.ellipse(x * pm, 0.3 * 96 / 0.85, 0.36 * pm, 0.3 * 96 / 0.85, 25);
		c.ellipse(x * pm, 0.3 * 96 / 0.85, 0.16 * pm, 0.14 * 96 / 0.85, 140);
	}
	c.rect(0, 55, 512, 58, body - 50);  // door line and handles
	c.rect(int(1.6 * pm), 20, int(1.62 * pm), 80, body - 50);
	c.rect(int(2.7 * pm), 20, int(2.72 * pm), 80, body - 50);
	c.rect(int(2.0 * pm), 60, int(2.2 * pm), 64, 230);
	c.rect(0, 70, 24, 88, 230);  // lights at both ends
	c.rect(488, 70, 512, 88, 60);
	return {c.toImage(), 4.5, 0.85};
}

Texture carCabinTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "car cabin texture");
	const float body = static_cast<float>(rng.uniform(40, 210));
	TextureCanvas c(512, 64, body);  // 4.5 m x 0.55 m
	const double pm = 512 / 4.5;
	c.rect(int(0.15 * pm), 6, int(4.35 * pm), 54, 45);
	c.addNoise(seed, 16, 18, 2);  // reflections
	for (double x : {0.15, 1.55, 2.9, 4.3}) c.rect(int(x * pm), 0, int(x * pm) + 10, 64, body);  // pillars
	return {c.toImage(), 4.5, 0.55};
}

Texture barkTexture(uint64_t seed)
{
	TextureCanvas c(128, 512, 75);
	Rng rng = Rng::stream(seed, "bark texture");
	c.addNoise(seed, 3, 20, 3);
	for (int i = 0; i < 60; ++i)
	{
		const double x = rng.uniform(0, 128), y = rng.uniform(0, 512);
		c.line(x, y, x + rng.uniform(-3, 3), y + rng.uniform(20, 60), 2.5, static_cast<float>(rng.uniform(30, 130)), 0.8f);
	}
	return {c.toImage(), 1.0, 4.0};
}

Texture foliageTexture(uint64_t seed)
{
	TextureCanvas c(512, 512, 95);
	Rng rng = Rng::stream(seed, "foliage texture");
	c.addNoise(seed, 4, 25, 2);
	for (int i = 0; i < 2500; ++i)  // leaves and gaps: 3-8 cm blobs, light on top of dark
	{
		const double r = rng.uniform(2, 5), a = rng.uniform(0, M_PI);
		const double x = rng.uniform(0, 512), y = rng.uniform(0, 512);
		c.line(x, y, x + r * std::cos(a), y + r * std::sin(a), r, static_cast<float>(rng.uniform(40, 170)), 0.9f);
	}
	return {c.toImage(), 4.0, 4.0};
}

Texture poleTexture(uint64_t seed)
{
	TextureCanvas c(32, 512, 130);
	c.addNoise(seed, 2, 25, 3);
	c.rect(0, 0, 32, 40, 60);  // dark foot
	for (int y = 140; y < 512; y += 96) c.rect(0, y, 32, y + 6, 190);  // bands
	return {c.toImage(), 0.5, 8.0};
}

Texture signTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "sign texture");
	TextureCanvas c(128, 128, 235);
	c.ellipse(64, 64, 60, 60, 50);
	c.ellipse(64, 64, 46, 46, 235);
	c.rect(34, 54, 94, 74, static_cast<float>(rng.uniform(20, 80)));
	return {c.toImage(), 0.8, 0.8};
}

Texture gardenWallTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "wall texture");
	TextureCanvas c(512, 256, 95);  // mortar
	for (int row = 0; row < 8; ++row)  // irregular stone courses, 0.25 m
	{
		int x = -rng.integer(0, 60);
		while (x < 512)
		{
			const int w = rng.integer(35, 90);
			c.rect(x + 2, row * 32 + 2, x + w - 2, row * 32 + 30, static_cast<float>(rng.uniform(120, 200)));
			x += w;
		}
	}
	c.addNoise(seed, 16, 12, 3);
	return {c.toImage(), 4.0, 2.0};
}

Texture muralTexture(uint64_t seed)
{
	Rng rng = Rng::stream(seed, "mural texture");
	TextureCanvas c(2048, 512, static_cast<float>(rng.uniform(120, 170)));  // 32 m x 8 m, 64 px/m
	c.addNoise(seed, 8, 18, 4);
	for (int i = 0; i < 40; ++i)  // panels and posters
	{
		const int x = rng.integer(0, 2048), y = rng.integer(20, 420), w = rng.integer(60, 260), h = rng.integer(50, 200);
		const float tone = static_cast<float>(rng.uniform(30, 230));
		c.rect(x, y, x + w, y + h, tone);
		for (int k = 0; k < 6; ++k)  // "text" lines and pictures on the poster
		{
			const int lx = x + rng.integer(5, std::max(6, w / 2)), ly = y + rng.integer(5, std::max(6, h - 12));
			c.rect(lx, ly, lx + rng.integer(10, std::max(11, w / 2)), ly + rng.integer(4, 12),
				tone > 128 ? tone - 110 : tone + 110);
		}
	}
	for (int i = 0; i < 25; ++i)  // graffiti strokes
	{
		double x = rng.uniform(0, 2048), y = rng.uniform(40, 300), a = rng.uniform(0, 2 * M_PI);
		const float tone = static_cast<float>(rng.uniform(10, 250));
		for (int k = 0; k < 12; ++k)
		{
			const double nx = x + 14 * std::cos(a), ny = y + 14 * std::sin(a);
			c.line(x, y, nx, ny, 7, tone, 0.9f);
			x = nx, y = ny, a += rng.uniform(-0.9, 0.9);
		}
	}
	for (int i = 0; i < 300; ++i)  // small stickers and dirt: corners everywhere
	{
		const int x = rng.integer(0, 2048), y = rng.integer(0, 512), s = rng.integer(6, 20);
		c.rect(x, y, x + s, y + s, static_cast<float>(rng.uniform(20, 240)), 0.8f);
	}
	return {c.toImage(), 32, 8};
}
}  // namespace vlo::sim
