#!/usr/bin/env bash
# vlo-eval end to end: JSON keys and values on constructed trajectories, and bad input
# (one line on stderr, non-zero exit, no JSON left behind).
set -u
EVAL="${VLO_BIN:?}/vlo-eval"
. "${VLO_SRC:?}/tests/e2e/lib/common.sh"
# near ACTUAL EXPECTED TOL
near() { awk -v a="$1" -v e="$2" -v t="$3" 'BEGIN { d = a - e; if (d < 0) d = -d; exit !(a != "" && d <= t) }'; }
expect_near() { near "$(jv "$1" "$2")" "$3" "$4" || fail "$1: $2 = $(jv "$1" "$2"), expected $3 +- $4"; }
expect_eq() { [ "$(jv "$1" "$2")" = "$3" ] || fail "$1: $2 = $(jv "$1" "$2"), expected $3"; }

# N poses 0.9 m apart along x, 10 Hz, every EVERY-th one, positions scaled by S; yaw rate W rad/frame.
make_tum() { # N EVERY S W OUT
	awk -v n="$1" -v every="$2" -v s="$3" -v w="$4" 'BEGIN {
		x = 0; y = 0; yaw = 0
		for (i = 0; i < n; i++) {
			if (i % every == 0) printf "%.6f %.9f %.9f 0 0 0 %.12f %.12f\n", i * 0.1, s * x, s * y, sin(yaw / 2), cos(yaw / 2)
			x += 0.9 * cos(yaw); y += 0.9 * sin(yaw); yaw += w
		}
	}' > "$5"
}

# expect_bad NAME EXPECTED_TEXT ARGS...: non-zero exit, one stderr line containing the text, no JSON
expect_bad() {
	local name="$1" text="$2"
	shift 2
	rm -f bad.json bad.json.partial
	"$EVAL" "$@" --json bad.json > /dev/null 2> err.txt
	local rc=$?
	[ $rc -ne 0 ] || fail "$name: exit code 0"
	[ "$(wc -l < err.txt)" -eq 1 ] || fail "$name: stderr is not one line: $(cat err.txt)"
	grep -qF -- "$text" err.txt || fail "$name: stderr lacks '$text': $(cat err.txt)"
	[ ! -e bad.json ] && [ ! -e bad.json.partial ] || fail "$name: JSON left behind"
	echo "ok (rc $rc): $name: $(cat err.txt)"
}

"$EVAL" --help | grep -q -- "--kitti-calib" || fail "--help"

# 1. Straight 1349 m drive, estimate 5 % too long, 1 Hz ground truth: Sim(3) removes the scale;
#    KITTI t_err is 5 % times the devkit's overshoot factor (see test_kitti_metric.cpp).
make_tum 1500 10 1 0 gt1hz.tum
make_tum 1500 1 1.05 0 est.tum
"$EVAL" --gt gt1hz.tum --est est.tum --align sim3 --json scaled.json > scaled.txt || fail "scaled: exit code"
cat scaled.txt
expect_eq scaled.json n_matched 1491   # the last 9 estimates are after the last 1 Hz sample
expect_near scaled.json ate_rmse_m 0 1e-6
expect_near scaled.json are_rmse_deg 0 1e-4
expect_near scaled.json sim3_scale 0.952380952 1e-6
expect_near scaled.json kitti_t_err_pct 5.015 0.01
expect_near scaled.json kitti_r_err_deg_per_m 0 1e-6
grep -q '"kitti_r_err_deg_per_100m": ' scaled.json || fail "kitti_r_err_deg_per_100m missing"
"$EVAL" --gt gt1hz.tum --est est.tum --align sim3 --write-aligned aligned.tum > /dev/null || fail "write-aligned: exit code"
[ "$(wc -l < aligned.tum)" -eq 1491 ] || fail "aligned.tum should hold the 1491 matched poses"
# aligned pose 1000 (t = 100 s) lies on the ground truth's x = 900 m
awk 'NR == 1001 { d = $2 - 900; if (d < 0) d = -d; exit !(d < 1e-4) }' aligned.tum || fail "aligned.tum: $(sed -n 1001p aligned.tum)"
"$EVAL" --gt gt1hz.tum --est est.tum --align se3 --metric ate --json se3.json > /dev/null || fail "se3: exit code"
near "$(jv se3.json ate_rmse_m)" 10 40 || fail "se3 ATE of a 5 % scaled 1.3 km line should be metres: $(jv se3.json ate_rmse_m)"
expect_eq se3.json kitti_t_err_pct null

