#include <vlo/sim/camera_errors.h>
#include <vlo/sim/camera_sim.h>
#include <vlo/sim/lens.h>
#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
struct CameraSim::Lens
{
	PinholeCamera canvas;  // the pinhole picture rendered: K_ widened to every ray the lens sees
	LensMaps maps;  // where each distorted pixel looks in the canvas
};

CameraSim::CameraSim(const PinholeCamera& K, double zfar) : K_(K), zfar_(zfar)
{
	if (!K.distorted()) return;
	// Each output pixel's ray through the lens, as a pixel of the pinhole camera with the same K.
	LensMaps maps = pinholeLookup(K);
	// A real lens sees wider than its pinhole crop: render a canvas that holds every ray (at most one
	// image size more on each side; rays beyond see black).
	double x0 = 0, x1 = K.width - 1, y0 = 0, y1 = K.height - 1;
	for (int r = 0; r < K.height; ++r)
		for (int c = 0; c < K.width; ++c)
		{
			const float x = maps.x.at<float>(r, c), y = maps.y.at<float>(r, c);
			if (!std::isfinite(x) || !std::isfinite(y)) continue;
			x0 = std::min<double>(x0, x), x1 = std::max<double>(x1, x);
			y0 = std::min<double>(y0, y), y1 = std::max<double>(y1, y);
		}
	const auto margin = [](double out, int size) { return int(std::ceil(std::min(out, double(size)))) + 1; };
	const int left = margin(-x0, K.width), right = margin(x1 - (K.width - 1), K.width);
	const int top = margin(-y0, K.height), bottom = margin(y1 - (K.height - 1), K.height);
	lens_ = std::make_unique<Lens>();
	lens_->canvas = K;
	lens_->canvas.distortion = mrpt::img::DistortionModel::none;
	lens_->canvas.dist.fill(0.0);
	lens_->canvas.cx += left, lens_->canvas.cy += top;
	lens_->canvas.width += left + right, lens_->canvas.height += top + bottom;
	maps.x += left, maps.y += top;
	lens_->maps = maps;
}

CameraSim::~CameraSim() = default;

const PinholeCamera& CameraSim::pinhole() const { return lens_ ? lens_->canvas : K_; }

std::pair<int, int> CameraSim::tileSize() const { return {2 * pinhole().width, 2 * pinhole().height}; }

View CameraSim::view(const Eigen::Isometry3d& world_T_cam) const
{
	// Output pixel c covers supersampled pixels 2c and 2c+1, whose centres are at 2c and 2c+1 in the
	// supersampled image: output coordinate u maps to 2u + 0.5.
	const PinholeCamera& K = pinhole();
	View v;
	v.world_T_cam = world_T_cam;
	v.K = K;
	v.K.fx = 2 * K.fx, v.K.fy = 2 * K.fy;
	v.K.cx = 2 * K.cx + 0.5, v.K.cy = 2 * K.cy + 0.5;
	v.K.width = 2 * K.width, v.K.height = 2 * K.height;
	v.znear = 1.0, v.zfar = zfar_;
	return v;
}

mrpt::img::CImage CameraSim::image(const RenderedView& t, double sigma, Rng& rng, const CameraRealism* realism, double gain) const
{
	// 2x2 means of the supersampled tile (exact in float: sums of four bytes over 4).
	const PinholeCamera& P = pinhole();
	cv::Mat picture(P.height, P.width, CV_32F);
	for (int r = 0; r < P.height; ++r)
	{
		const uint8_t* a = &t.gray[static_cast<std::size_t>(2 * r) * t.width];
		const uint8_t* b = a + t.width;
		for (int c = 0; c < P.width; ++c) picture.at<float>(r, c) = (a[2 * c] + a[2 * c + 1] + b[2 * c] + b[2 * c + 1]) / 4.0f;
	}
	if (lens_)  // rays leaving the canvas see black, as beyond a real lens's field
	{
		picture = throughLens(picture, lens_->maps);
	}
	if (realism) applyCameraErrors(picture, *realism, gain, rng), sigma = 0;  // its noise replaces sigma's
	mrpt::img::CImage img(K_.width, K_.height, mrpt::img::CH_GRAY);
	for (int r = 0; r < K_.height; ++r)
	{
		auto* out = img.ptrLine<uint8_t>(r);
		for (int c = 0; c < K_.width; ++c)
		{
			const double v = picture.at<float>(r, c) + (sigma > 0 ? sigma * rng.normal() : 0.0);
			out[c] = static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
		}
	}
	return img;
}

float CameraSim::depthAt(const RenderedView& t, double u, double v)
{
	const int c = static_cast<int>(std::lround(2 * u + 0.5)), r = static_cast<int>(std::lround(2 * v + 0.5));
	if (c < 0 || r < 0 || c >= t.width || r >= t.height) return 0.f;
	return t.depthAt(r, c);
}
}  // namespace vlo::sim
