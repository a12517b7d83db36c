#!/usr/bin/env bash
# vlo-import rosbag end to end: a simulated drive written as a ROS 1 bag (build/bin/vlo-test-rawlog-to-bag)
# and imported back must give vlo-run the very same trajectory as the simulator's own rawlog; broken
# bags fail with one line naming the file, exit code 2 and no output.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 30 --seed 5 --no-realism --out sim.rawlog --quiet || fail "vlo-sim failed"
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --gt sim.gt.tum --out sim.bag || fail "bag writer failed"

# --list: every topic with type, count and rate.
"$BIN/vlo-import" rosbag --bag sim.bag --list > list.txt || fail "--list failed"
for row in "/velodyne_points +sensor_msgs/PointCloud2 +30 +10.00" "/camera/image_raw +sensor_msgs/Image +30 +10.00" \
	"/camera/camera_info +sensor_msgs/CameraInfo +30" "/tf_static +tf2_msgs/TFMessage +1" "/ground_truth +nav_msgs/Odometry +30"; do
	grep -qE "^$row" list.txt || fail "--list lacks '$row': $(cat list.txt)"
done

# The simulator's vehicle frame is base_link in the bag's /tf_static: the import is then the same rawlog.
"$BIN/vlo-import" rosbag --bag sim.bag --lidar-topic /velodyne_points --image-topic /camera/image_raw \
	--gt-topic /ground_truth --vehicle-frame base_link --out imp.rawlog || fail "import failed"
awk 'NR == FNR { for (i = 1; i <= 8; i++) a[FNR, i] = $i; next }
	{ for (i = 1; i <= 8; i++) { d = $i - a[FNR, i]; if (d < 0) d = -d; if (d > m) m = d } }
	END { exit !(m < 1e-8) }' sim.gt.tum imp.gt.tum || fail "ground truth differs from the simulator's"
for mode in lo vlo; do
	"$BIN/vlo-run" --rawlog sim.rawlog --ini "$INI/vlp16.ini" --out "sim_$mode" --quiet --set pipeline.mode=$mode || fail "vlo-run $mode on sim"
	"$BIN/vlo-run" --rawlog imp.rawlog --ini "$INI/vlp16.ini" --out "imp_$mode" --quiet --set pipeline.mode=$mode || fail "vlo-run $mode on import"
	cmp -s "sim_$mode/trajectory_$mode.tum" "imp_$mode/trajectory_$mode.tum" || fail "$mode: trajectories differ"
	[ "$(wc -l < "imp_$mode/trajectory_$mode.tum")" -eq 30 ] || fail "$mode: not 30 poses"
	echo "ok: $mode trajectory identical"
done

# Per-point ring and time: the rawlog holds CObservationVelodyneScans, which MRPT's own tools read.
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --out rt.bag --vlp16-fields --encoding jpeg || fail "ring/time bag"
"$BIN/vlo-import" rosbag --bag rt.bag --lidar-topic /velodyne_points --image-topic /camera/image_raw/compressed \
	--vehicle-frame base_link --out rt.rawlog > /dev/null || fail "ring/time import failed"
rawlog-edit --info -i rt.rawlog > rt.info 2>&1
grep -Eq "LIDAR +/ +30 " rt.info && grep -Eq "CAMERA +/ +30 " rt.info || fail "rawlog-edit on ring/time import: $(cat rt.info)"
"$BIN/vlo-run" --rawlog rt.rawlog --ini "$INI/vlp16.ini" --out rt_lo --quiet --set pipeline.mode=lo || fail "vlo-run on ring/time import"

# expect_bad NAME TEXT ARGS...: exit code 2, one stderr line with TEXT, nothing written
expect_bad() {
	local name=$1 text=$2
	shift 2
	expect_exit2 "$name" "$text" bad "$BIN/vlo-import" rosbag "$@" --out bad/x.rawlog
}
ulimit -v 4000000  # broken input below: a corrupt size must not make the reader ask for tens of GB
TOPICS=(--lidar-topic /velodyne_points --image-topic /camera/image_raw)
head -c 3000000 sim.bag > cut.bag
expect_bad "truncated bag" "cut.bag: not a readable ROS 1 bag" --bag cut.bag "${TOPICS[@]}"
expect_bad "missing topic" "sim.bag: --lidar-topic: no topic '/points' (topics there: /camera/camera_info, /camera/image_raw" \
	--bag sim.bag --lidar-topic /points --image-topic /camera/image_raw
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --out nox.bag --drop-x
expect_bad "PointCloud2 without x" "nox.bag: /velodyne_points: PointCloud2 without field 'x'" --bag nox.bag "${TOPICS[@]}"
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --out yuv.bag --encoding yuv422
expect_bad "image encoding" "yuv.bag: /camera/image_raw: image encoding 'yuv422' is not supported" --bag yuv.bag "${TOPICS[@]}"
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --out fov.bag --distortion-model fov
expect_bad "distortion model" "fov.bag: /camera/camera_info: CameraInfo: unknown distortion_model 'fov'" --bag fov.bag "${TOPICS[@]}"
"$BIN/vlo-test-rawlog-to-bag" --rawlog sim.rawlog --out notf.bag --no-tf
expect_bad "no extrinsics" "notf.bag: no transform between the LiDAR frame 'velodyne' and the camera frame 'camera_optical'" \
	--bag notf.bag "${TOPICS[@]}"
grep -qF -- "--extrinsics FILE.yaml" err.txt || fail "no extrinsics: the option is not named"
# Issue 34, defect 4: the YAML parser printed its error and a caret on lines of their own before the error line.
printf 'image_width: [1, 2\ncamera_matrix: {\n' > bad_info.yaml
expect_bad "malformed YAML" "bad_info.yaml: not valid YAML (3:1: error: did not find expected node content)" \
	--bag sim.bag "${TOPICS[@]}" --camera-info bad_info.yaml

# Repeated --bag: one recording (notf.bag holds the same 30 frames again, without tf).
"$BIN/vlo-import" rosbag --bag sim.bag --bag notf.bag --list > list2.txt || fail "--list of two bags failed"
grep -qE "^/velodyne_points +sensor_msgs/PointCloud2 +60 " list2.txt || fail "two bags: $(cat list2.txt)"
finish import_rosbag