# 2. Identical curved trajectories: zero everywhere; rig given as 12 numbers.
make_tum 1500 1 1 0.002 curve.tum
"$EVAL" --gt curve.tum --est curve.tum --cam0-T-vehicle "0 -1 0 0, 0 0 -1 -0.08, 1 0 0 -0.27" --json same.json > /dev/null \
	|| fail "identical: exit code"
for k in ate_rmse_m kitti_t_err_pct; do expect_near same.json $k 0 1e-6; done
expect_near same.json kitti_r_err_deg_per_m 0 1e-5
grep -q '"kitti_frame": "camera 0"' same.json || fail "kitti_frame should be camera 0"

# 3. Short trajectory: KITTI null with the reason, ATE still there; translation-only ground truth.
make_tum 60 1 1 0.01 short.tum
"$EVAL" --gt short.tum --est short.tum --json short.json > short.txt || fail "short: exit code"
expect_eq short.json kitti_t_err_pct null
expect_eq short.json kitti_segments 0
grep -q '"kitti_note": "no segment' short.json || fail "short: no kitti_note"
grep -q "n/a: no segment" short.txt || fail "short: table lacks the reason"
make_tum 60 1 1 0 short_straight.tum
"$EVAL" --gt short_straight.tum --est short.tum --gt-translation-only --json tonly.json > /dev/null || fail "translation-only: exit"
expect_eq tonly.json are_rmse_deg null
grep -q '"ate_rmse_m": [0-9]' tonly.json || fail "translation-only: ATE missing"

# 3b. --plots with two estimates of the 1349 m line (5 % and 2 % too long): the devkit's four plots and
#     one ATE view each; the curves' numbers are checked in test_viz (EvalPlots).
make_tum 1500 1 1 0 gt10hz.tum
make_tum 1500 1 1.02 0 est2.tum
"$EVAL" --gt gt10hz.tum --est est.tum --est est2.tum --plots plots > plots.txt || fail "plots: exit code"
grep -q "== est2 ==" plots.txt || fail "plots: no table per estimate"
for f in kitti_translation_vs_length kitti_rotation_vs_length kitti_translation_vs_speed kitti_rotation_vs_speed \
	ate_est ate_est2; do
	[ "$(head -c 4 "plots/$f.png" | tail -c 3)" = PNG ] || fail "plots: $f.png missing or not a PNG"
done
[ "$(ls plots | wc -l)" -eq 6 ] || fail "plots: expected 6 files, got $(ls plots)"
grep -q "^vlo-eval: plot plots/ate_est2.png$" plots.txt || fail "plots: no 'vlo-eval: plot' line: $(cat plots.txt)"

# 3c. Issue 34, defect 9: a drive too short for the devkit's plots gets the ATE view and a line saying why.
make_tum 60 1 1 0 short_gt.tum
make_tum 60 1 1.02 0 short_est.tum
"$EVAL" --gt short_gt.tum --est short_est.tum --plots short_plots > /dev/null 2> short.err || fail "short plots: exit code"
[ "$(ls short_plots)" = ate_short_est.png ] || fail "short plots: $(ls short_plots)"
grep -q "^vlo-eval: warning: --plots: no KITTI devkit plots: no segment: the ground-truth path .* is 53.1 m" short.err ||
	fail "short plots: no reason given: $(cat short.err)"

