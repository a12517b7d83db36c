// Test-only tool: a vlo rawlog (e.g. from vlo-sim) -> a ROS 1 bag as drivers record it, for the e2e tests
// of vlo-import rosbag. Not installed; not a converter for users.
#include "bag_writer.h"

#include <vlo/core/app_main.h>
#include <vlo/core/cli.h>
#include <vlo/io/rawlog_reader.h>

#include <iostream>

int main(int argc, char** argv)
{
	return vlo::runApp("vlo-test-rawlog-to-bag", [&] {
		const vlo::CommandLine cl(argc, argv, 1,
			{{"rawlog", "FILE.rawlog", "input", true}, {"out", "FILE.bag", "output bag", true},
				{"gt", "FILE.tum", "ground truth written as nav_msgs/Odometry on /ground_truth"},
				{"encoding", "E", "mono8 (default) rgb8 bgr8 rgba8 bgra8 mono16; png jpeg on /camera/image_raw/compressed"},
				{"no-tf", "", "write no transforms"}, {"tf-dynamic", "", "transforms on /tf every frame, not /tf_static"},
				{"distortion-model", "M", "CameraInfo distortion_model to write (broken-input tests)"},
				{"drop-x", "", "PointCloud2 without its x field (broken-input tests)"},
				{"vlp16-fields", "", "add VLP-16 driver fields ring (top-down) and time (from the azimuth)"}});
		if (cl.helpRequested())
		{
			std::cout << cl.usage("Usage: vlo-test-rawlog-to-bag --rawlog IN.rawlog --out OUT.bag [options]");
			return 0;
		}
		vlo::test::BagLayout layout;
		layout.image_encoding = cl.get("encoding", layout.image_encoding);
		if (layout.image_encoding == "png" || layout.image_encoding == "jpeg") layout.image_topic += "/compressed";
		layout.tf_static = !cl.has("no-tf");
		layout.tf_as_dynamic = cl.has("tf-dynamic");
		layout.distortion_model = cl.get("distortion-model");
		layout.drop_x = cl.has("drop-x");
		std::vector<vlo::Frame> frames;
		vlo::io::RawlogReader reader(cl.get("rawlog"));
		for (vlo::Frame f; reader.next(f);)
		{
			if (cl.has("vlp16-fields")) vlo::test::addVlp16Fields(f.scan);
			frames.push_back(f);
		}
		const vlo::Trajectory gt = cl.has("gt") ? vlo::io::readTum(cl.get("gt")) : vlo::Trajectory{};
		vlo::test::writeBag(cl.get("out"), frames, gt, layout);
		return 0;
	});
}
