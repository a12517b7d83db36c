#!/usr/bin/env bash
# vlo-sim --traffic end to end: a short urban drive with 5 moving vehicles, byte-identical when rerun
# with the same seed and different without traffic, and the full system (vlo-run mode vlo) through it.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

expect_exit2 "negative traffic" "--traffic" bad "$BIN/vlo-sim" --traffic -1 --frames 2 --out bad/x.rawlog
expect_exit2 "traffic not a number" "--traffic" bad "$BIN/vlo-sim" --traffic many --frames 2 --out bad/x.rawlog
expect_exit2 "no returns without traffic" "--traffic-without-returns" bad "$BIN/vlo-sim" --traffic-without-returns --frames 2 --out bad/x.rawlog

FRAMES=50
"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames $FRAMES --seed 21 --no-realism --traffic 5 --out drive.rawlog > sim.txt ||
	{ cat sim.txt; echo "FAIL: vlo-sim --traffic 5"; exit 1; }
grep -E 'traffic of 5 vehicles, [0-9.]+ within 50 m' sim.txt || fail "vlo-sim did not report the traffic"
# Same seed, same bytes; without traffic other scans and images (short drives of their own).
mkdir -p a b c
for d in a b; do
	"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames 2 --seed 21 --traffic 5 --out $d/t.rawlog --quiet || fail "vlo-sim rerun ($d)"
done
"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames 2 --seed 21 --out c/t.rawlog --quiet || fail "vlo-sim without traffic"
cmp a/t.rawlog b/t.rawlog || fail "same seed and traffic, different rawlogs"
for f in a/t_Images/*.pgm; do cmp "$f" "b/t_Images/$(basename "$f")" || fail "$f differs"; done
cmp -s a/t.rawlog c/t.rawlog && fail "traffic changed nothing in the scans"
cmp a/t.gt.tum c/t.gt.tum || fail "traffic changed the ground truth"

"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out vlo --gt drive.gt.tum --quiet \
	--set pipeline.mode=vlo --set pipeline.snapshots=false || fail "vlo-run mode vlo through traffic"
[ "$(wc -l < vlo/trajectory_vlo.tum)" -eq $FRAMES ] || fail "trajectory_vlo.tum does not have $FRAMES poses"
"$BIN/vlo-eval" --gt drive.gt.tum --est vlo/trajectory_vlo.tum --kitti-lengths 10,20,30 --json vlo.json > /dev/null ||
	fail "vlo-eval of the VLO trajectory"
echo "vlo through traffic: kitti_t_err_pct=$(jv vlo.json kitti_t_err_pct) ate_rmse_m=$(jv vlo.json ate_rmse_m)"
below "$(jv vlo.json kitti_t_err_pct)" 1.5 || fail "VLO KITTI t_err above 1.5 % through traffic"
below "$(jv vlo.json ate_rmse_m)" 0.3 || fail "VLO ATE above 0.3 m through traffic"

finish sim_traffic