# 3d. Revisits: a 100 m square driven 1.5 times (1 m steps), the estimate 0.5 m off from the second lap on:
#     204 revisits (the second lap's 201 poses and the 3 poses within 3 m before the start), 0.5 m each across
#     the laps (test_revisit.cpp has the closed forms); the 1349 m line has none.
awk -v n=601 'BEGIN {
	for (k = 0; k < n; k++) {
		side = int(k / 100) % 4; m = k % 100; x = 0; y = 0
		if (side >= 1) x = 100; if (side >= 2) y = 100; if (side == 3) x = 0
		if (side == 0) x += m; else if (side == 1) y += m; else if (side == 2) x = 100 - m; else y = 100 - m
		yaw = 1.5707963267948966 * side
		printf "%.1f %.3f %.3f 0 0 0 %.12f %.12f\n", 0.1 * k, x, y, sin(yaw / 2), cos(yaw / 2)
	}
}' > square.tum
awk '{ if (NR > 400) { $2 += 0.3; $3 -= 0.4 } print }' square.tum > square_off.tum
"$EVAL" --gt square.tum --est square_off.tum --json square.json > square.txt || fail "square: exit code"
expect_eq square.json revisit_pairs 204
expect_near square.json revisit_t_max_m 0.5 1e-6
expect_near square.json revisit_t_rmse_m 0.496310 1e-5   # 0.5 sqrt(201 / 204)
grep -q "^  Revisit error, translation  0.4963 m RMS, 0.5000 m max  (204 pairs: within 3 m after >= 50 m of path)$" square.txt ||
	fail "square: no revisit line: $(cat square.txt)"
"$EVAL" --gt square.tum --est square_off.tum --metric revisit --revisit-radius 2.5 --revisit-min-path 60 --json square2.json \
	> /dev/null || fail "square --metric revisit: exit code"
expect_eq square2.json revisit_pairs 203
expect_eq square2.json ate_rmse_m null
"$EVAL" --gt gt10hz.tum --est est2.tum --json line.json > /dev/null || fail "line: exit code"
expect_eq line.json revisit_pairs 0
expect_eq line.json revisit_t_rmse_m null
grep -q '"revisit_note": "no revisit: ' line.json || fail "line: no revisit_note"

# 4. Bad input.
printf '0 0 0 0 0 0 0 1\n0.1 nan 0 0 0 0 0 1\n' > nan.tum
printf '0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 1\n' > short_line.tum
awk '{ $1 = $1 + 1000; print }' curve.tum > later.tum
printf 'P0: 1 0 0 0 0 1 0 0 0 0 1 0\n' > calib_no_tr.txt
expect_bad "missing file" "no-such.tum: cannot open file" --gt no-such.tum --est est.tum
expect_bad "NaN value" "nan.tum: line 2" --gt curve.tum --est nan.tum
expect_bad "short line" "short_line.tum: line 2: expected 8 numbers" --gt short_line.tum --est curve.tum
expect_bad "no overlap" "no pose overlaps the ground truth" --gt curve.tum --est later.tum
expect_bad "bad alignment" "unknown alignment 'sim2'" --gt curve.tum --est curve.tum --align sim2
expect_bad "bad metric" "unknown metric" --gt curve.tum --est curve.tum --metric speed
expect_bad "bad revisit radius" "--revisit-radius: must be a positive number" --gt curve.tum --est curve.tum --revisit-radius 0
expect_bad "bad revisit path" "--revisit-min-path: must be zero or a positive" --gt curve.tum --est curve.tum --revisit-min-path -5
expect_bad "calib without Tr" "calib_no_tr.txt: missing key 'Tr'" --gt curve.tum --est curve.tum --kitti-calib calib_no_tr.txt
expect_bad "bad rig" "expected 12 numbers" --gt curve.tum --est curve.tum --cam0-T-vehicle "1 0 0"
expect_bad "missing --est" "missing required option '--est'" --gt curve.tum
expect_bad "--json with two --est" "--json: needs a single --est" --gt curve.tum --est curve.tum --est curve.tum
touch not_a_dir
expect_bad "plot folder in a file" "not_a_dir/plots: cannot create the plot folder" --gt curve.tum --est curve.tum \
	--plots not_a_dir/plots
"$EVAL" --gt curve.tum --est curve.tum --json no-such-dir/x.json > /dev/null 2> err.txt && fail "unwritable JSON: exit 0"
[ ! -e no-such-dir ] || fail "unwritable JSON: created something"

finish eval_cli
