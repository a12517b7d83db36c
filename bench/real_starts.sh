#!/bin/bash
# How much a short real drive's figures depend on where it starts. On 54 m the path ratio of one run
# moves by a few tenths of a percent with the start frame (a young map, the first motion from zero):
# this runs one mode from start frames 0, 1, ..., 8, 10, 12 of a KITTI raw drive and prints each start's
# path / truth and ATE (SE(3)), then their mean and spread; the path also against the truth dead-reckoned
# from the OXTS velocities (drive.gt_velocity.tum, doc/EVALUATION.md). Mode vlo: the scale-corrected VO
# (trajectory_vo.tum) too. Drive 0013 frames 0-47: ~0.7 GB in OUT_DIR, about a minute per mode on 2 cores.
# Usage: bench/real_starts.sh BIN_DIR DRIVE_DIR CALIB_DIR OUT_DIR MODE [vlo-run options, e.g. --set ...]
#   DRIVE_DIR: the drive's folder (image_02, velodyne_points, oxts); CALIB_DIR: its calib_*.txt.
set -euo pipefail
[[ $# -ge 5 ]] || { echo "usage: $0 BIN_DIR DRIVE_DIR CALIB_DIR OUT_DIR MODE [vlo-run options]" >&2; exit 2; }
bin=$1 drive=$2 calib=$3 out=$4 mode=$5
shift 5
ini=$(dirname "$0")/../ini/kitti-hdl64.ini
mkdir -p "$out"
for start in 0 1 2 3 4 5 6 7 8 10 12; do
	# The drive from frame `start` on, renumbered from 0: links to the data, the stamp files cut.
	part=$out/from_$start
	rm -rf "$part"
	for sensor in image_02 oxts velodyne_points; do
		[[ -d $drive/$sensor ]] || continue
		mkdir -p "$part/drive/$sensor/data"
		for stamps in "$drive/$sensor"/timestamps*.txt; do tail -n +$((start + 1)) "$stamps" > "$part/drive/$sensor/$(basename "$stamps")"; done
		[[ -f $drive/$sensor/dataformat.txt ]] && cp "$drive/$sensor/dataformat.txt" "$part/drive/$sensor/"
		for file in "$drive/$sensor"/data/*; do
			name=$(basename "$file") index=$((10#${name%%.*}))
			((index >= start)) && ln -s "$(realpath "$file")" "$part/drive/$sensor/data/$(printf %010d $((index - start))).${name#*.}"
		done
	done
	"$bin/vlo-import" kitti-raw --drive "$part/drive" --calib "$calib" --out "$part/drive.rawlog" --quiet > /dev/null
	"$bin/vlo-run" --rawlog "$part/drive.rawlog" --ini "$ini" --out "$part/run" --set pipeline.mode="$mode" \
		--set pipeline.snapshots=false "$@" --quiet --overwrite > /dev/null
	trajectories=$mode
	[[ $mode == vlo ]] && trajectories="vlo vo"
	for traj in $trajectories; do
		for truth in gt gt_velocity; do
			[[ -f $part/drive.$truth.tum ]] || continue
			"$bin/vlo-eval" --gt "$part/drive.$truth.tum" --est "$part/run/trajectory_$traj.tum" --metric ate \
				--json "$part/eval_${traj}_$truth.json" --quiet > /dev/null
		done
	done
done
python3 - "$out" $trajectories <<'PY'
import json, os, statistics, sys
def ratio_ate(path):
    if not os.path.exists(path): return None, None
    e = json.load(open(path))
    return e["path_ratio"], e["ate_rmse_m"]
for traj in sys.argv[2:]:
    rows = []
    for start in (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 12):
        part = os.path.join(sys.argv[1], f"from_{start}")
        ratio, ate = ratio_ate(os.path.join(part, f"eval_{traj}_gt.json"))
        by_velocity, ate_velocity = ratio_ate(os.path.join(part, f"eval_{traj}_gt_velocity.json"))
        rows.append((ratio, ate, by_velocity, ate_velocity))
        print(f"{traj} from frame {start:2d}: path/truth {ratio:.4f}  ATE {ate:.3f} m" +
              (f"  path/velocities {by_velocity:.4f}  ATE {ate_velocity:.3f} m" if by_velocity else ""))
    ratios, ates = [r[0] for r in rows], [r[1] for r in rows]
    line = (f"{traj}: mean path/truth {statistics.mean(ratios):.4f} (sd {statistics.pstdev(ratios):.4f}, "
            f"{min(ratios):.4f}-{max(ratios):.4f})  mean ATE {statistics.mean(ates):.3f} m")
    if all(r[2] for r in rows):
        v = [r[2] for r in rows]
        line += (f"  mean path/velocities {statistics.mean(v):.4f} ({min(v):.4f}-{max(v):.4f})"
                 f"  ATE {statistics.mean(r[3] for r in rows):.3f} m")
    print(line)
PY
