#!/bin/bash
# Whole-system speed on one core: vlo-run pinned to CPU 0 on each drive, first N frames.
# Usage: bench/realtime.sh BIN_DIR FRAMES OUT_DIR rawlog:ini [rawlog:ini ...]
# Prints a markdown table: processing per frame (frames.csv ms_total: every module, no rawlog
# reading) as mean / p95 / max and the share of frames over 100 ms, and the process's CPU time
# per frame including rawlog reading and image decoding, and its peak memory.
set -euo pipefail
[[ $# -ge 4 ]] || { echo "usage: $0 BIN_DIR FRAMES OUT_DIR rawlog:ini..." >&2; exit 2; }
bin=$1 frames=$2 out=$3
shift 3
mkdir -p "$out"
echo "| drive | processing mean / p95 / max [ms] | frames > 100 ms | CPU incl. reading [ms/frame] | peak RSS [MB] |"
echo "|---|---:|---:|---:|---:|"
for pair in "$@"; do
	rawlog=${pair%%:*} ini=${pair#*:}
	name=$(basename "$rawlog" .rawlog)
	dir=$out/$name
	/usr/bin/time -f "%U %S %M" -o "$dir.time" taskset -c 0 "$bin/vlo-run" --rawlog "$rawlog" --ini "$ini" \
		--set pipeline.max_frames="$frames" --out "$dir" --overwrite --quiet > "$dir.log" 2>&1
	read -r user sys rss < "$dir.time"
	awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "ms_total") c = i; next } { print $c }' "$dir/frames.csv" |
		sort -g | awk -v name="$name" -v user="$user" -v sys="$sys" -v rss="$rss" '
		{ v[++n] = $1; s += $1; if ($1 > 100) slow++ }
		END {
			printf "| %s | %.1f / %.1f / %.1f | %.1f %% | %.1f | %.0f |\n", name, s / n, v[int(0.95 * n)], v[n],
				100 * slow / n, 1000 * (user + sys) / n, rss / 1024
		}'
done
