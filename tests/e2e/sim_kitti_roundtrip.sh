#!/usr/bin/env bash
# vlo-sim --kitti-dir, read back by vlo-import kitti-odometry: the same frames (times, points, images,
# extrinsic) and the same ground truth as vlo-sim's own rawlog.
set -euo pipefail
: "${VLO_BIN:?}" "${VLO_WORK:?}"
if [ ! -x "$VLO_BIN/vlo-import" ] || [ ! -x "$VLO_BIN/test_sim" ]; then
	echo "SKIP: vlo-import or test_sim is not built"
	exit 0
fi
rm -rf "$VLO_WORK" && mkdir -p "$VLO_WORK" && cd "$VLO_WORK"
"$VLO_BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 5 --seed 4 --lidar-distortion \
	--out sim.rawlog --kitti-dir kitti --quiet
"$VLO_BIN/vlo-import" kitti-odometry --root kitti --seq 00 --out imported.rawlog > import.log
VLO_RT_SIM=sim.rawlog VLO_RT_IMPORTED=imported.rawlog \
	"$VLO_BIN/test_sim" --gtest_filter='KittiRoundTrip.*' --gtest_brief=1
echo OK
