#!/usr/bin/env bash
# The main job of `make run`: ./scripts/run-sample.sh BIN_DIR RESULTS_DIR
# 1. Generates the project's sample drive into rawlogs/ (deterministic; regenerated only when missing,
#    made with other settings, or older than the vlo-sim binary).
# 2. Runs whatever of the pipeline is built on it (vlo-run + vlo-eval, else a ground-truth snapshot).
# 3. Says where everything is.
set -euo pipefail
BIN=${1:-build/bin}
OUT=${2:-results/sample}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SAMPLE="$ROOT/rawlogs/sample.rawlog"
GT="$ROOT/rawlogs/sample.gt.tum"
STAMP="$ROOT/rawlogs/sample.cmd"
ARGS=(--scenario urban --lidar hdl64 --frames 80 --seed 7)  # 96 m with a bend and a slope

[ -x "$BIN/vlo-sim" ] || { echo "run-sample: $BIN/vlo-sim is not built (run 'make build')" >&2; exit 1; }
if [ ! -f "$SAMPLE" ] || [ ! -f "$GT" ] || [ "$(cat "$STAMP" 2> /dev/null)" != "${ARGS[*]}" ] ||
	[ "$BIN/vlo-sim" -nt "$SAMPLE" ]; then
	echo "run-sample: generating the sample drive (vlo-sim ${ARGS[*]}, about a minute)"
	"$BIN/vlo-sim" "${ARGS[@]}" --out "$SAMPLE"
	echo "${ARGS[*]}" > "$STAMP"
fi

mkdir -p "$OUT"
INI="$ROOT/ini/sim-hdl64.ini"
if [ -x "$BIN/vlo-run" ] && [ -f "$INI" ]; then
	"$BIN/vlo-run" --rawlog "$SAMPLE" --ini "$INI" --out "$OUT" --gt "$GT" --overwrite  # results/sample is make run's own
	# The final trajectory of the configured mode, as summary.json names it.
	TRAJ=$(grep -o '"trajectory": "[^"]*"' "$OUT/summary.json" | cut -d'"' -f4)
	if [ -x "$BIN/vlo-eval" ] && [ -f "$OUT/$TRAJ" ]; then
		"$BIN/vlo-eval" --gt "$GT" --est "$OUT/$TRAJ" --metric all --kitti-lengths 20,40,60,80 --json "$OUT/eval.json"
	fi
elif [ -x "$BIN/vlo-snapshot" ]; then
	echo "run-sample: vlo-run or $INI is missing; drawing the ground truth and two frames instead"
	"$BIN/vlo-snapshot" --gt "$GT" --rawlog "$SAMPLE" --frame 0 --frame 60 \
		--title "vlo sample drive: ground truth" --out "$OUT/snapshots"
fi
echo "run-sample: sample drive $SAMPLE (ground truth $GT); results in $OUT"
