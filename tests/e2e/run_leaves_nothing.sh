#!/usr/bin/env bash
# vlo-run creates its output folder (parents included) only when it has something to write: bad input,
# a VO that never initialises in mode vo, or Ctrl-C before the first frame leave no folder behind, with one
# line on stderr. A run that stops after some frames (Ctrl-C, a rawlog cut short) keeps them: a complete,
# consistent run folder whose summary.json says "complete": false (issue 34, section 2).
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

# Issue 34, section 2: --gt is read and checked before the first frame. The rawlog cut at 70 % fails only
# after its first frames, so an error naming the ground truth shows that it came first.
head -c $(($(stat -c %s many.rawlog) * 7 / 10)) many.rawlog > cut.rawlog
ln -s many_Images cut_Images
printf '0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 nan 1\n' > bad.gt.tum
refused "bad --gt, checked first" 2 "bad.gt.tum: line 2: non-finite value" \
	--rawlog cut.rawlog --ini "$INI/vlp16.ini" --set pipeline.mode=lo --gt bad.gt.tum

# kept_run DIR: the files of a run stopped early, consistent with each other
kept_run() {
	local d=$1 rows traj
	traj=$(jv "$d/summary.json" trajectory | tr -d '"')
	for f in summary.json frames.csv "$traj" run.ini report.md .vlo-run-files; do
		[ -s "$d/$f" ] || fail "$d: $f missing"
	done
	grep -q '"complete": false' "$d/summary.json" || fail "$d: summary.json does not say \"complete\": false"
	rows=$(($(wc -l < "$d/frames.csv") - 1))
	[ "$(wc -l < "$d/$traj")" -eq "$rows" ] || fail "$d: $traj and frames.csv disagree"
	[ "$(jv "$d/summary.json" frames)" = "$rows" ] || fail "$d: summary.json frames $(jv "$d/summary.json" frames), $rows rows"
	[ "$(jv "$d/summary.json" last_frame)" = "$(tail -1 "$d/frames.csv" | cut -d, -f1)" ] || fail "$d: last_frame"
	echo "kept: $d: $rows frames, $(jv "$d/summary.json" stop_reason)"
}
rm -rf out
"$BIN/vlo-run" --rawlog cut.rawlog --ini "$INI/vlp16.ini" --set pipeline.mode=lo --out out/a/b --quiet > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] || fail "cut rawlog: exit $rc, expected 2"
[ "$(wc -l < err.txt)" -eq 1 ] && grep -q "cut.rawlog: .*: the run stopped there; the [0-9]* frames up to frame [0-9]* are kept in out/a/b" err.txt ||
	fail "cut rawlog: $(cat err.txt)"
kept_run out/a/b

# Issue 34, section 2: a full disk (here a 50 kB file size limit, its signal ignored) while the outputs are
# written: one line, and no half of a run (frames.csv and trajectories without summary.json and the list).
(
	trap '' XFSZ
	ulimit -f 50
	refused "full disk" 2 "write failed (disk full?)" --rawlog many.rawlog --ini "$INI/vlp16.ini" --set pipeline.mode=lo \
		--set pipeline.snapshots=false
) || fail "full disk"

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
# Before the first frame nothing is left; after it, the frames computed.
[ ! -e out ] || kept_run out/a/b
finish run_leaves_nothing
