#!/bin/bash
# How much a short real drive's figures depend on where it starts. On 54 m the path ratio of one run
# moves by a few tenths of a percent with the start frame (a young map, the first motion from zero):
# this runs one mode from start frames 0, 1, ..., 8, 10, 12 of a KITTI raw drive and prints each start's
# path / truth and ATE (SE(3)), then their mean and spread. Drive 0013 frames 0-47: ~0.7 GB in OUT_DIR, about a
# minute per mode on 2 cores.
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
	"$bin/vlo-eval" --gt "$part/drive.gt.tum" --est "$part/run/trajectory_$mode.tum" --metric ate \
		--json "$part/eval.json" --quiet > /dev/null
done
python3 - "$out" <<'PY'
import json, os, statistics, sys
rows = []
for start in (0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 12):
    e = json.load(open(os.path.join(sys.argv[1], f"from_{start}", "eval.json")))
    rows.append((start, e["est_length_m"] / e["gt_length_m"], e["ate_rmse_m"]))
    print(f"from frame {start:2d}: path/truth {rows[-1][1]:.4f}  ATE {rows[-1][2]:.3f} m")
ratios, ates = [r[1] for r in rows], [r[2] for r in rows]
print(f"mean path/truth {statistics.mean(ratios):.4f} (sd {statistics.pstdev(ratios):.4f}, "
      f"{min(ratios):.4f}-{max(ratios):.4f})  mean ATE {statistics.mean(ates):.3f} m")
PY
