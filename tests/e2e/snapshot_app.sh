#!/usr/bin/env bash
# vlo-snapshot end to end: PNGs of the expected sizes from constructed trajectories and an ascii PCD
# map; with vlo-sim built, a camera frame with the projected scan; bad input gives one stderr line,
# exit code 2 and no PNG.
set -u
SNAP="${VLO_BIN:?}/vlo-snapshot"
. "${VLO_SRC:?}/tests/e2e/lib/common.sh"

# png_size FILE -> "W H" read from the IHDR chunk; empty if FILE is not a PNG.
png_size() {
	[ "$(head -c 8 "$1" 2> /dev/null | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || return
	od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%d %d\n", $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}
expect_png() { # FILE W H
	local s
	s="$(png_size "$1")"
	[ "$s" = "$2 $3" ] || fail "$1: size '$s', expected '$2 $3'"
	[ "$(stat -c %s "$1" 2> /dev/null || echo 0)" -gt 20000 ] || fail "$1: suspiciously small (blank?)"
}

# A 600 m drive with a left turn (10 Hz), and an estimate with 3 % scale error and yaw drift.
make_tum() { # SCALE YAWDRIFT OUT
	awk -v s="$1" -v d="$2" 'BEGIN {
		x = 0; y = 0; yaw = 0
		for (i = 0; i < 600; i++) {
			printf "%.2f %.6f %.6f 0 0 0 %.9f %.9f\n", 100 + i * 0.1, x, y, sin(yaw / 2), cos(yaw / 2)
			k = (i > 200 && i < 300) ? 0.0157 : 0; yaw += k + d; x += s * cos(yaw); y += s * sin(yaw)
		}
	}' > "$3"
}
make_tum 1 0 gt.tum
make_tum 1.03 0.0004 est.tum
# Ascii PCD: road points and two walls along the ground-truth path.
awk 'BEGIN { srand(1) } { x[NR] = $2; y[NR] = $3 } END {
	n = 0
	for (i = 2; i <= NR; i += 2) {
		dx = x[i] - x[i-1]; dy = y[i] - y[i-1]; l = sqrt(dx*dx + dy*dy); nx = -dy / l; ny = dx / l
		for (o = -12; o <= 12; o += 1) {
			h = (o < -10 || o > 10) ? 8 : 0.5
			for (z = 0; z < h; z += 0.5) { px[n] = x[i] + o * nx; py[n] = y[i] + o * ny; pz[n] = z - 1.73; n++ }
		}
	}
	print "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1"
	printf "WIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n", n, n
	for (k = 0; k < n; k++) printf "%.3f %.3f %.3f\n", px[k], py[k], pz[k]
}' gt.tum > map.pcd

"$SNAP" --help | grep -q -- "--rawlog" || fail "--help"

# 1. Top-down and 3D views.
"$SNAP" --traj est.tum --name "estimate" --gt gt.tum --map map.pcd --title "e2e" --out out/a > run.txt || fail "exit code"
cat run.txt
grep -q "^vlo-snapshot: wrote out/a/topdown.png" run.txt || fail "no 'wrote' line for topdown.png"
expect_png out/a/topdown.png 1200 1000
expect_png out/a/map3d.png 1600 1000
ls out/a | grep -q partial && fail "partial file left in out/a"

# 2. Two trajectories, default names, no ground truth: only the top-down view.
"$SNAP" --traj est.tum --traj gt.tum --out out/b > /dev/null || fail "two trajectories: exit code"
expect_png out/b/topdown.png 1200 1000
[ ! -e out/b/map3d.png ] || fail "map3d.png without --map"

# expect_bad NAME EXPECTED_TEXT ARGS...: exit code 2, one stderr line with the text, no PNG.
expect_bad() {
	local name="$1" text="$2"
	shift 2
	rm -rf bad
	"$SNAP" "$@" --out bad > /dev/null 2> err.txt
	local rc=$?
	[ $rc -eq 2 ] || fail "$name: exit code $rc, expected 2"
	[ "$(wc -l < err.txt)" -eq 1 ] || fail "$name: stderr is not one line: $(cat err.txt)"
	grep -qF -- "$text" err.txt || fail "$name: stderr lacks '$text': $(cat err.txt)"
	[ -z "$(ls bad 2> /dev/null)" ] || fail "$name: output left behind: $(ls bad)"
	echo "ok (rc $rc): $name: $(cat err.txt)"
}
printf 'FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 5\nHEIGHT 1\nPOINTS 5\nDATA binary\n1234' > truncated.pcd
printf '1 2 3 4 5 6 7\n' > short.tum
expect_bad "missing trajectory" "nope.tum: cannot open file" --traj nope.tum
expect_bad "malformed trajectory" "short.tum: line 1: expected 8 numbers" --traj short.tum
expect_bad "truncated map" "truncated.pcd: truncated" --traj est.tum --map truncated.pcd
expect_bad "not a PCD" "gt.tum: line 1:" --traj est.tum --map gt.tum
expect_bad "too many names" "2 names for 1 --traj files" --traj est.tum --name a --name b
expect_bad "nothing to draw" "nothing to draw"
expect_bad "frame without rawlog" "--frame: needs --rawlog" --traj est.tum --frame 3
expect_bad "unknown option" "unknown option '--colour'" --traj est.tum --colour red
expect_bad "missing rawlog" "nope.rawlog" --rawlog nope.rawlog

# 3. A camera frame with the projected scan (needs vlo-sim from the same build).
if [ -x "$VLO_BIN/vlo-sim" ]; then
	"$VLO_BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 3 --seed 2 --out sim.rawlog --quiet || fail "vlo-sim"
	"$SNAP" --rawlog sim.rawlog --frame 2 --traj sim.gt.tum --out out/c > run_c.txt || fail "rawlog: exit code"
	cat run_c.txt
	expect_png out/c/frame_000002.png 1241 440   # 376 image rows + 64-row legend panel
	expect_bad "frame beyond the end" "has only 3 frames" --rawlog sim.rawlog --frame 7
	# Issue 34, section 2: topdown.png was written, then --frame 7 failed and left it behind.
	expect_bad "frame beyond the end, after the top-down view" "has only 3 frames" --rawlog sim.rawlog --frame 7 \
		--traj sim.gt.tum
	[ ! -e bad ] || fail "the failed call left its folder"
	mkdir -p mine && echo keep > mine/notes.txt
	"$SNAP" --rawlog sim.rawlog --frame 7 --traj sim.gt.tum --out mine > /dev/null 2>&1 && fail "--frame 7 accepted"
	[ "$(ls mine)" = notes.txt ] || fail "a failed call into a folder of the user's: $(ls mine)"
else
	skip "$VLO_BIN/vlo-sim not built, no rawlog frame checked"
fi

finish snapshot_app
