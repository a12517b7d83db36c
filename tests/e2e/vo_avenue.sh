#!/usr/bin/env bash
# The VO through vlo-sim's avenue (doc/VO.md "Fast foliage"): close foliage at 11-13 m/s with the realistic
# camera. With weak frames (the default) it is never lost and its Sim(3) ATE stays small; with them off
# (ORB-SLAM2's rule, LOST below 30 inliers) the same drive loses track and most of its frames.
# The loss hangs on three frames of 36-40 inliers (so the test's threshold is 41, below): of 67 drives tried
# (seeds 1-6 at 50-100 frames, with a VLP-16 at 40-100, in sun and shade at 100) only seed 1, overcast, at 100
# frames came near ORB-SLAM2's 30. A shorter drive is another road and world; the VO reads the camera only,
# but a VLP-16 drive's images differ in a few grey levels.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

FRAMES=100
"$BIN/vlo-sim" --scenario avenue --foliage-depth 0.3 --frames $FRAMES --seed 1 --out av.rawlog --quiet > /dev/null ||
	{ echo "FAIL: vlo-sim avenue"; exit 1; }

# run NAME [--set ...]: mode vo over the avenue, scored with Sim(3) alignment into NAME.json
run() {
	local name=$1
	shift
	"$BIN/vlo-run" --rawlog av.rawlog --ini "$INI/sim-hdl64.ini" --out "$name" --quiet --set pipeline.mode=vo \
		--set pipeline.snapshots=false "$@" > /dev/null || fail "vlo-run $name"
	"$BIN/vlo-eval" --gt av.gt.tum --est "$name/trajectory_vo.tum" --align sim3 --metric ate --json "$name.json" \
		--quiet > /dev/null || fail "vlo-eval $name"
}
# count NAME WHAT: frames of NAME/frames.csv tracked (state OK), lost (OK then LOST: one loss each),
# or weak (kept with fewer inliers than min_local_inliers)
count() {
	case $2 in
	tracked) column "$1/frames.csv" vo_state | grep -c '^OK$' ;;
	lost) column "$1/frames.csv" vo_state | awk '$0 == "LOST" && prev == "OK" { n++ } { prev = $0 } END { print n + 0 }' ;;
	weak) column "$1/frames.csv" vo_reason | grep -c '; weak: ' ;;
	esac
}

# Both runs take a frame as LOST below 41 inliers, not 30: the drive's weakest frame (40) has 36, and 41
# leaves it 5 inliers of margin (a grey level elsewhere must not decide the test). With the default 30
# neither run loses track: since its trunks are round (24 faces, not 7) the drive's images changed and its
# weakest frame went from 29 to 36 inliers.
run weak --set vo.tracking.min_local_inliers=41
run strict --set vo.tracking.min_local_inliers=41 --set vo.tracking.min_weak_inliers=0
for r in weak strict; do
	echo "$r: $(count $r lost) losses, $(count $r tracked) / $FRAMES tracked, $(count $r weak) weak, Sim(3) ATE $(jv $r.json ate_rmse_m) m"
done

# Measured: no loss, 91 tracked (the first map takes 9 frames), three weak frames (31, 40, 42), ATE 0.163 m.
[ "$(count weak lost)" -eq 0 ] || fail "weak frames: lost track"
[ "$(count weak tracked)" -ge 88 ] || fail "weak frames: fewer than 88 frames tracked"
[ "$(count weak weak)" -ge 1 ] || fail "weak frames: none used (the drive no longer tests them)"
below "$(jv weak.json ate_rmse_m)" 0.25 || fail "weak frames: Sim(3) ATE above 0.25 m"
# Measured: lost at frame 31, 22 tracked.
[ "$(count strict lost)" -ge 1 ] || fail "without weak frames: never lost (the drive no longer tests them)"
[ "$(count strict tracked)" -le 60 ] || fail "without weak frames: more than 60 frames tracked"
# Up to the first weak frame both runs are the same (the rule only replaces a LOST).
first=$(column weak/frames.csv vo_reason | grep -n '; weak: ' | head -1 | cut -d: -f1)
before=$(column weak/frames.csv vo_state | head -n $((${first:-1} - 1)) | grep -c '^OK$')
cmp -s <(head -n "$before" weak/trajectory_vo.tum) <(head -n "$before" strict/trajectory_vo.tum) ||
	fail "the $before poses before the first weak frame differ"

finish vo_avenue
