#pragma once
// A float raster for painting procedural textures (values are gray levels 0..255). Coordinates
// wrap around so that textures tile seamlessly under GL_REPEAT.
#include <mrpt/img/CImage.h>

#include <cstdint>
#include <vector>

namespace vlo::sim
{
class Rng;

class TextureCanvas
{
   public:
	TextureCanvas(int width, int height, float fill);
	int width() const { return w_; }
	int height() const { return h_; }
	float& at(int x, int y) { return px_[wrapY(y) * w_ + wrapX(x)]; }

	/// Adds periodic fractal value noise: `cells` lattice cells across the width at the coarsest
	/// octave (the height gets cells * height / width), amplitude halves per octave.
	void addNoise(uint64_t seed, int cells, float amplitude, int octaves);
	/// Sets (alpha = 1) or blends a filled rectangle [x0, x1) x [y0, y1).
	void rect(int x0, int y0, int x1, int y1, float value, float alpha = 1.0f);
	void ellipse(double cx, double cy, double rx, double ry, float value, float alpha = 1.0f);
	void line(double x0, double y0, double x1, double y1, double width, float value, float alpha = 1.0f);
	/// Adds v to every pixel of the rectangle (shading, stains).
	void shade(int x0, int y0, int x1, int y1, float delta);
	/// Random speckles: n dots of radius r, gray value drawn around `value` +- spread.
	void speckle(Rng& rng, int n, double r, float value, float spread);

	mrpt::img::CImage toImage() const;

   private:
	int w_, h_;
	std::vector<float> px_;
	int wrapX(int x) const { return ((x % w_) + w_) % w_; }
	int wrapY(int y) const { return ((y % h_) + h_) % h_; }
};
}  // namespace vlo::sim
