#!/usr/bin/env bash
# SIGTERM or Ctrl-C (SIGINT) to vlo-batch while its vlo-sim or vlo-run runs: the children get the signal
# too and remove what they were writing, vlo-batch says what it stopped in one line and exits 130, no
# process of the batch is left running and no half-written drive or run folder stays behind.
set -u
BIN="${VLO_BIN:?}"
. "${VLO_SRC:?}/tests/e2e/lib/common.sh"

# Processes of this test's batches (their command lines name files under $W/data/).
ours() { pgrep -f -- "$W/data/"; }

# plan NAME FRAMES: one VLP-16 drive generated on demand, run under two configurations
plan() {
	cat > "$1.ini" <<PLAN
[plan]
data = data

[sequence x]
ini = $VLO_SRC/ini/vlp16.ini
sim = --scenario urban --lidar vlp16 --frames $2 --seed 2

[config a]
set = pipeline.mode=lo pipeline.snapshots=false

[config b]
set = pipeline.mode=vlo pipeline.snapshots=false
PLAN
}

# interrupt SIGNAL NAME READY TEXT: starts vlo-batch on NAME.ini, signals it once the file READY exists,
# checks that it ends within 60 s with exit code 130 and a last stderr line holding TEXT (the lines before
# it: progress of what finished), and that nothing of the batch still runs.
interrupt() {
	local sig=$1 name=$2 ready=$3 text=$4
	"$BIN/vlo-batch" --plan "$name.ini" --out "$name" --jobs 2 > "$name.log" 2> "$name.err" &
	local pid=$!
	for _ in $(seq 1500); do  # at most 300 s: generating the drive first takes minutes on a loaded machine
		[ -e "$ready" ] && break
		sleep 0.2
	done
	[ -e "$ready" ] || fail "$name: $ready never appeared: $(cat "$name.err")"
	sleep 1  # the child is in its frame loop (or still starting: either way it stops)
	kill -"$sig" "$pid"
	for _ in $(seq 300); do
		kill -0 "$pid" 2> /dev/null || break
		sleep 0.2
	done
	if kill -0 "$pid" 2> /dev/null; then
		fail "$name: vlo-batch still runs 60 s after SIG$sig"
		kill -9 "$pid" $(ours) 2> /dev/null
	fi
	wait "$pid"
	local rc=$?
	[ "$rc" -eq 130 ] || fail "$name: exit code $rc, expected 130"
	tail -1 "$name.err" | grep -qF -- "$text" || fail "$name: stderr: $(cat "$name.err")"
	! grep -q "FAILED" "$name.err" || fail "$name: a stopped task reported as failed: $(cat "$name.err")"
	sleep 0.5
	local left
	left=$(ours)
	if [ -n "$left" ]; then
		fail "$name: still running after vlo-batch ended: $(ps -o args= -p "$(echo $left | tr ' ' ,)")"
		kill -9 $left 2> /dev/null
	fi
	echo "ok: SIG$sig: $(tail -1 "$name.err")"
}

# 1. While vlo-sim generates the drive: no rawlog, ground truth, images or record of it, no run started.
plan gen 300
interrupt TERM gen data/x_Images.partial \
	"vlo-batch: interrupted: stopped generating: x (vlo-sim removes its partial drive); no run started"
left=$(find data gen/runs -mindepth 1 2> /dev/null | head -5)
[ -z "$left" ] || fail "generation: left behind: $left"

# 2. While the runs run (the drive generated first, by the batch): the stopped run's folder is removed,
# no results.md. The vlo run (x/b) is the slower one and is stopped; the lo run (x/a) may have finished
# in the second before the signal on a fast machine: then its folder stays, complete.
plan run 150
interrupt INT run run/runs/x/b/vlo-run.err "vlo-batch: interrupted: stopped runs: "
stopped=$(tail -1 run.err)
[[ "$stopped" == *"x/b"* ]] || fail "runs: x/b not among the stopped: $stopped"
[ -s data/x.rawlog ] && [ -s data/x.sim.txt ] || fail "runs: the finished drive is gone"
[ ! -e run/runs/x/b ] || fail "runs: the stopped run x/b left its folder: $(find run/runs/x/b | head -5)"
if [[ "$stopped" == *"x/a"* ]]; then
	[ ! -e run/runs/x/a ] || fail "runs: the stopped run x/a left its folder: $(find run/runs/x/a | head -5)"
else
	[ -s run/runs/x/a/summary.json ] || fail "runs: x/a neither stopped nor complete: $(find run/runs | head -5)"
fi
[ ! -e run/results.md ] || fail "runs: results.md written"
finish batch_interrupt
