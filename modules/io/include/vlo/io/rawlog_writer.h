#pragma once
// Writer of observation-only MRPT rawlogs, gzip or plain (MRPT and RawlogReader read both; a plain one
// is ~1.4x larger for a simulated HDL-64 drive but spares the reader the inflate). Images go as PNG to
// "<name>_Images/" beside the file (external storage) unless inline; PGM/PPM on request (no PNG
// decoding when read). Nothing appears at `path` until commit(): the rawlog is
// written to "<path>.partial" and the images to "<name>_Images.partial/", both renamed on commit.
#include <vlo/core/frame.h>

#include <Eigen/Geometry>

#include <memory>
#include <string>

namespace mrpt::obs
{
class CObservation;
}

namespace vlo::io
{
/// "<dir>/<name>_Images" for "<dir>/<name>.<ext>": where MRPT looks for a rawlog's external images.
std::string rawlogImagesDir(const std::string& rawlog_path);

enum class RawlogCompression
{
	Gzip,
	None
};
/// "gzip" or "none"; throws InputError naming `what` for anything else.
RawlogCompression parseRawlogCompression(const std::string& name, const std::string& what);

/// File format of external images: PNG, or PGM/PPM (uncompressed: ~1.8x larger, no inflate to read).
enum class ImageFileFormat
{
	Png,
	Pnm
};
/// "png" or "pnm"; throws InputError naming `what` for anything else.
ImageFileFormat parseImageFileFormat(const std::string& name, const std::string& what);

class RawlogWriter
{
   public:
	/// Throws InputError naming `path` when it cannot be created.
	explicit RawlogWriter(const std::string& path, bool external_images = true,
		RawlogCompression compression = RawlogCompression::Gzip, ImageFileFormat images = ImageFileFormat::Png);
	~RawlogWriter();  ///< removes the partial output if not committed
	RawlogWriter(const RawlogWriter&) = delete;
	RawlogWriter& operator=(const RawlogWriter&) = delete;

	/// Writes one observation as it is (an externally stored image must already be in place).
	void write(const mrpt::obs::CObservation& obs);
	/// Writes the frame's image and scan (whichever it has) with the rig's poses and intrinsics, at
	/// time frame.t. External images are named "<label>_<frame.index, 6 digits>.png" (or .pgm for a
	/// grey image in Pnm, .ppm for a colour one).
	void writeFrame(const Frame& frame, const std::string& camera_label = "CAMERA",
		const std::string& lidar_label = "LIDAR");
	/// Notes where KITTI's rectified camera 0 sits on the vehicle (frame_observations.h), at time t; once,
	/// ahead of the first frame.
	void noteCamera0(const Eigen::Isometry3d& vehicle_T_camera0, double t);
	void commit();

	std::size_t observationsWritten() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::io
