#include "observation_stream.h"  // mrptMessage

#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/core/stderr_capture.h>
#include <vlo/io/frame_observations.h>
#include <vlo/io/lidar_observations.h>
#include <vlo/io/rawlog_writer.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>

namespace vlo::io
{
namespace fs = std::filesystem;

std::string rawlogImagesDir(const std::string& rawlog_path)
{
	const fs::path p(rawlog_path);
	return (p.parent_path() / (p.stem().string() + "_Images")).string();
}

struct RawlogWriter::Impl
{
	std::string path, partial, images_dir, images_partial;
	bool external = true, committed = false;
	std::size_t written = 0;
	std::unique_ptr<mrpt::io::CStream> out;  // gzip or plain; closed when reset
	ImageFileFormat image_format = ImageFileFormat::Png;
	mrpt::serialization::CArchive::UniquePtr ar;

	void close()
	{
		ar.reset();
		out.reset();
	}
	void discard() noexcept
	{
		std::error_code ec;
		close();
		fs::remove(partial, ec);
		if (external) fs::remove_all(images_partial, ec);
	}
};

RawlogCompression parseRawlogCompression(const std::string& name, const std::string& what)
{
	if (name == "gzip") return RawlogCompression::Gzip;
	if (name == "none") return RawlogCompression::None;
	failInput(what, "'" + name + "' is not a rawlog compression (gzip | none)");
}

ImageFileFormat parseImageFileFormat(const std::string& name, const std::string& what)
{
	if (name == "png") return ImageFileFormat::Png;
	if (name == "pnm") return ImageFileFormat::Pnm;
	failInput(what, "'" + name + "' is not an image file format (png | pnm)");
}

RawlogWriter::RawlogWriter(
	const std::string& path, bool external_images, RawlogCompression compression, ImageFileFormat images)
	: impl_(std::make_unique<Impl>())
{
	auto& d = *impl_;
	d.image_format = images;
	d.path = path;
	d.partial = path + ".partial";
	d.external = external_images;
	d.images_dir = rawlogImagesDir(path);
	d.images_partial = d.images_dir + ".partial";
	std::error_code ec;
	if (fs::is_directory(path, ec)) failInput(path, "is a directory, expected a rawlog file name");
	const fs::path parent = fs::path(path).parent_path();
	if (!parent.empty()) fs::create_directories(parent, ec);
	bool opened = false;
	if (compression == RawlogCompression::Gzip)
	{
		auto gz = std::make_unique<mrpt::io::CFileGZOutputStream>();
		opened = gz->open(d.partial, 1 /*fast gzip: point clouds barely compress*/);
		d.out = std::move(gz);
	}
	else
	{
		auto plain = std::make_unique<mrpt::io::CFileOutputStream>();
		opened = plain->open(d.partial);
		d.out = std::move(plain);
	}
	if (!opened) failInput(path, "cannot open for writing");
	d.ar = mrpt::serialization::archiveUniquePtrFrom(*d.out);
	if (d.external)
	{
		fs::remove_all(d.images_partial, ec);
		if (!fs::create_directories(d.images_partial, ec))
		{
			d.discard();
			failInput(d.images_partial, "cannot create image directory: " + ec.message());
		}
	}
}

RawlogWriter::~RawlogWriter()
{
	if (!impl_->committed) impl_->discard();
}

void RawlogWriter::write(const mrpt::obs::CObservation& obs)
{
	try
	{
		*impl_->ar << obs;
	}
	catch (const std::exception& e)
	{
		// MRPT's message carries a 20-line backtrace: its own line only.
		failInput(impl_->path, "write failed (disk full?): " + mrptMessage(e.what()));
	}
	++impl_->written;
}

void RawlogWriter::writeFrame(const Frame& frame, const std::string& camera_label, const std::string& lidar_label)
{
	auto& d = *impl_;
	if (frame.has_image)
	{
		auto obs = toImageObservation(frame, camera_label);
		if (d.external)
		{
			const char* ext = d.image_format == ImageFileFormat::Png ? "png" : obs->image.isColor() ? "ppm"
																									: "pgm";
			char name[64];
			std::snprintf(name, sizeof(name), "_%06zu.%s", frame.index, ext);
			const std::string file = camera_label + name;
			StderrCapture capture;  // libpng says why ("Write Error") before the save fails
			if (!obs->image.saveToFile(d.images_partial + "/" + file))
				failInput(d.images_partial + "/" + file, withReason("cannot write image", capture.taken()));
			obs->image.setExternalStorage(file);  // relative to <name>_Images
		}
		write(*obs);
	}
	if (frame.has_scan) write(*toScanObservation(frame, lidar_label));
}

void RawlogWriter::noteCamera0(const Eigen::Isometry3d& vehicle_T_camera0, double t)
{
	write(*toCamera0Note(vehicle_T_camera0, t));
}

void RawlogWriter::commit()
{
	auto& d = *impl_;
	d.close();
	std::error_code ec;
	if (d.external)
	{
		fs::remove_all(d.images_dir, ec);
		fs::rename(d.images_partial, d.images_dir, ec);
		if (ec) failInput(d.images_dir, "cannot move images into place: " + ec.message());
	}
	commitFile(d.partial, d.path);
	d.committed = true;
}

std::size_t RawlogWriter::observationsWritten() const { return impl_->written; }
}  // namespace vlo::io
