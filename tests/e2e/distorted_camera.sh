#!/usr/bin/env bash
# A lens-distorted camera (vlo-sim --camera-distortion, plumb_bob and --fisheye) on the same simulated
# drive as an ideal one: the rawlog carries the lens, vlo-run undistorts, and the full system's error
# and the scale-corrected VO's ATE stay near the ideal camera's. 80 frames are too short for the 10 %
# measured on a 150-frame drive: here the bounds are 2x / 3x, which the VO misses by 10x when
# the images are not undistorted (VO ATE 1.9 m against 0.19 m with plumb_bob, measured).
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

# drive NAME [vlo-sim lens options]: simulates, runs mode vlo, prints "t_err vo_ate"
drive() {
	local name=$1
	shift
	"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames 80 --seed 4 --no-realism --out "$name.rawlog" --quiet "$@" > /dev/null ||
		{ fail "$name: vlo-sim failed"; return; }
	"$BIN/vlo-run" --rawlog "$name.rawlog" --ini "$INI/sim-hdl64.ini" --out "out_$name" --quiet > /dev/null ||
		{ fail "$name: vlo-run failed"; return; }
	"$BIN/vlo-eval" --gt "$name.gt.tum" --est "out_$name/trajectory_vlo.tum" --kitti-lengths 10,20,40 --json "$name.json" > /dev/null
	"$BIN/vlo-eval" --gt "$name.gt.tum" --est "out_$name/trajectory_vo.tum" --json "${name}_vo.json" > /dev/null
	echo "$(jv "$name.json" kitti_t_err_pct) $(jv "${name}_vo.json" ate_rmse_m)"
}
# within A B FACTOR FLOOR: A <= FACTOR * B + FLOOR
within() { awk -v a="$1" -v b="$2" -v k="$3" -v floor="$4" 'BEGIN { exit !(a != "" && a <= k * b + floor) }'; }

read -r t0 a0 <<< "$(drive ideal)"
echo "ideal: t_err $t0 %, scale-corrected VO ATE $a0 m"
for lens in "plumb_bob --camera-distortion=-0.3,0.1,0.0005,-0.0005" "fisheye --camera-distortion=0.02,-0.01,0.003,-0.001 --fisheye"; do
	name=${lens%% *}
	read -r t a <<< "$(drive "$name" ${lens#* })"
	echo "$name: t_err $t %, scale-corrected VO ATE $a m"
	within "$t" "$t0" 2 0.1 || fail "$name: t_err $t % above 2x the ideal camera's $t0 % + 0.1"
	within "$a" "$a0" 3 0.05 || fail "$name: VO ATE $a m above 3x the ideal camera's $a0 m + 0.05"
done
rawlog-edit --info -i plumb_bob.rawlog | grep -Eq "CAMERA +/ +80 " || fail "rawlog-edit cannot read the distorted rawlog"
"$BIN/vlo-sim" --frames 2 --camera-distortion 0.1,0.2 --out bad.rawlog --quiet 2> bad.err && fail "2 coefficients accepted"
grep -q "4 or 5 coefficients" bad.err || fail "bad lens: $(cat bad.err)"
finish distorted_camera
