#!/usr/bin/env bash
# vlo-sim from the command line: help, bad input, determinism (same seed, same bytes), what
# rawlog-edit sees, and the scenario (loop and facades among them), LiDAR, distortion, foliage and
# KITTI-trajectory variants.
set -euo pipefail
: "${VLO_BIN:?}" "${VLO_WORK:?}" "${VLO_DATA:?}"
rm -rf "$VLO_WORK" && mkdir -p "$VLO_WORK" && cd "$VLO_WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }
sim() { "$VLO_BIN/vlo-sim" --quiet "$@"; }
expect_error() {  # expect_error "message part" args...
	local msg=$1 rc=0
	shift
	"$VLO_BIN/vlo-sim" --quiet "$@" 2> err.txt || rc=$?
	[ $rc -eq 2 ] || fail "exit code $rc for: $*"
	grep -q "$msg" err.txt || fail "expected '$msg' for: $* (got: $(cat err.txt))"
}

"$VLO_BIN/vlo-sim" --help | grep -q -- "--lidar-distortion" || fail "--help"
expect_error "unknown scenario 'moon'" --scenario moon --out x.rawlog
expect_error "unknown LiDAR 'hdl32'" --lidar hdl32 --out x.rawlog
expect_error "missing required option '--out'" --frames 2
expect_error "frames" --frames 0 --out x.rawlog
expect_error "nope.txt" --trajectory nope.txt --out x.rawlog
expect_error "foliage-depth: must be between 0 and 10 m" --foliage-depth -1 --out x.rawlog
expect_error "ideal-deskew: needs --lidar-distortion" --no-realism --ideal-deskew --out x.rawlog
expect_error "realism: contradicts --no-realism" --realism --no-realism --out x.rawlog
expect_error "realism: contradicts --no-noise" --realism --no-noise --out x.rawlog
expect_error "point-times: needs the realism" --no-realism --point-times --out x.rawlog
expect_error "reverse-after: needs --scenario loop" --reverse-after 2 --out x.rawlog
expect_error "facade-period: needs --scenario facades" --scenario loop --facade-period 24 --out x.rawlog
expect_error "facade-period: must be a multiple of 8 m" --scenario facades --facade-period 20 --out x.rawlog
expect_error "reverse-after: must be between 0" --scenario loop --reverse-after -1 --out x.rawlog
expect_error "traffic: not on the loop" --scenario loop --traffic 2 --out x.rawlog
expect_error "has its own road" --scenario facades --trajectory nope.txt --out x.rawlog
if ls x.* x_Images ./*.partial > /dev/null 2>&1; then fail "output left after an error"; fi

# Same seed, same bytes: rawlog, images, ground truth.
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --out a/t.rawlog
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --out b/t.rawlog
cmp a/t.rawlog b/t.rawlog || fail "rawlogs differ"
cmp a/t.gt.tum b/t.gt.tum || fail "ground truth differs"
for f in a/t_Images/*.pgm; do cmp "$f" "b/t_Images/$(basename "$f")" || fail "$f differs"; done
sim --scenario trees --lidar vlp16 --frames 3 --seed 6 --out c/t.rawlog
cmp -s a/t.gt.tum c/t.gt.tum && fail "another seed gave the same drive"

# Foliage changes what the LiDAR returns, not what the camera sees.
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --foliage-depth 0.3 --out f/t.rawlog
for f in a/t_Images/*.pgm; do cmp "$f" "f/t_Images/$(basename "$f")" || fail "foliage changed the image $f"; done
cmp -s a/t.rawlog f/t.rawlog && fail "foliage did not change the scans"

[ "$(grep -vc '^#' a/t.gt.tum)" -eq 3 ] || fail "3 ground-truth poses expected"
head -1 a/t.gt.tum | grep -q "^0.000000000 0.000000000 0.000000000 0.000000000 0.000000000 0.000000000 0.000000000 1.000000000" ||
	fail "ground truth must start at the identity: $(head -1 a/t.gt.tum)"
rawlog-edit --info -i a/t.rawlog > info.txt
grep -Eq "CAMERA +/ +3 " info.txt && grep -Eq "LIDAR +/ +3 " info.txt || fail "rawlog-edit: $(cat info.txt)"

# The realism is the default; --no-realism is the exact sensor (other scans, other images, same truth).
# A realistic sweep is written without per-point times (a point cloud, as KITTI raw's), unless --point-times
# (a Velodyne scan with times and rings).
"$VLO_BIN/vlo-sim" --help | grep -q -- "--no-realism" || fail "--help lacks --no-realism"
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --realism --out r/t.rawlog
cmp a/t.rawlog r/t.rawlog || fail "--realism is not the default"
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --no-realism --out e/t.rawlog
cmp -s a/t.rawlog e/t.rawlog && fail "--no-realism gave the realistic scans"
img=$(ls a/t_Images | head -1)
cmp -s "a/t_Images/$img" "e/t_Images/$img" && fail "--no-realism gave the realistic image"
cmp a/t.gt.tum e/t.gt.tum || fail "the realism changed the ground truth"
sim --scenario trees --lidar vlp16 --frames 3 --seed 5 --point-times --out p/t.rawlog
# (MRPT's binary rawlog names each object's class)
grep -qa "CObservationPointCloud" a/t.rawlog && ! grep -qa "CObservationVelodyneScan" a/t.rawlog ||
	fail "a realistic sweep must be a point cloud without times"
grep -qa "CObservationVelodyneScan" p/t.rawlog || fail "--point-times: no Velodyne scan with times"

# Variants: HDL-64 corridor with distortion; urban along the first KITTI 00 poses; loop; facades.
sim --scenario corridor --frames 2 --lidar-distortion --out d/c.rawlog
tar -xJf "$VLO_DATA/kitti_gt_poses.tar.xz" kitti_gt_poses/00.txt
sim --scenario urban --lidar vlp16 --frames 3 --trajectory kitti_gt_poses/00.txt --out k/u.rawlog
[ "$(ls k/u_Images | wc -l)" -eq 3 ] || fail "3 images expected"
# The revisit scenarios (test_loop.cpp checks their geometry).
sim --scenario loop --lidar vlp16 --frames 2 --reverse-after 0 --out l/l.rawlog
sim --scenario facades --lidar vlp16 --frames 2 --facade-period 32 --out g/f.rawlog
[ "$(grep -vc "^#" l/l.gt.tum)" -eq 2 ] && [ "$(ls g/f_Images | wc -l)" -eq 2 ] || fail "loop / facades: 2 frames expected"
if ls ./*/*.partial > /dev/null 2>&1; then fail "partial output left"; fi
cd / && rm -rf "$VLO_WORK"  # passed: nothing to look at
echo OK
