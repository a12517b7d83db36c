#!/usr/bin/env bash
# Provenance (issue 34, section 3): --version of every tool names the version, the git commit it was built from
# and the build type; a run's summary.json and run.ini carry the same; the commit is taken at build time, from
# the source tree's own checkout only.
set -u
BIN="${VLO_BIN:?}"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 3 --seed 1 --out drive.rawlog --quiet || fail "vlo-sim"
"$BIN/vlo-run" --rawlog drive.rawlog --ini "$VLO_SRC/ini/vlp16.ini" --out run --set pipeline.mode=lo \
	--set pipeline.snapshots=false --quiet > /dev/null || fail "vlo-run"

# Provenance: --version of every tool, and the commit in summary.json and run.ini.
for tool in vlo-run vlo-eval vlo-import vlo-sim vlo-snapshot vlo-batch; do
	"$BIN/$tool" --version > v.txt || fail "$tool --version"
	grep -Eq "^$tool [0-9]+\.[0-9]+\.[0-9]+ \(git [0-9a-z-]+, [A-Za-z]+\)$" v.txt || fail "$tool --version: $(cat v.txt)"
done
commit=$(sed -E 's/.*\(git ([^,]+),.*/\1/' v.txt)
[ "$(jv run/summary.json git_commit)" = "\"$commit\"" ] || fail "summary.json: git_commit $(jv run/summary.json git_commit), not $commit"
grep -q "\"version\": \"[0-9]" run/summary.json || fail "summary.json: no version"
grep -q "^# Written by vlo .*, git $commit, " run/run.ini || fail "run.ini: no provenance line"
# The commit is taken from the source tree's own checkout only: a folder inside another repository (this work
# folder) or outside any gets "unknown", and the header is rewritten only when its text changes.
outside=$(mktemp -d)
for src in "$W" "$outside" "$VLO_SRC"; do
	cmake -DSOURCE_DIR="$src" -DOUT="$W/info.h" -DVERSION=1.2.3 -DBUILD_TYPE=Debug -P "$VLO_SRC/cmake/build_info.cmake" ||
		fail "build_info.cmake in $src"
	c=$(sed -n 's/#define VLO_GIT_COMMIT "\(.*\)"/\1/p' info.h)
	if [ "$src" = "$VLO_SRC" ]; then
		echo "$c" | grep -Eq '^[0-9a-f]{12}(-dirty)?$' || fail "build_info.cmake: commit '$c' of the checkout"
	else
		[ "$c" = unknown ] || fail "build_info.cmake: commit '$c' for $src, not a checkout of its own"
	fi
done
rmdir "$outside"
before=$(stat -c %Y info.h) && sleep 1.1
cmake -DSOURCE_DIR="$VLO_SRC" -DOUT="$W/info.h" -DVERSION=1.2.3 -DBUILD_TYPE=Debug -P "$VLO_SRC/cmake/build_info.cmake"
[ "$(stat -c %Y info.h)" = "$before" ] || fail "build_info.cmake rewrote an unchanged header (every build would recompile)"
finish provenance
