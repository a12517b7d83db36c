#!/bin/bash
# A long drive through mode vlo: peak memory and the time per frame at the start against the end (issue 16:
# memory must not grow with the drive's length, the time per frame must stay flat). Not run in CI (too long).
# Usage: bench/long_drive.sh BIN_DIR OUT_DIR [FRAMES (default 5000: ~5 km)] [SEED (default 7)]
# Generates OUT_DIR/drive_FRAMES.rawlog with vlo-sim (HDL-64E, urban) unless it exists, runs vlo-run under
# /usr/bin/time -v and prints one markdown row.
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: $0 BIN_DIR OUT_DIR [FRAMES] [SEED]" >&2; exit 2; }
bin=$1 out=$2 frames=${3:-5000} seed=${4:-7}
ini="$(cd "$(dirname "$0")/.." && pwd)/ini/sim-hdl64.ini"
mkdir -p "$out"
drive=$out/drive_$frames.rawlog
[[ -s $drive ]] || "$bin/vlo-sim" --lidar hdl64 --frames "$frames" --seed "$seed" --out "$drive" --quiet
/usr/bin/time -v -o "$out/run_$frames.time" "$bin/vlo-run" --rawlog "$drive" --ini "$ini" --out "$out/run_$frames" \
	--overwrite --quiet > "$out/run_$frames.log"
rss_kb=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$out/run_$frames.time")
points=$(awk '/^POINTS/ { print $2; exit }' "$out/run_$frames/map.pcd")
echo "| frames | path [m] | peak RSS [MB] | map.pcd points | ms/frame, first 10 % | ms/frame, last 10 % |"
echo "|---:|---:|---:|---:|---:|---:|"
python3 - "$out/run_$frames/frames.csv" "$out/run_$frames/summary.json" "$rss_kb" "$points" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
ms = [float(r["ms_total"]) for r in rows]
tenth = max(1, len(ms) // 10)
path = json.load(open(sys.argv[2]))["path_length_m"]
print(f"| {len(ms)} | {path:.0f} | {int(sys.argv[3]) / 1024:.0f} | {sys.argv[4]} | "
      f"{sum(ms[:tenth]) / tenth:.1f} | {sum(ms[-tenth:]) / tenth:.1f} |")
PY
