#!/usr/bin/env bash
# Option errors name where the value came from: a --set override by its text, a value of the INI file by
# the file, section and key; a typo'd key or section gets the nearest known one suggested. Each is one
# stderr line, exit 2, no output folder.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 1 --seed 1 --out one.rawlog --quiet || fail "vlo-sim failed"

# refused NAME EXPECTED-LINE ARGS...: exit 2, exactly the expected stderr line, no out/ folder
refused() {
	local name=$1 expected=$2
	shift 2
	rm -rf out
	"$BIN/vlo-run" --rawlog one.rawlog --out out --quiet "$@" > /dev/null 2> err.txt
	local rc=$?
	[ "$rc" -eq 2 ] || fail "$name: exit code $rc, expected 2"
	[ "$(cat err.txt)" = "vlo-run: error: $expected" ] || fail "$name: stderr: $(cat err.txt), expected: $expected"
	[ ! -e out ] || fail "$name: left out/"
	echo "ok: $name: $(cat err.txt)"
}

refused "typo'd key via --set" \
	"--set loam.mapping.map_raduis=80: unknown key 'map_raduis' in section [loam.mapping] (did you mean map_radius?)" \
	--ini "$INI/vlp16.ini" --set loam.mapping.map_raduis=80
refused "typo'd section via --set" \
	"--set loam.maping.map_radius=80: unknown section [loam.maping] (did you mean loam.mapping?)" \
	--ini "$INI/vlp16.ini" --set loam.maping.map_radius=80
refused "bad value via --set" "--set loam.mapping.map_radius=abc: expects a number, got 'abc'" \
	--ini "$INI/vlp16.ini" --set loam.mapping.map_radius=abc
refused "range error via --set" "--set vo.orb.n_features=10: must be >= 50" \
	--ini "$INI/vlp16.ini" --set vo.orb.n_features=10
refused "unknown choice via --set" "--set pipeline.mode=vlp: 'vlp' is not one of lo, vo, vlo (did you mean vlo?)" \
	--ini "$INI/vlp16.ini" --set pipeline.mode=vlp
# Issue 34, defect 4: a value that shares nothing with the allowed ones gets no "did you mean".
refused "unknown choice, no near one" "--set pipeline.threads=7: '7' is not one of 1, 2, auto" \
	--ini "$INI/vlp16.ini" --set pipeline.threads=7
refused "unknown module via --set" "--set pipeline.lidar_odometry=kiss: unknown module 'kiss' (known: aloam, icp)" \
	--ini "$INI/vlp16.ini" --set pipeline.lidar_odometry=kiss

# The same mistakes in the file name the file, the section and the key.
sed 's/^map_radius .*/map_radius     = abc/' "$INI/vlp16.ini" > bad_value.ini
grep -q "^map_radius     = abc" bad_value.ini || fail "vlp16.ini has no map_radius line to change"
refused "bad value in the file" "bad_value.ini: [loam.mapping] map_radius: expects a number, got 'abc'" --ini bad_value.ini
sed 's/^map_radius .*/map_radius     = 0.5/' "$INI/vlp16.ini" > bad_range.ini
refused "relation error in the file" "bad_range.ini: [loam.mapping] map_radius: must exceed voxel_size" --ini bad_range.ini
printf '[scale]\nlk_levels = 9\n' > range.ini
refused "range error in the file" "range.ini: [scale] lk_levels: must be in [0, 6]" --ini range.ini
printf '[icp]\nvoxel_sise = 1\n' > typo.ini
refused "typo'd key in the file" "typo.ini: unknown key 'voxel_sise' in section [icp] (did you mean voxel_size?)" --ini typo.ini
# --set wins over the file and is blamed, not the file.
refused "--set over a good file value" "--set loam.mapping.map_radius=-1: must be > 0" \
	--ini "$INI/vlp16.ini" --set loam.mapping.map_radius=-1
finish option_errors
