#!/usr/bin/env bash
# vlo-batch end to end: a tiny plan (one simulated drive, generated on demand; configurations lo, vo and
# a broken one) run here with two processes, then the same plan as job lines through GNU parallel and
# --collect: same numbers. Bad plans fail before anything runs.
set -u
BIN="${VLO_BIN:?}"
. "${VLO_SRC:?}/tests/e2e/lib/common.sh"
# csv_field FILE SEQUENCE CONFIG TRAJECTORY COLUMN: one value of results.csv
csv_field() {
	awk -F, -v s="$2" -v c="$3" -v t="$4" -v col="$5" \
		'NR == 1 { for (i = 1; i <= NF; i++) n[$i] = i; next } $1 == s && $2 == c && $3 == t { print $n[col] }' "$1"
}
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 < b + 0) }'; }

# The test's own INIs, so that it does not depend on what the shipped ones select: vlo-run refuses the
# sections of modules that a mode does not run, so the camera-only configuration has its own.
printf '[pipeline]\nmode = lo\n[loam.scan]\nring_model = hdl64\nmin_range = 2.0\nmax_range = 120.0\n' > hdl64.ini
printf '[pipeline]\nmode = vo\n' > camera.ini
cat > tiny.ini <<PLAN
# 25 frames, 2.5 s of urban drive: KITTI segments of 5 and 10 m
[plan]
data = data
kitti_lengths = 5,10

[sequence tiny]
ini = hdl64.ini
sim = --scenario urban --lidar hdl64 --frames 25 --seed 5

[config lo]
set = pipeline.mode=lo pipeline.snapshots=false

# camera only: an INI without LOAM sections
[config vo]
ini = camera.ini
set = pipeline.mode=vo pipeline.snapshots=false
align = sim3

[config broken]
set = pipeline.mode=lo loam.scan.ring_modle=hdl64
PLAN

# Bad plans: one line naming the plan and the key, exit 2, nothing run or written.
expect_bad() {
	local name=$1 text=$2 plan=$3
	"$BIN/vlo-batch" --plan "$plan" --out bad_out > /dev/null 2> err.txt
	local rc=$?
	[ $rc -eq 2 ] || fail "$name: exit code $rc, expected 2"
	[ "$(wc -l < err.txt)" -eq 1 ] || fail "$name: stderr is not one line: $(cat err.txt)"
	grep -qF -- "$text" err.txt || fail "$name: stderr lacks '$text': $(cat err.txt)"
	[ ! -e bad_out ] || fail "$name: output folder created"
	[ ! -e data ] || fail "$name: data generated"
	echo "ok: $name: $(cat err.txt)"
}
sed 's/^align = sim3/align = sim4/' tiny.ini > bad_align.ini
sed 's/^kitti_lengths/kitti_length/' tiny.ini > bad_key.ini
sed 's/^\[config broken\]/[config lo]/' tiny.ini > bad_twice.ini
grep -v '^sim = ' tiny.ini > bad_nosim.ini
expect_bad "bad align" "bad_align.ini: [config vo] align: 'sim4' is not one of se3, sim3, none (did you mean sim3?)" bad_align.ini
expect_bad "unknown key" "bad_key.ini: [plan]: unknown key 'kitti_length'" bad_key.ini
expect_bad "repeated config" "bad_twice.ini: line 19: section [config lo] given twice" bad_twice.ini
expect_bad "no data" "bad_nosim.ini: [sequence tiny] rawlog: $W/data/tiny.rawlog does not exist" bad_nosim.ini
expect_bad "missing plan" "nope.ini: cannot open the plan file" nope.ini

