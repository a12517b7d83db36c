#!/usr/bin/env bash
# A LiDAR whose lasers all fire 0.3 deg above their calibration (vlo-sim --lidar-elevation-error, realistic
# sensor) makes the ground a shallow bowl about the sensor, and A-LOAM pitches as it drives; [lidar]
# elevation_offset_deg = 0.3 raises the rays back and takes the drift away (doc/LOAM.md "A common elevation
# error"). Measured (60 frames, residential seed 2): KITTI r_err over 10-30 m 0.0238 deg/m uncorrected,
# 0.0024 corrected; ATE 0.068 / 0.006 m. Bad values fail cleanly.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --scenario residential --frames 60 --seed 2 --lidar-elevation-error 0.3 --out tilted.rawlog --quiet > /dev/null ||
	{ echo "FAIL: vlo-sim --lidar-elevation-error"; exit 1; }
# r_err OFFSET: A-LOAM alone with [lidar] elevation_offset_deg = OFFSET, its KITTI rotation error [deg/m]
r_err() {
	"$BIN/vlo-run" --rawlog tilted.rawlog --ini "$INI/sim-hdl64.ini" --set pipeline.mode=lo --set pipeline.snapshots=false \
		--set lidar.elevation_offset_deg="$1" --out "out_$1" --quiet > /dev/null || { fail "vlo-run offset $1"; return; }
	"$BIN/vlo-eval" --gt tilted.gt.tum --est "out_$1/trajectory_lo.tum" --metric kitti --kitti-lengths 10,20,30 \
		--json "$1.json" --quiet > /dev/null && jv "$1.json" kitti_r_err_deg_per_m
}
flat=$(r_err 0) raised=$(r_err 0.3)
echo "A-LOAM's rotation drift: $flat deg/m uncorrected, $raised deg/m with the offset"
below "$flat" 0.01 && fail "uncorrected, the drift $flat deg/m is too small to tell the offset's effect"
below "$raised" "$(awk -v f="$flat" 'BEGIN { print 0.3 * f }')" || fail "the offset does not cut the drift to 30 %"

expect_exit2 "sim refuses it without the realism" "needs the realism" none \
	"$BIN/vlo-sim" --no-realism --lidar-elevation-error 0.2 --frames 2 --out none/x.rawlog
expect_exit2 "run refuses an offset beyond 2 deg" "elevation_offset_deg" none2 \
	"$BIN/vlo-run" --rawlog tilted.rawlog --ini "$INI/sim-hdl64.ini" --set lidar.elevation_offset_deg=3 --out none2/run
finish elevation_offset
