#!/usr/bin/env bash
# vlo-run with lidar_odometry = icp (KISS-ICP's method, modules/icp): every shipped INI loads with it in
# every mode, a short simulated drive is tracked in modes lo and vlo within bounds, and a bad [icp]
# value fails cleanly naming its key.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

frames=40
"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames $frames --seed 5 --no-realism --out drive.rawlog --quiet || fail "vlo-sim failed"

# Five frames: mode vo needs its two-view initialisation, which the first pair of frames may or may
# not give (too few points triangulated by a few: the features of a frame decide it).
for ini in "$INI"/*.ini; do
	for mode in lo vlo vo; do
		"$BIN/vlo-run" --rawlog drive.rawlog --ini "$ini" --out "load_$mode" --overwrite --quiet --set pipeline.lidar_odometry=icp \
			--set pipeline.mode=$mode --set pipeline.max_frames=5 --set pipeline.snapshots=false 2> err.txt ||
			fail "$(basename "$ini") mode $mode: $(cat err.txt)"
	done
done

# run_case MODE MAX_T_ERR_PCT MAX_ATE_M
run_case() {
	local mode=$1 terr=$2 ate=$3 out="out_$1"
	"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out "$out" --gt drive.gt.tum --quiet \
		--set pipeline.lidar_odometry=icp --set pipeline.mode="$mode" || { fail "$mode: vlo-run failed"; return; }
	local traj="$out/trajectory_$mode.tum"
	[ "$(wc -l < "$traj")" -eq $frames ] || fail "$mode: trajectory does not have $frames poses"
	grep -q "^lidar_odometry *= *icp" "$out/run.ini" || fail "$mode: run.ini does not name icp"
	grep -q "^\[icp\]" "$out/run.ini" || fail "$mode: run.ini lacks the [icp] section"
	! grep -q ',skipped,' "$out/frames.csv" || fail "$mode: skipped frames"
	"$BIN/vlo-eval" --gt drive.gt.tum --est "$traj" --kitti-lengths 10,20,30 --json "$mode.json" > /dev/null ||
		{ fail "$mode: vlo-eval failed"; return; }
	echo "icp $mode: kitti_t_err_pct=$(jv "$mode.json" kitti_t_err_pct) ate_rmse_m=$(jv "$mode.json" ate_rmse_m)"
	below "$(jv "$mode.json" kitti_t_err_pct)" "$terr" || fail "$mode: KITTI t_err above $terr %"
	below "$(jv "$mode.json" ate_rmse_m)" "$ate" || fail "$mode: ATE above $ate m"
}
# Bounds about 3x the measured values (lo 0.37 % and 0.028 m, vlo 0.17 % and 0.018 m).
run_case lo 1.0 0.1
run_case vlo 0.6 0.06
[ "$(grep -c ',external,' out_vlo/frames.csv)" -gt $((frames / 2)) ] || fail "vlo: the VO's guess was not used"

rm -rf bad_out
"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out bad_out --quiet \
	--set pipeline.lidar_odometry=icp --set icp.voxel_size=0 > /dev/null 2> err.txt && fail "bad [icp] value: exit 0"
grep -qF -- "--set icp.voxel_size=0: must be > 0" err.txt || fail "bad [icp] value: $(cat err.txt)"
[ ! -e bad_out/trajectory_lo.tum ] && [ ! -e bad_out/trajectory_vlo.tum ] || fail "bad [icp] value: trajectory left behind"

finish run_icp
