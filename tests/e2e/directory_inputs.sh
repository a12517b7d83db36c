#!/usr/bin/env bash
# Issue 34, defect 4: a directory given where a file is expected is said to be one ("D: is a directory,
# expected a file"), by every tool and option, not "no [section]", "missing key 'P0'", "no such file",
# "no pose overlaps" or "no DATA line". One stderr line, exit 2.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

mkdir -p D root/sequences/00/calib.txt root/sequences/00/image_0
printf '0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 0 1\n0.2 2 0 0 0 0 0 1\n' > gt.tum

# says TOOL ARGS...: exit 2 and one line "TOOL: error: <a directory>: is a directory, expected a file"
says() {
	local tool=$1
	shift
	"$BIN/$tool" "$@" > /dev/null 2> err.txt
	local rc=$?
	[ $rc -eq 2 ] || fail "$tool $*: exit $rc, expected 2"
	[ "$(wc -l < err.txt)" -eq 1 ] && grep -Eq "^$tool: error: [^ ]*(D|calib.txt): is a directory, expected a file$" err.txt ||
		fail "$tool $*: $(cat err.txt)"
}
says vlo-run --rawlog D --ini "$INI/vlp16.ini" --out out
says vlo-run --rawlog gt.tum --ini D --out out
says vlo-eval --gt D --est gt.tum
says vlo-eval --gt gt.tum --est D
says vlo-eval --gt gt.tum --est gt.tum --kitti-calib D
says vlo-snapshot --map D --out snap
says vlo-import kitti-odometry --root root --seq 00 --out x.rawlog
says vlo-import rosbag --bag D --list
[ -e out ] || [ -e snap ] || [ -e x.rawlog ] && fail "an output was left"
finish directory_inputs
