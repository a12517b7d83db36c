#pragma once
// Runs a simulator over all its frames and writes FILE.rawlog (+ FILE_Images/), FILE.gt.tum and,
// on request, the KITTI odometry layout. Nothing is left behind if it fails half-way.
#include <vlo/io/rawlog_writer.h>
#include <vlo/sim/simulator.h>

#include <string>

namespace vlo::sim
{
struct OutputOptions
{
	std::string rawlog;  ///< FILE.rawlog
	io::RawlogCompression compression = io::RawlogCompression::Gzip;
	io::ImageFileFormat images = io::ImageFileFormat::Png;
	std::string kitti_dir;  ///< "" = no KITTI export
	std::string description;  ///< recorded in the KITTI export (the command line)
	bool progress = true;
};

struct RunStats
{
	int frames = 0;
	double points_per_frame = 0;
	double seconds = 0;  ///< wall time for rendering and writing the frames
	std::string ground_truth;  ///< path of the written FILE.gt.tum
};

RunStats writeSequence(Simulator& sim, const OutputOptions& out);
}  // namespace vlo::sim
