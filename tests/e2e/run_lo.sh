#!/usr/bin/env bash
# vlo-run end to end, LiDAR-only (the A-LOAM baseline): short simulated drives (HDL-64 and VLP-16)
# must be tracked within error bounds and leave every output; bad input must fail cleanly.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

# run_case NAME LIDAR INI FRAMES MAX_T_ERR_PCT MAX_ATE_M
run_case() {
	local name=$1 lidar=$2 ini=$3 frames=$4 terr=$5 ate=$6
	"$BIN/vlo-sim" --scenario urban --lidar "$lidar" --frames "$frames" --seed 5 --no-realism --out "$name.rawlog" --quiet ||
		{ fail "$name: vlo-sim failed"; return; }
	"$BIN/vlo-run" --rawlog "$name.rawlog" --ini "$INI/$ini" --out "out_$name" --gt "$name.gt.tum" --quiet \
		--set pipeline.mode=lo ||
		{ fail "$name: vlo-run failed"; return; }
	for f in trajectory_lo.tum frames.csv map.pcd run.ini summary.json snapshots/topdown.png snapshots/map3d.png; do
		[ -s "out_$name/$f" ] || fail "$name: $f missing"
	done
	[ "$(wc -l < "out_$name/trajectory_lo.tum")" -eq "$frames" ] || fail "$name: trajectory does not have $frames poses"
	[ "$(wc -l < "out_$name/frames.csv")" -eq $((frames + 1)) ] || fail "$name: frames.csv does not have $frames rows"
	"$BIN/vlo-eval" --gt "$name.gt.tum" --est "out_$name/trajectory_lo.tum" --kitti-lengths 10,20,30 \
		--json "$name.json" > /dev/null || { fail "$name: vlo-eval failed"; return; }
	echo "$name: kitti_t_err_pct=$(jv "$name.json" kitti_t_err_pct) ate_rmse_m=$(jv "$name.json" ate_rmse_m)"
	below "$(jv "$name.json" kitti_t_err_pct)" "$terr" || fail "$name: KITTI t_err above $terr %"
	below "$(jv "$name.json" ate_rmse_m)" "$ate" || fail "$name: ATE above $ate m"
}
run_case hdl64 hdl64 sim-hdl64.ini 40 1.5 0.3
run_case vlp16 vlp16 vlp16.ini 40 3.0 0.5

# Verbosity: the table of times per stage unless --quiet, debug lines with --verbose; the final line always.
for v in "" --verbose --quiet; do
	rm -rf out_v
	"$BIN/vlo-run" --rawlog hdl64.rawlog --ini "$INI/sim-hdl64.ini" --out out_v --set pipeline.mode=lo \
		--set pipeline.max_frames=5 --set pipeline.snapshots=false $v > out.txt 2> err.txt || fail "vlo-run $v failed"
	grep -q "^vlo-run: 5 frames in" out.txt || fail "vlo-run $v: no final line: $(cat out.txt)"
	grep -q "^ms_lo_mapping .* 5$" err.txt && grep -q "^vlo-run: time per stage over 5 frames" err.txt &&
		grep -q "^wall time per frame: [0-9.]* ms with [12] threads\? (ms_total: each frame's own time" err.txt
	table=$?
	grep -q "^vlo-run: debug: mode lo" err.txt
	debug=$?
	case "$v" in
	"") [ $table -eq 0 ] && [ $debug -ne 0 ] || fail "default: $(cat err.txt)" ;;
	--verbose) [ $table -eq 0 ] && [ $debug -eq 0 ] || fail "--verbose: $(cat err.txt)" ;;
	--quiet) [ ! -s err.txt ] || fail "--quiet: stderr: $(cat err.txt)" ;;
	esac
done

# expect_bad NAME TEXT ARGS...: non-zero exit, one stderr line with TEXT, no output folder
expect_bad() {
	local name=$1 text=$2
	shift 2
	rm -rf bad_out
	"$BIN/vlo-run" --out bad_out --quiet "$@" > /dev/null 2> err.txt && fail "$name: exit code 0"
	[ "$(wc -l < err.txt)" -eq 1 ] || fail "$name: stderr is not one line: $(cat err.txt)"
	grep -qF -- "$text" err.txt || fail "$name: stderr lacks '$text': $(cat err.txt)"
	[ ! -e bad_out/trajectory_lo.tum ] || fail "$name: trajectory left behind"
	echo "ok: $name: $(cat err.txt)"
}
printf '[pipeline]\nmode = lo\n[loam.scan]\nring_modle = hdl64\n' > typo.ini
printf '[pipeline]\nmode = lo\nmax_time_diff = soon\n' > badvalue.ini
printf '[pipeline]\nmode = fast\n' > badmode.ini
printf '[pipeline]\nlidar_label = VELODYNE\n' > badlabel.ini
expect_bad "missing rawlog" "nope.rawlog" --rawlog nope.rawlog --ini "$INI/sim-hdl64.ini"
expect_bad "missing ini" "nope.ini" --rawlog hdl64.rawlog --ini nope.ini
expect_bad "unknown key" "unknown key 'ring_modle'" --rawlog hdl64.rawlog --ini typo.ini
expect_bad "bad value" "expects a number" --rawlog hdl64.rawlog --ini badvalue.ini
expect_bad "bad mode" "badmode.ini: [pipeline] mode: 'fast' is not one of lo, vo, vlo" --rawlog hdl64.rawlog --ini badmode.ini
expect_bad "unknown label" "VELODYNE" --rawlog hdl64.rawlog --ini badlabel.ini
expect_bad "bad --set" "section.key=value" --rawlog hdl64.rawlog --ini "$INI/sim-hdl64.ini" --set nodot
head -c 3000000 hdl64.rawlog > truncated.rawlog && cp -r hdl64_Images truncated_Images
expect_bad "truncated rawlog" "truncated" --rawlog truncated.rawlog --ini "$INI/sim-hdl64.ini"

finish run_lo
