#pragma once
// Writer of observation-only MRPT rawlogs. Images go to "<name>_Images/" beside the file as PNG
// (external storage) unless inline. The file appears only on commit().
#include <vlo/core/frame.h>

#include <memory>
#include <string>

namespace mrpt::obs
{
class CObservation;
}

namespace vlo
{
class RawlogWriter
{
   public:
	explicit RawlogWriter(const std::string& path, bool external_images = true);
	~RawlogWriter();  ///< removes the partial file if not committed
	RawlogWriter(const RawlogWriter&) = delete;
	RawlogWriter& operator=(const RawlogWriter&) = delete;

	void write(const mrpt::obs::CObservation& obs);
	/// Writes the frame's image and scan (whichever it has) with the rig's poses and intrinsics.
	void writeFrame(const Frame& frame, const std::string& camera_label = "CAMERA",
		const std::string& lidar_label = "LIDAR");
	void commit();

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo
