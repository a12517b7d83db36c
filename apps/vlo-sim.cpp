// vlo-sim: simulated camera + LiDAR drives with ground truth (see doc/SIMULATOR.md).
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/sim/sequence_writer.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv)
{
	return vlo::runApp("vlo-sim", [&] {
		const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 1,
			{{"scenario", "NAME", "urban | trees | corridor | loop | facades | avenue | residential (default urban)"},
				{"lidar", "MODEL", "hdl64 | vlp16 (default hdl64)"},
				{"frames", "N", "number of 10 Hz frames (default 100)"},
				{"seed", "S", "world, drive and noise seed (default 1)"},
				{"out", "FILE.rawlog", "output rawlog; FILE.gt.tum and FILE_Images/ go beside it", true},
				{"trajectory", "POSES.txt", "drive along KITTI camera-0 poses instead of a generated drive"},
				{"reverse-after", "LAPS", "loop: turn around at the turning place nearest to LAPS laps and drive the circuit the other way (default 1.5; 0: never)"},
				{"facade-period", "P", "facades: metres between the street's identical units, a multiple of 8 from 16 to 96 (default 24)"},
				{"kitti-dir", "DIR", "also write the KITTI odometry layout (sequence 00) to DIR"},
				{"lidar-distortion", "", "each LiDAR firing at its own time over the 0.1 s sweep"},
				{"ideal-deskew", "", "with --lidar-distortion: each return moved to the LiDAR's pose at the frame's time (times 0): the best any deskew gives"},
				{"camera-distortion", "K1,K2,P1,P2[,K3]", "render through a plumb_bob lens with these coefficients"},
				{"fisheye", "", "with --camera-distortion K1,K2,K3,K4: an equidistant (fisheye) lens instead"},
				{"realism", "", "a real sensor's errors (default): per-laser calibration errors, range noise growing with range and incidence, mixed returns at depth edges, dropouts on dark and grazing surfaces, intensity noise; camera blur, exposure changes, shot noise; a rolling sweep written without per-point times (doc/SIMULATOR.md)"},
				{"no-realism", "", "the exact sensor: nominal beams, 2 cm range noise, 0.5 % dropouts, 2 grey levels of image noise, an ideal (de-skewed) sweep unless --lidar-distortion"},
				{"point-times", "", "with the realism: write each point's time and ring (a rolling sweep as a driver with times gives it)"},
				{"lidar-elevation-error", "DEG", "with the realism: every laser fires this much above its nominal elevation, an error common to all (KITTI's HDL-64: 0.22; vlo-run corrects it with [lidar] elevation_offset_deg; default 0)"},
				{"no-noise", "", "the exact sensor without image noise, range noise or dropouts (for checks; implies --no-realism)"},
				{"foliage-depth", "M", "mean depth of LiDAR returns inside tree crowns and bushes (default 0: solid hulls)"},
				{"sun-shadows", "", "strong sun: tree crowns cast hard, dappled shadows on everything the camera sees (lit x1.45, shade x0.4)"},
				{"blackout", "A:B", "uniform grey images for frames A..B-1 (a blinded camera)"},
				{"traffic", "N", "N vehicles driving the road both ways, overtaking and oncoming (default 0)"},
				{"traffic-without-returns", "", "the vehicles block the LiDAR's beams but return nothing (an ideal removal of moving points)"},
				{"rawlog-compression", "none|gzip", "none (default) or gzip: ~1.4x smaller, read and written with more CPU (doc/SPEED.md)"},
				{"image-format", "pnm|png", "pnm (PGM, default) or png: ~1.8x smaller images, read and written with more CPU (doc/SPEED.md)"}},
			"vlo-sim --out FILE.rawlog [options]\n\n"
			"Renders a seeded procedural drive headless: a grayscale camera (KITTI intrinsics) and a\n"
			"spinning LiDAR, 10 Hz, with ground truth in FILE.gt.tum (vehicle frame, relative to frame 0).\n"
			"By default the sensors are realistic (--realism); --no-realism gives the exact sensor.");
		vlo::sim::SimConfig cfg;
		cfg.scenario = vlo::sim::parseScenario(cl.get("scenario", "urban"));
		cfg.lidar = vlo::sim::lidarByName(cl.get("lidar", "hdl64"));
		const long frames = cl.getInt("frames", 100), seed = cl.getInt("seed", 1);
		if (frames < 1 || frames > 100000) vlo::failInput("--frames", "must be between 1 and 100000");
		if (seed < 0) vlo::failInput("--seed", "must not be negative");
		cfg.frames = static_cast<int>(frames);
		cfg.seed = static_cast<uint64_t>(seed);
		cfg.kitti_poses = cl.get("trajectory");
		if (cl.has("reverse-after") && cfg.scenario != vlo::sim::Scenario::Loop) vlo::failInput("--reverse-after", "needs --scenario loop");
		if (cl.has("facade-period") && cfg.scenario != vlo::sim::Scenario::Facades)
			vlo::failInput("--facade-period", "needs --scenario facades");
		cfg.reverse_after_laps = cl.getDouble("reverse-after", cfg.reverse_after_laps);
		cfg.facade_period = cl.getDouble("facade-period", cfg.facade_period);
		cfg.lidar_distortion = cl.has("lidar-distortion");
		cfg.lidar_ideal_deskew = cl.has("ideal-deskew");
		if (cl.has("fisheye") && !cl.has("camera-distortion")) vlo::failInput("--fisheye", "needs --camera-distortion K1,K2,K3,K4");
		if (cl.has("camera-distortion"))
			vlo::sim::setLens(cfg.rig.camera, cl.get("camera-distortion"), cl.has("fisheye"));
		if (cfg.rig.camera.distorted() && cl.has("kitti-dir"))
			vlo::failInput("--kitti-dir", "KITTI's images are rectified: not with --camera-distortion");
		if (cl.has("realism") && (cl.has("no-realism") || cl.has("no-noise")))
			vlo::failInput("--realism", std::string("contradicts ") + (cl.has("no-noise") ? "--no-noise" : "--no-realism"));
		const bool realism = !cl.has("no-realism") && !cl.has("no-noise");
		if (cl.has("point-times") && !realism)
			vlo::failInput("--point-times", "needs the realism (the exact sensor's sweep has times with --lidar-distortion)");
		if (realism)
		{
			cfg.realism = vlo::sim::realisticSensors(cfg.lidar);
			cfg.lidar_distortion = true;  // a spinning LiDAR's sweep, moved by the vehicle while it turns
			cfg.lidar_point_times = cl.has("point-times");
			cfg.realism.lidar.common_elevation_error_deg = cl.getDouble("lidar-elevation-error", 0);
			if (!(std::abs(cfg.realism.lidar.common_elevation_error_deg) <= 2))
				vlo::failInput("--lidar-elevation-error", "must be between -2 and 2 degrees");
		}
		else if (cl.has("lidar-elevation-error"))
			vlo::failInput("--lidar-elevation-error", "needs the realism (the exact sensor's beams are nominal)");
		if (cfg.lidar_ideal_deskew && !cfg.lidar_distortion) vlo::failInput("--ideal-deskew", "needs --lidar-distortion");
		if (cl.has("no-noise")) cfg.range_noise = cfg.image_noise = cfg.dropout = 0;
		cfg.foliage_depth = cl.getDouble("foliage-depth", 0);
		if (!(cfg.foliage_depth >= 0 && cfg.foliage_depth <= 10)) vlo::failInput("--foliage-depth", "must be between 0 and 10 m");
		cfg.sun_shadows = cl.has("sun-shadows");
		const long traffic = cl.getInt("traffic", 0);
		if (traffic < 0 || traffic > 1000) vlo::failInput("--traffic", "must be between 0 and 1000 vehicles");
		cfg.traffic = static_cast<int>(traffic);
		cfg.traffic_lidar_returns = !cl.has("traffic-without-returns");
		if (!cfg.traffic_lidar_returns && cfg.traffic == 0) vlo::failInput("--traffic-without-returns", "needs --traffic N");
		const auto compression = vlo::io::parseRawlogCompression(cl.get("rawlog-compression", "none"), "--rawlog-compression");
		const auto image_format = vlo::io::parseImageFileFormat(cl.get("image-format", "pnm"), "--image-format");
		if (cl.has("blackout"))
		{
			const std::string b = cl.get("blackout");
			int first = -1, end = -1;
			char extra = 0;
			if (std::sscanf(b.c_str(), "%d:%d%c", &first, &end, &extra) != 2 || first < 0 || end <= first)
				vlo::failInput("--blackout " + b, "expected A:B with 0 <= A < B (frames A..B-1)");
			cfg.blackout_first = first;
			cfg.blackout_end = end;
		}

		std::string cmd = "vlo-sim";
		for (int i = 1; i < argc; ++i) cmd += std::string(" ") + argv[i];
		if (realism && !cl.has("realism")) cmd += " (--realism by default)";
		const auto t0 = std::chrono::steady_clock::now();
		vlo::sim::Simulator sim(cfg);
		const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		vlo::logger().logStr(mrpt::system::LVL_INFO, sim.summary() + " (built in " + std::to_string(setup) + " s)");

		vlo::sim::OutputOptions out;
		out.rawlog = cl.get("out");
		out.compression = compression;
		out.images = image_format;
		out.kitti_dir = cl.get("kitti-dir");
		out.description = cmd;
		const auto st = vlo::sim::writeSequence(sim, out);
		std::printf("vlo-sim: %d frames, %.0f points/frame, %.2f s/frame (%.1f s + %.1f s setup) -> %s, %s%s%s\n",
			st.frames, st.points_per_frame, st.seconds / st.frames, st.seconds, setup, out.rawlog.c_str(),
			st.ground_truth.c_str(), out.kitti_dir.empty() ? "" : ", ", out.kitti_dir.c_str());
		if (cfg.traffic > 0)
		{
			double within = 0;
			for (int k = 0; k < sim.frameCount(); ++k) within += sim.vehiclesWithin(k, 50);
			std::printf("vlo-sim: traffic of %d vehicles, %.1f within 50 m on average\n", cfg.traffic, within / sim.frameCount());
		}
		return 0;
	});
}
