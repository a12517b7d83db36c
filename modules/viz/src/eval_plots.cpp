#include <vlo/core/error.h>
#include <vlo/core/units.h>
#include <vlo/eval/kitti_curves.h>
#include <vlo/viz/eval_plots.h>
#include <vlo/viz/topdown.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace vlo::viz
{
namespace
{
constexpr double kKmhPerMs = 3.6;

enum class Error
{
	Translation,
	Rotation
};
enum class Axis
{
	Length,
	Speed
};

PlotSpec devkitPlot(const std::vector<EvalRun>& runs, const std::vector<eval::KittiCurves>& curves, Error e, Axis x)
{
	PlotSpec p;
	const bool t = e == Error::Translation, len = x == Axis::Length;
	p.file = std::string("kitti_") + (t ? "translation" : "rotation") + "_vs_" + (len ? "length" : "speed") + ".png";
	p.style.title = std::string(t ? "Translation" : "Rotation") + " error against " + (len ? "path length" : "speed") +
		" (KITTI devkit)";
	p.style.xlabel = len ? "path length [m]" : "speed [km/h]";
	p.style.ylabel = t ? "translation error [%]" : "rotation error [deg/m]";
	p.style.ymin = 0;
	double ymax = 0;
	for (std::size_t i = 0; i < runs.size(); ++i)
	{
		Series s;
		s.name = runs[i].name;
		s.markers = true;
		for (const auto& pt : len ? curves[i].by_length : curves[i].by_speed)
		{
			s.x.push_back(len ? pt.x : kKmhPerMs * pt.x);
			s.y.push_back(t ? 100 * pt.t_err : kDegPerRad * pt.r_err);
		}
		for (const double y : s.y) ymax = std::max(ymax, y);
		p.series.push_back(std::move(s));
	}
	if (ymax > 0) p.style.ymax = 1.35 * ymax;  // room above the curves for the legend
	return p;
}

bool hasPoint(const PlotSpec& p)
{
	for (const auto& s : p.series)
		if (!s.x.empty()) return true;
	return false;
}

std::string metres(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof buf, v < 10 ? "%.3f m" : "%.2f m", v);
	return buf;
}
}  // namespace

std::vector<PlotSpec> kittiErrorPlots(const std::vector<EvalRun>& runs)
{
	std::vector<eval::KittiCurves> curves;
	for (const auto& r : runs)
		curves.push_back(r.report.kitti ? eval::kittiCurves(*r.report.kitti, r.report.options.kitti_options) : eval::KittiCurves{});
	std::vector<PlotSpec> plots;
	for (const Axis x : {Axis::Length, Axis::Speed})
		for (const Error e : {Error::Translation, Error::Rotation})
		{
			PlotSpec p = devkitPlot(runs, curves, e, x);
			if (hasPoint(p)) plots.push_back(std::move(p));
		}
	return plots;
}

std::string atePlotFile(const std::string& run_name)
{
	std::string f = "ate_" + run_name + ".png";
	for (char& c : f)
		if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
	return f;
}

std::vector<std::string> writeEvalPlots(const std::string& dir, const std::vector<EvalRun>& runs)
{
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec) failInput(dir, "cannot create the plot folder: " + ec.message());
	std::vector<std::string> written;
	for (const auto& p : kittiErrorPlots(runs))
	{
		renderSeries(p.series, dir + "/" + p.file, p.style);
		written.push_back(p.file);
	}
	for (const auto& run : runs)
	{
		const eval::EvalReport& r = run.report;
		if (!r.ate) continue;
		const NamedTrajectory est{run.name, eval::alignedEstimate(r), {}};
		TopDownStyle style;
		style.values = eval::ateErrors(r.association.gt, est.traj, Sim3{});  // already aligned
		style.value_label = "ATE [m]";
		style.title = run.name + ": ATE after " + eval::toString(r.options.align) + " alignment, RMSE " +
			metres(r.ate->ate_rmse_m) + ", max " + metres(r.ate->ate_max_m);
		const std::string file = atePlotFile(run.name);
		renderTopDown({est}, &r.association.gt, dir + "/" + file, style);
		written.push_back(file);
	}
	return written;
}
}  // namespace vlo::viz
