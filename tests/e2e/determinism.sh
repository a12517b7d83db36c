#!/usr/bin/env bash
# The same run twice (mode vlo, a short simulated drive) gives byte-identical outputs: trajectories, map.pcd,
# run.ini, and frames.csv and summary.json apart from their timing (ms_* columns; seconds, ms_per_frame and the stage_timings figures).
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --frames 40 --seed 9 --out drive.rawlog --quiet || fail "vlo-sim"
for r in a b; do
	"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out $r --quiet --set pipeline.mode=vlo \
		--set pipeline.snapshots=false > /dev/null || fail "vlo-run $r"
done
for f in trajectory_vlo.tum trajectory_vo.tum map.pcd run.ini; do
	[ -s a/$f ] || fail "$f missing"
	cmp -s a/$f b/$f || fail "$f differs between two identical runs"
done
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
cmp -s <(untimed a/frames.csv) <(untimed b/frames.csv) || fail "frames.csv (timing columns apart) differs"
grep -vE '"(seconds|ms_per_frame|mean_ms|p95_ms|max_ms)"' a/summary.json > a.json
grep -vE '"(seconds|ms_per_frame|mean_ms|p95_ms|max_ms)"' b/summary.json | sed 's|"b/|"a/|' > b.json
cmp -s a.json b.json || fail "summary.json (timing apart) differs: $(diff a.json b.json | head -4)"
finish determinism
