#pragma once
// Turns the images of a lens-distorted camera into ideal pinhole images with the same K, once per frame
// through remap tables built once per camera (OpenCV: plumb_bob incl. the rational model, and
// kannala_brandt = fisheye / ROS equidistant). The estimators assume a pinhole model.
#include <vlo/core/frame.h>

#include <memory>

namespace vlo::io
{
class ImageUndistorter
{
   public:
	ImageUndistorter();
	~ImageUndistorter();

	/// When the frame's camera is distorted: replaces its image by the undistorted one and its camera by
	/// the pinhole (same K, no distortion). Returns whether it changed the frame.
	bool apply(Frame& frame);

   private:
	struct Maps;
	std::unique_ptr<Maps> maps_;
};
}  // namespace vlo::io
