#!/usr/bin/env bash
# vlo-import on the shared real KITTI data: both importers, their outputs read by rawlog-edit.
set -euo pipefail
: "${VLO_BIN:?}" "${VLO_DATA:?}" "${VLO_WORK:?}"
rm -rf "$VLO_WORK" && mkdir -p "$VLO_WORK" && cd "$VLO_WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }

tar -xJf "$VLO_DATA/kitti_odometry_06_0000-0050.tar.xz"
tar -xJf "$VLO_DATA/kitti_raw_2011_09_26_sample.tar.xz"

for sub in "" kitti-odometry kitti-raw; do
	"$VLO_BIN/vlo-import" $sub --help | grep -q Usage || fail "--help of '$sub'"
done

"$VLO_BIN/vlo-import" kitti-odometry --root kitti_odometry_06_0000-0050 --seq 06 --out out/s06.rawlog 2> odo.err
grep -q "warning: .*camera-only" odo.err || fail "no camera-only warning: $(cat odo.err)"
[ -f out/s06.rawlog ] && [ -d out/s06_Images ] || fail "odometry output missing"
[ "$(ls out/s06_Images | wc -l)" -eq 51 ] || fail "expected 51 images"
[ "$(grep -vc '^#' out/s06.gt.tum)" -eq 51 ] || fail "expected 51 ground-truth poses"
rawlog-edit --info -i out/s06.rawlog > odo.info
grep -Eq "CAMERA +/ +51 " odo.info || fail "rawlog-edit: $(cat odo.info)"

"$VLO_BIN/vlo-import" kitti-raw --drive kitti_raw_2011_09_26_sample --calib kitti_raw_2011_09_26_sample \
	--camera 2 --out out/raw.rawlog 2> raw.err  # its stdout line gives the speed
rawlog-edit --info -i out/raw.rawlog > raw.info
grep -Eq "CAMERA +/ +32 " raw.info && grep -Eq "LIDAR +/ +32 " raw.info || fail "rawlog-edit: $(cat raw.info)"
ls out/*.partial 2> /dev/null && fail "partial output left"

# Issue 34, defect 8: an earlier import is not replaced without --overwrite (as vlo-run's run folders).
md5=$(md5sum < out/s06.rawlog)
"$VLO_BIN/vlo-import" kitti-odometry --root kitti_odometry_06_0000-0050 --seq 06 --last 2 --out out/s06.rawlog 2> again.err &&
	fail "an earlier import was replaced without --overwrite"
grep -qx "vlo-import: error: out/s06.rawlog: exists: give --overwrite to replace it, or another --out" again.err ||
	fail "re-import: $(cat again.err)"
[ "$(md5sum < out/s06.rawlog)" = "$md5" ] || fail "the refused import changed the rawlog"
"$VLO_BIN/vlo-import" kitti-odometry --root kitti_odometry_06_0000-0050 --seq 06 --last 2 --out out/s06.rawlog \
	--overwrite --quiet > /dev/null || fail "--overwrite"
[ "$(ls out/s06_Images | wc -l)" -eq 3 ] || fail "--overwrite: expected 3 images, got $(ls out/s06_Images | wc -l)"
cd / && rm -rf "$VLO_WORK"  # passed: nothing to look at
echo OK
