#include <vlo/core/progress.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_writer.h>
#include <vlo/sim/kitti_export.h>
#include <vlo/sim/sequence_writer.h>

#include <cstdio>
#include <memory>

namespace vlo::sim
{
RunStats writeSequence(Simulator& sim, const OutputOptions& out)
{
	const auto start = SteadyClock::now();
	// Both writers keep their output under ".partial" names until they commit: an error (or Ctrl-C)
	// half-way leaves no file that looks complete.
	io::RawlogWriter rawlog(out.rawlog, true, out.compression, out.images);
	std::unique_ptr<KittiExporter> kitti;
	if (!out.kitti_dir.empty()) kitti = std::make_unique<KittiExporter>(out.kitti_dir, sim.config().rig, out.description);
	if (!out.progress) ProgressLine::setEnabled(false);
	ProgressLine progress("vlo-sim", static_cast<std::size_t>(sim.frameCount()));
	std::size_t points = 0;
	for (int k = 0; k < sim.frameCount(); ++k)
	{
		const Frame f = sim.frame(k);
		rawlog.writeFrame(f);
		if (kitti) kitti->write(f);
		points += f.scan.size();
		progress.update(static_cast<std::size_t>(k + 1));
	}
	progress.finish();
	RunStats st;
	const Trajectory gt = sim.groundTruth();
	st.ground_truth = io::groundTruthPathFor(out.rawlog);
	io::writeTum(st.ground_truth, gt);
	try
	{
		if (kitti) kitti->commit(gt);
		rawlog.commit();
	}
	catch (...)
	{
		std::remove(st.ground_truth.c_str());  // no ground truth without its rawlog
		throw;
	}
	st.frames = sim.frameCount();
	st.points_per_frame = st.frames ? double(points) / st.frames : 0;
	st.seconds = msSince(start) / 1000.0;
	return st;
}
}  // namespace vlo::sim
