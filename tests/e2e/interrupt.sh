#!/usr/bin/env bash
# Ctrl-C (SIGINT) or SIGTERM during a long job: one line, exit code 130, and none of the outputs it
# was writing left behind (no .partial files or folders, no half-written results).
set -u
BIN="${VLO_BIN:?}"
. "$VLO_SRC/tests/e2e/lib/common.sh"

# interrupt SIGNAL: starts a 300-frame vlo-sim, signals it once it has written frames, checks the aftermath
interrupt() {
	local sig=$1 dir="sim_$1"
	mkdir -p "$dir"
	"$BIN/vlo-sim" --scenario urban --lidar vlp16 --frames 300 --seed 2 --out "$dir/x.rawlog" --kitti-dir "$dir/kitti" --quiet \
		> /dev/null 2> "$dir.err" &
	local pid=$!
	for _ in $(seq 100); do  # until its first frames are on disk (at most 20 s)
		[ -n "$(ls "$dir"/x_Images.partial 2> /dev/null | head -1)" ] && break
		sleep 0.2
	done
	kill -"$sig" "$pid"
	wait "$pid"
	local rc=$?
	[ "$rc" -eq 130 ] || fail "$sig: exit code $rc, expected 130"
	[ "$(wc -l < "$dir.err")" -eq 1 ] && grep -q "vlo-sim: interrupted" "$dir.err" || fail "$sig: stderr: $(cat "$dir.err")"
	local left
	left=$(find "$dir" -mindepth 1 | head -5)
	[ -z "$left" ] || fail "$sig: left behind: $left"
	echo "ok: $sig: $(cat "$dir.err")"
}
interrupt INT
interrupt TERM
finish interrupt