# 1. Run here: generate the drive, 3 runs two at a time; the broken one fails, the others complete.
start=$(date +%s)
"$BIN/vlo-batch" --plan tiny.ini --out out1 --jobs 2 > out1.log 2> out1.err
rc=$?
cat out1.err
[ $rc -eq 1 ] || fail "local run: exit code $rc, expected 1 (one configuration is broken)"
[ -s data/tiny.rawlog ] && [ -s data/tiny.gt.tum ] || fail "drive not generated"
grep -q "^vlo-batch: generated 1/1 tiny: ok, " out1.err || fail "no progress line for the generation"
[ "$(cat data/tiny.sim.txt)" = "--scenario urban --lidar hdl64 --frames 25 --seed 5" ] || fail "no record of the sim arguments"
# A plan whose sim line changed refuses the old drive instead of running on it.
sed 's/--seed 5$/--seed 6/' tiny.ini > changed.ini
"$BIN/vlo-batch" --plan changed.ini --out changed_out > /dev/null 2> err.txt && fail "changed sim line: accepted the old drive"
grep -qF "data/tiny.rawlog: was generated with vlo-sim --scenario urban --lidar hdl64 --frames 25 --seed 5 but the plan's sim line says" err.txt ||
	fail "changed sim line: $(cat err.txt)"
[ "$(grep -c '^vlo-batch: run [123]/3 tiny/' out1.err)" -eq 3 ] || fail "not one progress line per run"
grep -q "^vlo-batch: run ./3 tiny/broken: FAILED, .*unknown key 'ring_modle'" out1.err || fail "failure not reported"
for f in plan.ini results.md results.csv snapshots/tiny.png runs/tiny/lo/trajectory_lo.tum runs/tiny/vo/aligned_vo.tum \
	runs/tiny/broken/vlo-run.err; do
	[ -s "out1/$f" ] || fail "out1/$f missing"
done
cat out1/results.md
t_err=$(csv_field out1/results.csv tiny lo lo kitti_t_err_pct)
ate_lo=$(csv_field out1/results.csv tiny lo lo ate_rmse_m)
ate_vo=$(csv_field out1/results.csv tiny vo vo ate_rmse_m)
echo "lo: t_err $t_err %, ATE $ate_lo m; vo (Sim(3)): ATE $ate_vo m"
below "$t_err" 5 || fail "lo: KITTI t_err '$t_err' not below 5 %"
below "$ate_lo" 0.3 || fail "lo: ATE '$ate_lo' not below 0.3 m"
below "$ate_vo" 1.0 || fail "vo: Sim(3) ATE '$ate_vo' not below 1 m"
grep -q "^| lo / lo | [0-9.]* / [0-9.]* |$" out1/results.md || fail "results.md: no KITTI row for lo"
grep -q "^| vo / vo | sim3 | [0-9.]* / [0-9.]* |$" out1/results.md || fail "results.md: no ATE/ARE row for vo"
grep -q "^| broken | failed |$" out1/results.md || fail "results.md: broken is not failed"
grep -q "^| tiny / broken | vlo-run: error: --set loam.scan.ring_modle=hdl64: unknown key 'ring_modle'" out1/results.md || fail "results.md: no failure line"
grep -q "^| lo | [0-9.]* |$" out1/results.md || fail "results.md: no timing for lo"
grep -qF -- "- [tiny / lo](runs/tiny/lo/report.md)" out1/results.md || fail "results.md: no link to lo's report.md"
grep -qF "runs/tiny/broken/report.md" out1/results.md && fail "results.md: links a report the failed run never wrote"
[ "$(csv_field out1/results.csv tiny broken '' status)" = failed ] || fail "results.csv: broken is not failed"
# A 25-frame drive never comes back to a place: 0 revisits, no number and no revisit table.
[ "$(csv_field out1/results.csv tiny lo lo revisit_pairs)" = 0 ] || fail "results.csv: tiny/lo revisit_pairs is not 0"
[ -z "$(csv_field out1/results.csv tiny lo lo revisit_t_rmse_m)" ] || fail "results.csv: a revisit error without a revisit"
grep -q "^## Revisits" out1/results.md && fail "results.md: a revisit table for a drive without revisits"
echo "local run: $(($(date +%s) - start)) s"

# --collect again gives the same files.
cp out1/results.csv first.csv
"$BIN/vlo-batch" --collect out1 > /dev/null
[ $? -eq 1 ] || fail "--collect: exit code is not 1 with a failed run"
cmp -s first.csv out1/results.csv || fail "--collect changed results.csv"

