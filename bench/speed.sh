#!/bin/bash
# vlo-run's speed with 1 and 2 threads ([pipeline] threads) on one drive, modes lo and vlo.
# Usage: bench/speed.sh BIN_DIR FRAMES OUT_DIR RAWLOG INI
# threads=1 runs pinned to one core (taskset -c 1), threads=2 on two (taskset -c 0,1). Prints a markdown
# table: processing per frame (frames.csv ms_total: the modules' own time, no reading) as mean / p95 /
# p99 / max, the process's CPU time per frame including rawlog reading and image decoding (user + sys
# of /usr/bin/time), the wall time of the whole run, and the throughput ratio (1-thread wall time over
# 2-thread wall time). On a shared, loaded machine wall time says little: read the CPU columns too.
# SPEED_THREADS="1 2" by default; "0" runs without the threads option (a binary older than it), on one core.
set -euo pipefail
[[ $# -eq 5 ]] || { echo "usage: $0 BIN_DIR FRAMES OUT_DIR RAWLOG INI" >&2; exit 2; }
bin=$1 frames=$2 out=$3 rawlog=$4 ini=$5
mkdir -p "$out"
echo "| mode | threads | ms_total mean / p95 / p99 / max | CPU incl. reading [ms/frame] | wall [s] | throughput vs 1 thread |"
echo "|---|---:|---:|---:|---:|---:|"
for mode in lo vlo; do
	wall1=
	for threads in ${SPEED_THREADS:-1 2}; do
		dir=$out/${mode}_t$threads
		cores=0,1 set=(--set pipeline.threads="$threads")
		[[ $threads == 1 || $threads == 0 ]] && cores=1
		[[ $threads == 0 ]] && set=()
		/usr/bin/time -f "%e %U %S" -o "$dir.time" taskset -c $cores "$bin/vlo-run" --rawlog "$rawlog" --ini "$ini" \
			--set pipeline.mode=$mode --set pipeline.max_frames="$frames" --set pipeline.snapshots=false "${set[@]}" \
			--out "$dir" --overwrite --quiet > "$dir.log" 2>&1
		read -r wall user sys < "$dir.time"
		[[ -z $wall1 ]] && wall1=$wall
		awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "ms_total") c = i; next } { print $c }' "$dir/frames.csv" |
			sort -g | awk -v mode=$mode -v threads=$threads -v wall=$wall -v wall1=$wall1 -v user=$user -v sys=$sys '
			{ v[++n] = $1; s += $1 }
			function q(p) { i = int(p * n + 0.999999); return v[i < 1 ? 1 : i] }
			END {
				printf "| %s | %s | %.1f / %.1f / %.1f / %.1f | %.1f | %.1f | %.2fx |\n", mode, threads == 0 ? "1 (before)" : threads,
					s / n, q(0.95), q(0.99), v[n], 1000 * (user + sys) / n, wall, wall1 / wall
			}'
	done
done
