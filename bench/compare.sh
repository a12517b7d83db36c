#!/bin/bash
# Two vlo-run binaries (or one on two drives) timed in alternation, mode vlo, one thread on one core and
# two threads on two, ROUNDS times: on a machine whose speed drifts (a shared host), runs side by side in
# time are what compares. Prints one line per run: processing (frames.csv ms_total) mean / p99 / max,
# the process's CPU per frame including reading (user + sys), the wall time; then per binary the
# medians over the rounds and the throughput (1-thread wall over 2-thread wall).
# Usage: bench/compare.sh ROUNDS OUT_DIR INI A_BIN A_RAWLOG B_BIN B_RAWLOG
# INI may be A_INI:B_INI, one configuration per binary (a change of settings against the old ones).
set -euo pipefail
[[ $# -eq 7 ]] || { echo "usage: $0 ROUNDS OUT_DIR INI A_BIN A_RAWLOG B_BIN B_RAWLOG" >&2; exit 2; }
rounds=$1 out=$2
IFS=: read -r ini_a ini_b <<< "$3"
inis=("$ini_a" "${ini_b:-$ini_a}")
bins=("$4" "$6") rawlogs=("$5" "$7")
mkdir -p "$out"
: > "$out/runs.txt"
for r in $(seq 1 "$rounds"); do
	for run in "0 1" "1 1" "1 2" "0 2"; do
		read -r k threads <<< "$run"
		name=$(printf '%s_t%s_r%s' "$(echo AB | cut -c$((k + 1)))" "$threads" "$r") dir=$out/$name cores=1
		[[ $threads == 2 ]] && cores=0,1
		/usr/bin/time -f "%e %U %S" -o "$dir.time" taskset -c $cores "${bins[$k]}/vlo-run" --rawlog "${rawlogs[$k]}" \
			--ini "${inis[$k]}" --set pipeline.mode=vlo --set pipeline.threads="$threads" --set pipeline.snapshots=false \
			--out "$dir" --overwrite --quiet > "$dir.log" 2>&1
		read -r wall user sys < "$dir.time"
		awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "ms_total") c = i; next } { print $c }' "$dir/frames.csv" |
			sort -g | awk -v name="$name" -v wall="$wall" -v u="$user" -v s="$sys" '
			{ v[++n] = $1; t += $1 }
			END { i = int(0.99 * n + 0.999999); printf "%s %.1f %.1f %.1f %.1f %.2f\n", name, t / n, v[i], v[n], 1000 * (u + s) / n, wall }' |
			tee -a "$out/runs.txt"
	done
done
median() { sort -g | awk '{ v[++n] = $1 } END { print (n % 2) ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2 }'; }
echo "| binary | mean / p99 / max [ms], 1 thread | CPU incl. reading [ms/frame] | wall 1 / 2 threads [s] | throughput |"
echo "|---|---:|---:|---:|---:|"
for k in A B; do
	m() { grep "^${k}_t$1_" "$out/runs.txt" | awk -v c="$2" '{ print $c }' | median; }
	w1=$(m 1 6) w2=$(m 2 6)
	printf "| %s | %s / %s / %s | %s | %s / %s | %.2fx |\n" "$k" "$(m 1 2)" "$(m 1 3)" "$(m 1 4)" "$(m 1 5)" "$w1" "$w2" \
		"$(awk -v a="$w1" -v b="$w2" 'BEGIN { print a / b }')"
done
