#!/bin/bash
# Does the full system gain from the VO where a 16-beam LiDAR is weak (issue 32 section 3)? Six 260-frame
# VLP-16 drives of vlo-sim with the realistic sensor (trees with foliage, urban, corridor; seeds 1 and 2),
# each run as A-LOAM alone (mode lo) and as the full system (mode vlo, which also writes the
# scale-corrected VO's trajectory_vo.tum). Prints each drive's KITTI t_err of the three and whether the
# full system beats both, then how many drives it does. Missing drives are generated first (about 1.5 min
# each on one core); runs go two at a time.
# Usage: bench/vlp16_fusion.sh BIN_DIR OUT_DIR [vlo-run options, e.g. --set ...]
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: $0 BIN_DIR OUT_DIR [vlo-run options]" >&2; exit 2; }
bin=$(realpath "$1") out=$2
shift 2
ini=$(realpath "$(dirname "$0")/../ini/vlp16.ini")
mkdir -p "$out"
drives="trees_1 trees_2 urban_1 urban_2 corridor_1 corridor_2"
for drive in $drives; do
	[[ -f $out/$drive.rawlog ]] && continue
	scenario=${drive%_*} seed=${drive#*_}
	foliage=()
	[[ $scenario == trees ]] && foliage=(--foliage-depth 0.3)
	echo "$bin/vlo-sim --scenario $scenario --lidar vlp16 --frames 260 --seed $seed ${foliage[*]} --out $out/$drive.rawlog --quiet"
done | xargs -P 2 -I{} bash -c "{}"
run() {  # DRIVE MODE [vlo-run options]
	local drive=$1 mode=$2 traj
	shift 2
	"$bin/vlo-run" --rawlog "$out/$drive.rawlog" --ini "$ini" --out "$out/${drive}_$mode" --set pipeline.mode="$mode" \
		--set pipeline.snapshots=false --set pipeline.threads=1 "$@" --quiet --overwrite > /dev/null
	for traj in $mode $([[ $mode == vlo ]] && echo vo); do
		"$bin/vlo-eval" --gt "$out/$drive.gt.tum" --est "$out/${drive}_$mode/trajectory_$traj.tum" --metric all \
			--json "$out/${drive}_$traj.json" --quiet > /dev/null
	done
}
for drive in $drives; do
	for mode in lo vlo; do
		run "$drive" "$mode" "$@" &
		(($(jobs -r | wc -l) < 2)) || wait -n
	done
done
wait
python3 - "$out" $drives <<'PY'
import json, os, sys
out, drives = sys.argv[1], sys.argv[2:]
t_err = lambda d, traj: json.load(open(os.path.join(out, f"{d}_{traj}.json")))["kitti_t_err_pct"]
wins = 0
print(f"{'drive':12s} {'A-LOAM':>8s} {'full':>8s} {'VO':>8s}  KITTI t_err %")
for d in drives:
    lo, vlo, vo = t_err(d, "lo"), t_err(d, "vlo"), t_err(d, "vo")
    win = vlo < lo and vlo < vo
    wins += win
    print(f"{d:12s} {lo:8.3f} {vlo:8.3f} {vo:8.3f}  {'full system best' if win else ''}")
print(f"the full system beats A-LOAM alone and the VO on {wins} of {len(drives)} drives")
PY
