#!/usr/bin/env bash
# The same run with one thread, with two, and with two again (modes vlo and lo, a short simulated drive) gives
# byte-identical outputs: trajectories, map.pcd, run.ini (apart from its threads line), and frames.csv and
# summary.json apart from their timing (ms_* columns; seconds, ms_per_frame and the stage_timings figures).
# With two threads the VO's local bundle adjustment also runs beside tracking (its result enters at a fixed frame).
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --frames 40 --seed 9 --out drive.rawlog --quiet || fail "vlo-sim"
# run NAME MODE THREADS [--set ...]
run() {
	local name=$1 mode=$2 threads=$3
	shift 3
	"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out $name --quiet --set pipeline.mode=$mode \
		--set pipeline.threads=$threads --set pipeline.snapshots=false "$@" > /dev/null || fail "vlo-run $name"
}
run a vlo 1
run b vlo 2
run c vlo 2
run lo1 lo 1
run lo2 lo 2
# The VO's local BA one frame after its keyframe ([vo.mapping] mapping_delay; 2 above, where one thread
# runs its two passes in two frames): on the mapping thread for one frame of tracking.
run d1 vlo 1 --set vo.mapping.mapping_delay=1
run d2 vlo 2 --set vo.mapping.mapping_delay=1
# same A B FILE...: the files are byte-identical in runs A and B
same() {
	local a=$1 b=$2
	shift 2
	for f in "$@"; do
		[ -s $a/$f ] || fail "$a/$f missing"
		cmp -s $a/$f $b/$f || fail "$f differs between runs $a and $b"
	done
}
same a b trajectory_vlo.tum trajectory_vo.tum map.pcd
same b c trajectory_vlo.tum trajectory_vo.tum map.pcd run.ini
same lo1 lo2 trajectory_lo.tum map.pcd
same d1 d2 trajectory_vlo.tum trajectory_vo.tum map.pcd
cmp -s <(grep -v '^threads ' a/run.ini) <(grep -v '^threads ' b/run.ini) || fail "run.ini differs beyond threads"
# frames.csv without the timing columns (ms_*): python's csv module, as frames.csv quotes cells with commas.
untimed() {
	python3 - "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
keep = [i for i, name in enumerate(rows[0]) if not name.startswith("ms_")]
for row in rows:
    print(",".join(row[i] for i in keep))
PY
}
[ "$(untimed a/frames.csv | head -1 | tr ',' '\n' | grep -c .)" -ge 20 ] || fail "frames.csv has too few columns"
# untimed_json RUN: summary.json without its timing, the run's folder in paths named "run"
untimed_json() { grep -vE '"(seconds|ms_per_frame|mean_ms|p95_ms|max_ms)"' $1/summary.json | sed "s|\"$1/|\"run/|"; }
for pair in a:b b:c lo1:lo2 d1:d2; do
	x=${pair%:*} y=${pair#*:}
	cmp -s <(untimed $x/frames.csv) <(untimed $y/frames.csv) || fail "frames.csv (timing columns apart) differs: $x, $y"
	untimed_json $x > x.json
	untimed_json $y > y.json
	cmp -s x.json y.json || fail "summary.json (timing apart) differs: $x, $y: $(diff x.json y.json | head -4)"
done
finish determinism
