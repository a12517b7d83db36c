#!/bin/bash
# The LiDAR methods side by side on one drive (does a simulated drive rank them as a real one does?):
# A-LOAM alone (mode lo), the KISS-ICP-like odometry (mode lo, lidar_odometry = icp) and the full system
# (mode vlo). Prints one row each: estimated path / true path, ATE (SE(3)-aligned), KITTI t_err over 10-30 m,
# and the median over the frames of the scan-to-map RMS residual (frames.csv lo_map_rms_m).
# Usage: bench/method_ranking.sh BIN_DIR DRIVE.rawlog INI [OUT_DIR (default DRIVE's folder)]
# DRIVE.gt.tum must lie beside the rawlog. Without it (a real drive without truth) only the residual and the
# estimated path length are printed.
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: $0 BIN_DIR DRIVE.rawlog INI [OUT_DIR]" >&2; exit 2; }
bin=$1 rawlog=$2 ini=$3
drive=${rawlog%.rawlog}
out=${4:-$(dirname "$rawlog")}
gt=$drive.gt.tum
for method in "lo lo" "icp lo --set pipeline.lidar_odometry=icp" "vlo vlo"; do
	set -- $method
	name=$1 mode=$2
	shift 2
	run=$out/$(basename "$drive")_$name
	"$bin/vlo-run" --rawlog "$rawlog" --ini "$ini" --out "$run" --set pipeline.mode="$mode" \
		--set pipeline.snapshots=false "$@" --quiet --overwrite > /dev/null
	[[ -f $gt ]] && "$bin/vlo-eval" --gt "$gt" --est "$run/trajectory_$mode.tum" --kitti-lengths 10,20,30 \
		--json "$run/eval.json" --quiet > /dev/null
	python3 - "$name" "$run" <<'PY'
import csv, json, math, os, statistics, sys
name, run = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(run, "frames.csv"))))
rms = [float(r["lo_map_rms_m"]) for r in rows if r.get("lo_map_rms_m", "") not in ("", "nan")]
residual = f"median residual {statistics.median(rms) * 100:.2f} cm"
evaluation = os.path.join(run, "eval.json")
if os.path.exists(evaluation):
    e = json.load(open(evaluation))
    print(f"{name:4s} path/truth {e['path_ratio']:.4f}  ATE {e['ate_rmse_m']:.3f} m  "
          f"t_err {e['kitti_t_err_pct']:.3f} %  {residual}")
else:
    mode = "vlo" if name == "vlo" else "lo"
    xs = [list(map(float, l.split()[1:4])) for l in open(os.path.join(run, f"trajectory_{mode}.tum")) if l.strip()]
    print(f"{name:4s} path {sum(math.dist(a, b) for a, b in zip(xs, xs[1:])):.1f} m  {residual}")
PY
done
