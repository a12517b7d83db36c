// vlo-run: replays a rawlog through the estimators chosen in an INI file.
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/pipeline/run.h>

#include <malloc.h>

#include <cstdio>

int main(int argc, char** argv)
{
	// Keep freed memory for the next frame: by default glibc gives each scan-sized buffer (a few MB)
	// its own mapping, or trims the heap after it, so every frame faults its pages in again
	// (kernel time: 42k page faults per 100 frames, 27k with these). 32 MB is the largest threshold glibc accepts.
	mallopt(M_MMAP_THRESHOLD, 32 << 20);
	mallopt(M_TRIM_THRESHOLD, 256 << 20);
	mallopt(M_TOP_PAD, 16 << 20);
	return vlo::runApp("vlo-run", [&] {
		const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 1,
			{{"rawlog", "FILE", "input MRPT rawlog (CAMERA + LIDAR observations)", true, false},
				{"ini", "INI", "configuration, e.g. ini/sim-hdl64.ini", true, false},
				{"out", "DIR", "output folder (created)", true, false},
				{"set", "SEC.KEY=VAL", "override one option of the INI", false, true},
				{"gt", "GT.tum", "ground truth, only drawn in the snapshots", false, false},
				{"kitti-calib", "calib.txt", "KITTI calib.txt whose Tr places camera 0 (KITTI imports carry it): trajectories also as KITTI poses", false, false},
				{"overwrite", "", "replace the run that DIR holds (only its files)", false, false}},
			"usage: vlo-run --rawlog FILE --ini INI --out DIR [--set section.key=value ...] [--gt GT.tum]\n"
			"               [--kitti-calib calib.txt] [--overwrite]\n\n"
			"Writes trajectory_<mode>.tum (and trajectory_<mode>.kitti.txt, KITTI's camera-0 poses, when the\n"
			"rig's camera 0 is known), frames.csv, map.pcd, run.ini, summary.json, report.md and snapshots/ in DIR.");
		vlo::pipeline::RunRequest req{cl.get("rawlog"), cl.get("ini"), cl.get("out"), cl.getAll("set"), cl.get("gt"),
			cl.get("kitti-calib"), cl.has("overwrite")};
		const auto s = vlo::pipeline::runPipeline(req);
		std::printf("vlo-run: %zu frames in %.1f s (%.1f ms/frame), path %.1f m, largest step %.2f m -> %s/%s\n", s.frames,
			s.seconds, s.ms_per_frame, s.path_length_m, s.max_step_m, req.out.c_str(), s.final_trajectory.c_str());
		return 0;
	});
}
