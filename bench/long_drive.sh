#!/bin/bash
# A long drive through mode vlo: peak memory and the time per frame at the start against the end (issue 16:
# memory must not grow with the drive's length, the time per frame must stay flat). Not run in CI (too long).
# Usage: bench/long_drive.sh BIN_DIR OUT_DIR [FRAMES (default 5000: ~5 km)] [SEED (default 7)]
# Generates OUT_DIR/drive_FRAMES.rawlog with vlo-sim (HDL-64E, urban) unless it exists, runs vlo-run under
# /usr/bin/time -v and prints one markdown row, then vlo-run's resident memory and CPU time in each tenth of the
# frame loop (sampled every 5 s into OUT_DIR/run_FRAMES.rss: seconds since the start, RSS kB, CPU seconds):
# flat once the maps are full. CPU time, unlike the wall times of frames.csv, does not follow the machine's load.
# LONG_DRIVE_ARGS adds vlo-run options, e.g. "--set pipeline.threads=1": with one thread a frame's ms_total is
# the wall time of that frame, so the first and last tenths compare (on an idle machine).
set -euo pipefail
[[ $# -ge 2 ]] || { echo "usage: $0 BIN_DIR OUT_DIR [FRAMES] [SEED]" >&2; exit 2; }
bin=$1 out=$2 frames=${3:-5000} seed=${4:-7}
ini="$(cd "$(dirname "$0")/.." && pwd)/ini/sim-hdl64.ini"
mkdir -p "$out"
drive=$out/drive_$frames.rawlog
[[ -s $drive ]] || "$bin/vlo-sim" --no-realism --lidar hdl64 --frames "$frames" --seed "$seed" --out "$drive" --quiet
/usr/bin/time -v -o "$out/run_$frames.time" "$bin/vlo-run" --rawlog "$drive" --ini "$ini" --out "$out/run_$frames" \
	--overwrite --quiet ${LONG_DRIVE_ARGS:-} > "$out/run_$frames.log" &
timer=$!
: > "$out/run_$frames.rss"
started=$SECONDS
while kill -0 "$timer" 2> /dev/null; do
	run=$(pgrep -P "$timer" vlo-run || true)
	# utime + stime (fields 14, 15 of /proc/PID/stat) in clock ticks; the name field holds no space here.
	[[ -n $run ]] && echo "$((SECONDS - started)) $(awk '/^VmRSS/ { print $2 }' "/proc/$run/status" 2> /dev/null)" \
		"$(awk -v hz="$(getconf CLK_TCK)" '{ print ($14 + $15) / hz }' "/proc/$run/stat" 2> /dev/null)" >> "$out/run_$frames.rss"
	sleep 5
done
wait "$timer"
rss_kb=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$out/run_$frames.time")
points=$(awk '/^POINTS/ { print $2; exit }' "$out/run_$frames/map.pcd")
echo "| frames | path [m] | peak RSS [MB] | map.pcd points | ms/frame, first 10 % | ms/frame, last 10 % |"
echo "|---:|---:|---:|---:|---:|---:|"
python3 - "$out/run_$frames/frames.csv" "$out/run_$frames/summary.json" "$rss_kb" "$points" "$out/run_$frames.rss" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
ms = [float(r["ms_total"]) for r in rows]
tenth = max(1, len(ms) // 10)
path = json.load(open(sys.argv[2]))["path_length_m"]
print(f"| {len(ms)} | {path:.0f} | {int(sys.argv[3]) / 1024:.0f} | {sys.argv[4]} | "
      f"{sum(ms[:tenth]) / tenth:.1f} | {sum(ms[-tenth:]) / tenth:.1f} |")
# Per tenth of the frame loop's wall time (summary.json "seconds"; with two threads the frames' ms_total add
# up to more than the loop's time, so a sample's frame cannot be told from them): peak RSS and CPU seconds;
# samples after the loop are the outputs (map.pcd, snapshots).
loop = json.load(open(sys.argv[2]))["seconds"]
samples = [(float(f[0]), int(f[1]), float(f[2])) for f in (l.split() for l in open(sys.argv[5])) if len(f) == 3]
rss, cpu, outputs = [0] * 10, [[] for _ in range(10)], 0
for t, kb, s in samples:
    if t > loop:
        outputs = max(outputs, kb)
        continue
    k = min(9, int(10 * t / loop))
    rss[k] = max(rss[k], kb)
    cpu[k].append(s)
print("peak RSS [MB] per tenth of the loop: " + " ".join(f"{kb / 1024:.0f}" for kb in rss) +
      f"; writing the outputs: {outputs / 1024:.0f}")
print("CPU seconds (both threads) per tenth of the loop: " +
      " ".join(f"{c[-1] - c[0]:.1f}" if len(c) > 1 else "-" for c in cpu))
PY
