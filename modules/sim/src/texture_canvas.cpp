#include "texture_canvas.h"

#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
TextureCanvas::TextureCanvas(int width, int height, float fill)
	: w_(width), h_(height), px_(static_cast<size_t>(width) * height, fill)
{
}

void TextureCanvas::addNoise(uint64_t seed, int cells, float amplitude, int octaves)
{
	std::vector<double> lattice;
	for (int o = 0; o < octaves; ++o, cells *= 2, amplitude *= 0.5f)
	{
		// Lattice indices wrap with the period, so the noise tiles.
		const int cx = std::max(1, cells), cy = std::max(1, cells * h_ / w_);
		lattice.resize(static_cast<std::size_t>(cx) * cy);
		for (int j = 0; j < cy; ++j)
			for (int i = 0; i < cx; ++i) lattice[j * cx + i] = hash01(i, j, seed * 31 + o);
		const double sx = double(cx) / w_, sy = double(cy) / h_;
		for (int y = 0; y < h_; ++y)
		{
			const double fy = y * sy;
			const int iy = static_cast<int>(fy);
			const double ty = fy - iy, wy = ty * ty * (3 - 2 * ty);
			const double* r0 = &lattice[(iy % cy) * cx];
			const double* r1 = &lattice[((iy + 1) % cy) * cx];
			for (int x = 0; x < w_; ++x)
			{
				const double fx = x * sx;
				const int ix = static_cast<int>(fx), i0 = ix % cx, i1 = (ix + 1) % cx;
				const double tx = fx - ix, wx = tx * tx * (3 - 2 * tx);
				const double v = (r0[i0] + (r0[i1] - r0[i0]) * wx) * (1 - wy) + (r1[i0] + (r1[i1] - r1[i0]) * wx) * wy;
				px_[y * w_ + x] += static_cast<float>((2 * v - 1) * amplitude);
			}
		}
	}
}

void TextureCanvas::rect(int x0, int y0, int x1, int y1, float value, float alpha)
{
	for (int y = y0; y < y1; ++y)
		for (int x = x0; x < x1; ++x)
		{
			float& p = at(x, y);
			p += alpha * (value - p);
		}
}

void TextureCanvas::ellipse(double cx, double cy, double rx, double ry, float value, float alpha)
{
	for (int y = static_cast<int>(std::floor(cy - ry)); y <= static_cast<int>(std::ceil(cy + ry)); ++y)
		for (int x = static_cast<int>(std::floor(cx - rx)); x <= static_cast<int>(std::ceil(cx + rx)); ++x)
		{
			const double dx = (x + 0.5 - cx) / rx, dy = (y + 0.5 - cy) / ry;
			if (dx * dx + dy * dy > 1) continue;
			float& p = at(x, y);
			p += alpha * (value - p);
		}
}

void TextureCanvas::line(double x0, double y0, double x1, double y1, double width, float value, float alpha)
{
	const double len = std::hypot(x1 - x0, y1 - y0);
	const int steps = std::max(1, static_cast<int>(len / std::max(0.5, width * 0.5)));
	for (int i = 0; i <= steps; ++i)
	{
		const double t = double(i) / steps;
		ellipse(x0 + t * (x1 - x0), y0 + t * (y1 - y0), width / 2, width / 2, value, alpha);
	}
}

void TextureCanvas::shade(int x0, int y0, int x1, int y1, float delta)
{
	for (int y = y0; y < y1; ++y)
		for (int x = x0; x < x1; ++x) at(x, y) += delta;
}

void TextureCanvas::speckle(Rng& rng, int n, double r, float value, float spread)
{
	for (int i = 0; i < n; ++i)
		ellipse(rng.uniform(0, w_), rng.uniform(0, h_), r, r, value + static_cast<float>(rng.uniform(-spread, spread)));
}

mrpt::img::CImage TextureCanvas::toImage() const
{
	mrpt::img::CImage img(w_, h_, mrpt::img::CH_GRAY);
	for (int y = 0; y < h_; ++y)
	{
		auto* row = img.ptrLine<uint8_t>(y);
		for (int x = 0; x < w_; ++x) row[x] = static_cast<uint8_t>(std::clamp(std::lround(px_[y * w_ + x]), 0L, 255L));
	}
	return img;
}
}  // namespace vlo::sim
