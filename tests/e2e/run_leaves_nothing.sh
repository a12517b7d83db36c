#!/usr/bin/env bash
# vlo-run creates its output folder (parents included) only when it has something to write: bad input,
# a VO that never initialises in mode vo, or Ctrl-C leave no folder behind, with one line on stderr.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 1 --seed 1 --out one.rawlog --quiet || fail "vlo-sim failed"
"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 60 --seed 1 --out many.rawlog --quiet || fail "vlo-sim failed"

# refused NAME CODE TEXT ARGS...: exit CODE, one stderr line with TEXT, no out/ folder at all
refused() {
	local name=$1 code=$2 text=$3
	shift 3
	rm -rf out
	"$BIN/vlo-run" --out out/a/b --quiet "$@" > /dev/null 2> err.txt
	local rc=$?
	[ "$rc" -eq "$code" ] || fail "$name: exit code $rc, expected $code"
	[ "$(wc -l < err.txt)" -eq 1 ] && grep -qF -- "$text" err.txt || fail "$name: stderr: $(cat err.txt)"
	[ ! -e out ] || fail "$name: left $(find out | head -3 | tr '\n' ' ')"
	echo "ok: $name: $(cat err.txt)"
}
refused "missing rawlog" 2 "nothere.rawlog: file not found" --rawlog nothere.rawlog --ini "$INI/vlp16.ini"
refused "unknown key" 2 "unknown key" --rawlog one.rawlog --ini "$INI/vlp16.ini" --set pipeline.no_such_key=1
refused "VO never initialised" 2 "the visual odometry never initialised in 1 frames" \
	--rawlog one.rawlog --ini "$INI/vlp16.ini" --set pipeline.mode=vo

# Ctrl-C in the middle of the frame loop
rm -rf out
"$BIN/vlo-run" --rawlog many.rawlog --ini "$INI/vlp16.ini" --out out/a/b --quiet > /dev/null 2> int.txt &
pid=$!
# in its setup or its frame loop: either way the signal is honoured at the next frame
catching "$pid" 2 || fail "Ctrl-C: vlo-run never caught SIGINT (ended or hung in its start-up)"
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 130 ] || fail "Ctrl-C: exit code $rc (the run may have ended before the signal: $(cat int.txt))"
grep -q "vlo-run: interrupted" int.txt || fail "Ctrl-C: stderr: $(cat int.txt)"
[ ! -e out ] || fail "Ctrl-C: left $(find out | head -3 | tr '\n' ' ')"
finish run_leaves_nothing
