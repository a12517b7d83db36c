#!/usr/bin/env bash
# Re-using an --out folder: one that holds another run, or other files, is refused (one line naming the folder
# and --overwrite, exit 2, nothing changed); with --overwrite the earlier run's files go, and only those.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --frames 8 --seed 4 --out drive.rawlog --quiet || fail "vlo-sim"
run() { "$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --quiet --set pipeline.mode=lo "$@" > /dev/null; }

mkdir -p out/snapshots
echo mine > out/notes.txt
echo mine > out/snapshots/mine.txt
# Issue 34, defect 5: a folder with other files and no run (/usr/share, /) was taken, and / failed in a
# "filesystem error" from walking /proc.
for dir in out / /usr/share; do
	run --out $dir 2> err.txt
	rc=$?
	[ $rc -eq 2 ] || fail "--out $dir, a folder of other files: exit $rc, expected 2"
	[ "$(wc -l < err.txt)" -eq 1 ] &&
		grep -qF "vlo-run: error: $dir: is a folder with other files and no run in it: give --overwrite" err.txt ||
		fail "--out $dir: $(cat err.txt)"
done
[ "$(ls -A out | sort | tr '\n' ' ')" = "notes.txt snapshots " ] || fail "the refused run changed out/: $(ls -A out)"
run --out out --overwrite --set pipeline.sample_frame_every=4 || fail "--overwrite: a folder with only the user's files"
[ -s out/snapshots/frame_000004.png ] && [ -s out/.vlo-run-files ] || fail "first run: no snapshot or no manifest"
grep -qx "trajectory_lo.tum" out/.vlo-run-files && grep -qx "snapshots/topdown.png" out/.vlo-run-files ||
	fail "manifest lacks the run's files: $(cat out/.vlo-run-files)"
grep -q "notes.txt\|mine.txt" out/.vlo-run-files && fail "manifest lists the user's files"
sums() { (cd out && find . -type f -exec md5sum {} + | sort -k2); }
sums > before.md5

run --out out 2> err.txt
rc=$?
[ $rc -eq 2 ] || fail "re-used folder: exit $rc, expected 2"
[ "$(wc -l < err.txt)" -eq 1 ] && grep -qF "vlo-run: error: out: holds the files of another run: give --overwrite" err.txt ||
	fail "re-used folder: $(cat err.txt)"
sums | diff -q before.md5 - > /dev/null || fail "the refused run changed the folder"

# A run without sample frames: the earlier run's frame snapshot must not stay beside the new files.
run --out out --overwrite || fail "--overwrite"
[ -e out/snapshots/frame_000004.png ] && fail "--overwrite left the earlier run's snapshot"
[ "$(cat out/notes.txt)" = mine ] && [ "$(cat out/snapshots/mine.txt)" = mine ] || fail "--overwrite touched the user's files"
[ -s out/trajectory_lo.tum ] && [ -s out/snapshots/topdown.png ] || fail "--overwrite: the new run is incomplete"

# A run from before manifests: its own files (names every run leaves) go, nothing else.
rm out/.vlo-run-files
echo stale > out/trajectory_vo.tum
run --out out 2> err.txt && fail "a run without manifest was not recognised"
run --out out --overwrite --set pipeline.snapshots=false || fail "--overwrite of a run without manifest"
[ -e out/trajectory_vo.tum ] || [ -e out/snapshots/topdown.png ] && fail "the old run's files stayed"
[ -e out/notes.txt ] && [ -e out/snapshots/mine.txt ] || fail "the user's files went"

# A manifest cannot make vlo-run delete outside the folder.
echo keep > outside.txt
printf '../outside.txt\n/etc/hostname\n' >> out/.vlo-run-files
run --out out --overwrite || fail "--overwrite with a tampered manifest"
[ -e outside.txt ] || fail "a manifest line deleted a file outside the folder"
finish overwrite
