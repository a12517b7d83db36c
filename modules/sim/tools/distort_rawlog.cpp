// Test-only tool: a rawlog of pinhole images (e.g. an imported KITTI snippet) -> the same frames as a
// camera with a known lens sees them: every image remapped through the lens (the pinhole picture
// sampled where each distorted pixel looks; rays beyond it see black) and the lens written into the
// camera model. For the e2e test of vlo-run's undistortion on real images. Not installed.
#include <vlo/core/app_main.h>
#include <vlo/core/cli.h>
#include <vlo/core/error.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/rawlog_writer.h>
#include <vlo/sim/config.h>
#include <vlo/sim/lens.h>

#include <iostream>
#include <optional>

int main(int argc, char** argv)
{
	return vlo::runApp("vlo-test-distort-rawlog", [&] {
		const vlo::CommandLine cl(argc, argv, 1,
			{{"rawlog", "IN.rawlog", "input with pinhole images", true}, {"out", "OUT.rawlog", "output", true},
				{"camera-distortion", "K1,K2,P1,P2[,K3]", "plumb_bob lens (with --fisheye: K1,K2,K3,K4)", true},
				{"fisheye", "", "an equidistant (fisheye) lens"}});
		if (cl.helpRequested())
		{
			std::cout << cl.usage("Usage: vlo-test-distort-rawlog --rawlog IN.rawlog --out OUT.rawlog --camera-distortion K1,K2,P1,P2");
			return 0;
		}
		vlo::io::RawlogReaderOptions camera_only_too;  // a camera-only rawlog (e.g. KITTI's grey 06 sequence) is fine
		camera_only_too.need_lidar = false;
		vlo::io::RawlogReader reader(cl.get("rawlog"), camera_only_too);
		vlo::io::RawlogWriter writer(cl.get("out"));
		std::optional<vlo::sim::LensMaps> maps;  // built once: the camera is the same for every frame
		vlo::PinholeCamera lens;
		for (vlo::Frame f; reader.next(f);)
		{
			if (f.has_image)
			{
				if (f.rig.camera.distorted()) vlo::failInput(cl.get("rawlog"), "its images already have a lens distortion");
				if (!maps)
				{
					lens = f.rig.camera;
					vlo::sim::setLens(lens, cl.get("camera-distortion"), cl.has("fisheye"));
					maps = vlo::sim::pinholeLookup(lens);
				}
				const cv::Mat distorted = vlo::sim::throughLens(f.image.asCvMatRef(), *maps);
				f.image = mrpt::img::CImage(distorted, mrpt::img::DEEP_COPY);
				f.rig.camera = lens;
			}
			writer.writeFrame(f);
		}
		writer.commit();
		return 0;
	});
}
