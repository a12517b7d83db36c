#!/usr/bin/env bash
# vlo-import on bad input: one "vlo-import: error: ..." line naming the problem, exit code != 0,
# and no output file (nor partial file) left behind.
set -uo pipefail
: "${VLO_BIN:?}" "${VLO_DATA:?}" "${VLO_WORK:?}"
rm -rf "$VLO_WORK" && mkdir -p "$VLO_WORK" && cd "$VLO_WORK" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_error <text the message must contain> <vlo-import args...>
expect_error() {
	local want="$1"; shift
	rm -rf out
	"$VLO_BIN/vlo-import" "$@" > stdout.txt 2> stderr.txt
	local rc=$?
	[ "$rc" -ne 0 ] || fail "exit 0 for: $*"
	[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "not one line for: $* -> $(cat stderr.txt)"
	grep -q "^vlo-import: error: .*$want" stderr.txt || fail "'$want' not in: $(cat stderr.txt)"
	[ -z "$(ls -A out 2> /dev/null)" ] || fail "output left for: $* -> $(ls -A out)"
	echo "ok ($rc): $(cat stderr.txt)"
}

tar -xJf "$VLO_DATA/kitti_odometry_06_0000-0050.tar.xz"
ODO=kitti_odometry_06_0000-0050
expect_error "missing subcommand" 
expect_error "unknown subcommand 'kitti'" kitti
expect_error "unknown option '--sequence'" kitti-odometry --root $ODO --sequence 06 --out out/x.rawlog
expect_error "missing required option '--out'" kitti-odometry --root $ODO --seq 06
expect_error "nowhere/sequences/06/calib.txt: cannot open" kitti-odometry --root nowhere --seq 06 --out out/x.rawlog
expect_error "bad frame range" kitti-odometry --root $ODO --seq 06 --out out/x.rawlog --first 9 --last 3

# A calibration file without P0.
cp -r $ODO broken && sed -i '/^P0/d' broken/sequences/06/calib.txt
expect_error "broken/sequences/06/calib.txt: missing key 'P0'" kitti-odometry --root broken --seq 06 --out out/x.rawlog
rm -rf broken

# Times out of order: fails before anything is written.
cp -r $ODO broken && sed -i '5s/.*/9.0e+00/' broken/sequences/06/times.txt
expect_error "times.txt: line 6: time is not after" kitti-odometry --root broken --seq 06 --out out/x.rawlog
rm -rf broken

# A Velodyne scan whose size is not a multiple of 16, found midway through the import.
cp -r $ODO broken && mkdir broken/sequences/06/velodyne
echo "Tr: 0 -1 0 0 0 0 -1 0 1 0 0 0" >> broken/sequences/06/calib.txt
for i in $(seq -f %06g 0 50); do head -c 32 /dev/zero > broken/sequences/06/velodyne/$i.bin; done
head -c 33 /dev/zero > broken/sequences/06/velodyne/000030.bin
expect_error "000030.bin: size 33 bytes is not a multiple of 16" kitti-odometry --root broken --seq 06 --out out/x.rawlog
rm -rf broken

# Issue 34, defect 4: libpng printed its own line ("libpng error: IDA[AB]: invalid chunk type") before the
# error line; now it is part of it.
cp -r $ODO broken
python3 -c "import sys; b = bytearray(open(sys.argv[1], 'rb').read()); b[40] ^= 0xFF; open(sys.argv[1], 'wb').write(b)" \
	broken/sequences/06/image_0/000005.png
expect_error "000005.png: cannot read image (libpng error: " kitti-odometry --root broken --seq 06 --out out/x.rawlog
rm -rf broken

# Issue 34, defect 4: a full disk (here a 2 MB file size limit, its signal ignored) in the middle of an import
# printed MRPT's 20-line backtrace; one line, and nothing left behind.
tar -xJf "$VLO_DATA/kitti_odometry_snippets.tar.xz" --wildcards 'kitti_odometry_snippets/sequences/00/*'
(
	trap '' XFSZ
	ulimit -f 2000
	expect_error "out/x.rawlog: write failed (disk full?): Cannot write bytes to stream" \
		kitti-odometry --root kitti_odometry_snippets --seq 00 --camera 2 --out out/x.rawlog
) || exit 1
rm -rf kitti_odometry_snippets

# kitti-raw without calibration files, and with a bad camera number.
expect_error "calib_cam_to_cam.txt: cannot open" kitti-raw --drive . --calib . --out out/x.rawlog
expect_error "--camera: must be 0, 1, 2 or 3" kitti-raw --drive . --calib . --out out/x.rawlog --camera 7
cd / && rm -rf "$VLO_WORK"  # passed: nothing to look at
echo OK