# 2. The same plan as job lines; data exist, so nothing to generate.
"$BIN/vlo-batch" --plan tiny.ini --out out2 --emit-jobs jobs.txt --emit-data data.txt > emit.log || fail "--emit-jobs failed"
[ "$(wc -l < jobs.txt)" -eq 3 ] || fail "jobs.txt does not have 3 lines"
[ ! -s data.txt ] || fail "data.txt is not empty although the drive exists"
grep -q "^mkdir -p $W/out2/runs/tiny/lo && cd $W/out2/runs/tiny/lo || exit 1; " jobs.txt || fail "unexpected job line: $(head -1 jobs.txt)"
[ -s out2/plan.ini ] && [ ! -e out2/runs ] || fail "--emit-jobs must write plan.ini and run nothing"
# A missing drive becomes a data line that generates it.
sed 's/^\[sequence tiny\]/[sequence other]/' tiny.ini > other.ini
"$BIN/vlo-batch" --plan other.ini --out out3 --emit-data other-data.txt > /dev/null || fail "--emit-data failed"
grep -qF "$BIN/vlo-sim --scenario urban --lidar hdl64 --frames 25 --seed 5 --out $W/data/other.rawlog --quiet" other-data.txt ||
	fail "unexpected data line: $(cat other-data.txt)"

# The shipped plans are valid and expand to 7 drives x 6 (paper table), 6 drives x 10 (ablation) and 5 x 2 (loop) runs. Their
# KITTI drive needs odometry 00's ground-truth poses in the data folder, as doc/BATCH.md says.
if [ -f "$VLO_DATA/kitti_gt_poses.tar.xz" ]; then
	mkdir -p shipped && tar -xJf "$VLO_DATA/kitti_gt_poses.tar.xz" -C shipped kitti_gt_poses/00.txt
	for p in paper-table:42:7 ablation:60:6 loop:10:5; do
		name=${p%%:*} n=${p#*:}; drives=${n#*:}; n=${n%:*}
		"$BIN/vlo-batch" --plan "$VLO_SRC/ini/experiments/$name.ini" --out "shipped/$name" --data shipped \
			--emit-jobs "shipped/$name.jobs" --emit-data "shipped/$name.data" > /dev/null || fail "$name.ini: not a valid plan"
		[ "$(wc -l < "shipped/$name.jobs")" -eq "$n" ] || fail "$name.ini: not $n jobs"
		[ "$(wc -l < "shipped/$name.data")" -eq "$drives" ] || fail "$name.ini: not $drives drives to generate"
	done
	grep -qF -- "--trajectory $W/shipped/kitti_gt_poses/00.txt --frames 1450 --seed 10 --out $W/shipped/kitti00_hdl64.rawlog" \
		shipped/paper-table.data || fail "paper-table.ini: unexpected KITTI drive line"
	grep -qF -- "--ini $VLO_SRC/ini/vo-kitti.ini" shipped/paper-table.jobs || fail "paper-table.ini: vo_mono without its INI"
	echo "ok: shipped plans: 42, 60 and 10 jobs, 7, 6 and 5 drives"
else
	skip "$VLO_DATA/kitti_gt_poses.tar.xz not found: shipped plans not checked"
fi

if ! command -v parallel > /dev/null; then
	skip "GNU parallel is not installed (scripts/install-deps.sh installs it): emitted jobs not run"
else
	parallel --will-cite -j2 < jobs.txt
	[ $? -eq 1 ] || fail "parallel: expected exactly one failed job"
	"$BIN/vlo-batch" --collect out2 > collect.log
	[ $? -eq 1 ] || fail "--collect out2: exit code is not 1 with a failed run"
	# Everything but the timing (and the error text, which names no run folder) must match.
	cut -d, -f1-14 out1/results.csv > a.csv
	cut -d, -f1-14 out2/results.csv > b.csv
	diff a.csv b.csv || fail "results.csv differs between the local run and parallel + --collect"
	[ -s out2/snapshots/tiny.png ] || fail "out2: no snapshot"
	echo "parallel + --collect: same numbers"
fi

finish batch
