#!/usr/bin/env bash
# Loop closure end to end (doc/LOOP.md): a realistic VLP-16 drive around vlo-sim's circuit, a little more
# than one lap, is closed (the revisits' error and the ATE far below the odometry's) and leaves its
# outputs; a street of identical facades, seen again every few metres but never revisited, gets no loop.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

# The circuit: 515 m a lap (right lane), about 650 frames; 720 frames come back over the first 50 m.
"$BIN/vlo-sim" --scenario loop --lidar vlp16 --frames 720 --seed 3 --out loop.rawlog --quiet || fail "vlo-sim loop failed"
"$BIN/vlo-run" --rawlog loop.rawlog --ini "$INI/vlp16.ini" --out out_loop --gt loop.gt.tum --quiet \
	--set pipeline.mode=lo --set pipeline.sample_frame_every=0 || fail "vlo-run on the circuit failed"
for f in trajectory_lo.tum trajectory_slam.tum frames.csv map.pcd summary.json snapshots/topdown.png; do
	[ -s "out_loop/$f" ] || fail "circuit: $f missing"
done
[ "$(wc -l < out_loop/trajectory_slam.tum)" -eq 720 ] || fail "circuit: trajectory_slam.tum does not have 720 poses"
accepted=$(jv out_loop/summary.json loops_accepted)
[ "${accepted:-0}" -ge 5 ] || fail "circuit: $accepted loops accepted, expected at least 5"
[ "$(column out_loop/frames.csv loop_accepted | grep -c '^1$')" -eq "$accepted" ] ||
	fail "circuit: frames.csv's loop_accepted does not count $accepted loops"
for t in lo slam; do
	"$BIN/vlo-eval" --gt loop.gt.tum --est "out_loop/trajectory_$t.tum" --metric all --json "loop_$t.json" > /dev/null ||
		fail "vlo-eval $t failed"
done
lo_rev=$(jv loop_lo.json revisit_t_rmse_m) slam_rev=$(jv loop_slam.json revisit_t_rmse_m)
lo_ate=$(jv loop_lo.json ate_rmse_m) slam_ate=$(jv loop_slam.json ate_rmse_m)
echo "circuit: $accepted loops; revisit error $lo_rev -> $slam_rev m RMS over $(jv loop_slam.json revisit_pairs) pairs; ATE $lo_ate -> $slam_ate m"
below "$slam_rev" 0.05 || fail "circuit: revisit error $slam_rev m, above 0.05 m"
below "$slam_ate" "$(awk -v a="$lo_ate" 'BEGIN { print a / 3 }')" || fail "circuit: ATE $slam_ate m is not a third of the odometry's $lo_ate m"
cmp -s out_loop/trajectory_lo.tum out_loop/trajectory_slam.tum && fail "circuit: the loop-closed trajectory is the odometry's"

# The odometry's outputs do not depend on the loop closure.
"$BIN/vlo-run" --rawlog loop.rawlog --ini "$INI/vlp16.ini" --out out_noloop --quiet --set pipeline.mode=lo \
	--set pipeline.loop_closure=false --set pipeline.snapshots=false || fail "vlo-run without loop closure failed"
cmp -s out_loop/trajectory_lo.tum out_noloop/trajectory_lo.tum || fail "loop closure changed trajectory_lo.tum"
[ ! -e out_noloop/trajectory_slam.tum ] || fail "trajectory_slam.tum without loop closure"

# Identical facades: the descriptor finds the same place again and again; the drift gate refuses them all.
"$BIN/vlo-sim" --scenario facades --lidar vlp16 --frames 300 --seed 4 --out facades.rawlog --quiet || fail "vlo-sim facades failed"
"$BIN/vlo-run" --rawlog facades.rawlog --ini "$INI/vlp16.ini" --out out_facades --quiet --set pipeline.mode=lo \
	--set pipeline.snapshots=false || fail "vlo-run on the facades failed"
echo "facades: $(jv out_facades/summary.json loop_candidates) candidates, $(jv out_facades/summary.json loops_accepted) accepted"
[ "$(jv out_facades/summary.json loops_accepted)" = 0 ] || fail "facades: a false loop was accepted"

finish loop_closure
