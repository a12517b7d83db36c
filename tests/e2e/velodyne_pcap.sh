#!/usr/bin/env bash
# Real Velodyne captures (MRPT's sample pcaps) -> rawlog with MRPT's rawlog-grabber -> vlo-run: the
# CObservationVelodyneScan packets are decoded (VLP-16 with the calibration the grabber stored; HDL-32E
# with the model's default, since MRPT 2.5.8's grabber stores VLP-16's for it) and tracked.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
SAMPLES="${VLO_DATA:?}/mrpt_samples"
. "$VLO_SRC/tests/e2e/lib/common.sh"

# grab MODEL PCAP: writes grab_MODEL/*.rawlog (label LIDAR_SCAN) as doc/FORMATS.md shows
grab() {
	mkdir -p "grab_$1"
	cat > "grab_$1.ini" <<INI
[global]
rawlog_prefix         = $W/grab_$1/$1
time_between_launches = 300
use_sensoryframes     = 0
GRABBER_PERIOD_MS     = 50
[VELODYNE]
driver         = CVelodyneScanner
process_rate   = 500
sensorLabel    = LIDAR
model          = $1
pcap_input     = $2
pcap_read_once = true
pcap_read_fast = true
pose_x = 0
pose_y = 0
pose_z = 0
pose_yaw = 0
pose_pitch = 0
pose_roll = 0
INI
	# rawlog-grabber quits when its standard input ends: keep it open while the capture is read, for 4 s
	# from the moment it runs (on a loaded machine loading MRPT can take longer than that by itself).
	{
		for _ in $(seq 600); do
			grep -q "Press any key" "grab_$1.log" 2> /dev/null && break
			sleep 0.1
		done
		sleep 4
	} | rawlog-grabber "grab_$1.ini" > "grab_$1.log" 2>&1
	ls grab_"$1"/*.rawlog > /dev/null 2>&1 || fail "$1: rawlog-grabber wrote nothing: $(tail -3 "grab_$1.log")"
}

# run_case MODEL PCAP INI FRAMES MAX_PATH_M: vlo-run (LiDAR only) tracks every scan of the capture
run_case() {
	local model=$1 pcap=$2 ini=$3 frames=$4 max_path=$5
	grab "$model" "$pcap"
	local rawlog
	rawlog=$(ls grab_"$model"/*.rawlog | head -1)
	"$BIN/vlo-run" --rawlog "$rawlog" --ini "$INI/$ini" --out "out_$model" --quiet \
		--set pipeline.mode=lo --set pipeline.lidar_label=LIDAR_SCAN > /dev/null 2> "run_$model.err" ||
		{ fail "$model: vlo-run failed: $(cat "run_$model.err")"; return; }
	[ "$(wc -l < "out_$model/trajectory_lo.tum")" -eq "$frames" ] || fail "$model: not $frames poses"
	local path
	path=$(jv "out_$model/summary.json" path_length_m)
	echo "$model: $frames scans tracked, path $path m; reader: $(jv "out_$model/summary.json" reader)"
	below "$path" "$max_path" || fail "$model: path $path m above $max_path m"
}
# The VLP-16 capture is 0.2 s of a slowly moving sensor; the HDL-32E one starts with a partial sweep.
run_case VLP16 "$SAMPLES/sample_velodyne_vlp16_gps.pcap" vlp16.ini 3 0.1
grep -q "default calibration" out_VLP16/summary.json && fail "VLP16: its own calibration was replaced"
run_case HDL32 "$SAMPLES/sample_velodyne_hdl32.pcap" hdl32.ini 2 0.5
grep -q "2 Velodyne scans decoded with the model's default calibration" out_HDL32/summary.json ||
	fail "HDL32: the grabber's wrong (16-laser) calibration was used"

# A label that holds a class vlo does not read is one line naming the class.
"$BIN/vlo-run" --rawlog "$SAMPLES/rot_scan_velodyne.rawlog" --ini "$INI/vlp16.ini" --out bad --quiet \
	--set pipeline.mode=lo --set pipeline.lidar_label=Velodyne1_SCAN > /dev/null 2> bad.err && fail "rot_scan: exit 0"
[ "$(wc -l < bad.err)" -eq 1 ] && grep -q "CObservationRotatingScan" bad.err || fail "rot_scan: $(cat bad.err)"
[ ! -e bad/trajectory_lo.tum ] || fail "rot_scan: output left behind"
finish velodyne_pcap
