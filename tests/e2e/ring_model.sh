#!/usr/bin/env bash
# The data tells how many rings its scans have: an INI whose [loam.scan] ring model contradicts it is one
# line naming the INI and the model that fits, exit 2, nothing written; the right INI runs.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --lidar hdl64 --frames 5 --seed 3 --out hdl64.rawlog --quiet || fail "vlo-sim hdl64"
"$BIN/vlo-sim" --lidar vlp16 --frames 5 --seed 3 --out vlp16.rawlog --quiet || fail "vlo-sim vlp16"
tar -xJf "$VLO_DATA/kitti_odometry_snippets.tar.xz" --wildcards '*/sequences/00/*' '*/poses/00.txt'
"$BIN/vlo-import" kitti-odometry --root kitti_odometry_snippets --seq 00 --camera 2 --last 4 --out kitti.rawlog \
	> /dev/null 2> import.err || fail "vlo-import: $(cat import.err)"

expect_exit2 "vlp16.ini on simulated HDL-64" "ini/vlp16.ini: [loam.scan] ring model uniform (16 rings) but the scans have 6" \
	out "$BIN/vlo-run" --rawlog hdl64.rawlog --ini "$INI/vlp16.ini" --out out/run --quiet
grep -qF "use ini/kitti-hdl64.ini or ring_model = hdl64" err.txt || fail "no advice for HDL-64: $(cat err.txt)"
expect_exit2 "sim-hdl64.ini on simulated VLP-16" "ini/sim-hdl64.ini: [loam.scan] ring model hdl64 (64 rings) but the scans have 16 rings" \
	out "$BIN/vlo-run" --rawlog vlp16.rawlog --ini "$INI/sim-hdl64.ini" --out out/run --quiet
grep -qF "use ini/vlp16.ini" err.txt || fail "no advice for VLP-16: $(cat err.txt)"
expect_exit2 "vlp16.ini on KITTI 00" "ini/vlp16.ini: [loam.scan] ring model uniform (16 rings) but the scans have 6" \
	out "$BIN/vlo-run" --rawlog kitti.rawlog --ini "$INI/vlp16.ini" --out out/run --quiet --set pipeline.mode=lo
expect_exit2 "a --set that makes the model wrong" "ring model uniform (64 rings) but the scans have 16 rings" \
	out "$BIN/vlo-run" --rawlog vlp16.rawlog --ini "$INI/vlp16.ini" --out out/run --quiet --set loam.scan.n_rings=64

# The models that fit run (mode lo: the check is LOAM's; the camera's part is tested elsewhere).
for c in "hdl64 sim-hdl64" "vlp16 vlp16" "kitti kitti-hdl64"; do
	set -- $c
	"$BIN/vlo-run" --rawlog "$1.rawlog" --ini "$INI/$2.ini" --out "ok_$1" --quiet --set pipeline.mode=lo \
		--set pipeline.snapshots=false > /dev/null 2> "ok_$1.err" || fail "$2.ini on $1: $(cat "ok_$1.err")"
	[ "$(wc -l < "ok_$1/trajectory_lo.tum")" -eq 5 ] || fail "$2.ini on $1: not 5 poses"
done
finish ring_model
