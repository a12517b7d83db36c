# Helpers of the end-to-end scripts: `. "$VLO_SRC/tests/e2e/lib/common.sh"` after `set -u`.
# Starts in a fresh $VLO_WORK; fail() and skip() count, finish NAME reports and sets the exit code (and
# removes $VLO_WORK when every check passed: a failed test's files stay for a look).
W="${VLO_WORK:?}"
rm -rf "$W" && mkdir -p "$W" && cd "$W" || exit 1
fails=0 skips=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
# skip WHY: a check that cannot run here (data or tool missing); the script then exits 77, which ctest reports as
# skipped (and `make test` refuses), never as passed.
skip() { echo "SKIP: $*"; skips=$((skips + 1)); }
# jv FILE KEY: a value of a JSON file written by vlo-eval or vlo-run (one key per line)
jv() { grep -o "\"$2\": [^,]*" "$1" | head -1 | cut -d' ' -f2-; }
# below A B: A is a number and A < B
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a != "null" && a + 0 < b + 0) }'; }
# column CSV NAME: the values of one column, one per line. A real CSV reader (python3's csv module): frames.csv
# quotes cells that hold commas, e.g. vo_reason "initialised (F, 212 points)".
column() {
	python3 - "$1" "$2" <<'PY'
import csv, signal, sys
signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # quiet when the reader stops early (| head)
path, name = sys.argv[1], sys.argv[2]
with open(path, newline="") as f:
    rows = csv.reader(f)
    header = next(rows, [])
    if name not in header:
        sys.exit(f"column: {path}: no column '{name}'")
    c = header.index(name)
    for n, row in enumerate(rows, 2):
        if len(row) != len(header):
            sys.exit(f"column: {path}:{n}: {len(row)} cells, the header has {len(header)}")
        print(row[c])
PY
}
# catching PID SIGNUM: waits (at most 60 s) until process PID has a handler for signal SIGNUM. A background
# job of a script starts with SIGINT ignored, so a signal sent before the program installs its handler is
# lost (on a loaded machine its start-up alone can take seconds). Fails when the process ends first.
catching() {
	local mask
	for _ in $(seq 600); do
		mask=$(awk '/^SigCgt:/ { print $2 }' "/proc/$1/status" 2> /dev/null) || return 1
		[ -n "$mask" ] && (((16#$mask >> ($2 - 1)) & 1)) && return 0
		sleep 0.1
	done
	return 1
}
finish() {
	if [ $fails -gt 0 ]; then echo "$1: $fails failure(s)"; exit 1; fi
	if [ $skips -gt 0 ]; then echo "$1: passed, $skips check(s) skipped"; exit 77; fi
	echo "$1: all passed"
	cd / && rm -rf "$W"  # a passed test's files are not needed; the suite would otherwise keep ~7 GB
	exit 0
}
# expect_exit2 NAME TEXT OUTDIR CMD...: CMD exits with code 2 and one stderr line holding TEXT, and
# leaves OUTDIR (created empty beforehand) empty. The stderr line stays in err.txt.
expect_exit2() {
	local name=$1 text=$2 out=$3
	shift 3
	rm -rf "$out" && mkdir -p "$out"
	"$@" > /dev/null 2> err.txt
	local rc=$?
	[ $rc -eq 2 ] || fail "$name: exit code $rc, expected 2"
	[ "$(wc -l < err.txt)" -eq 1 ] || fail "$name: stderr is not one line: $(cat err.txt)"
	grep -qF -- "$text" err.txt || fail "$name: stderr lacks '$text': $(cat err.txt)"
	[ -z "$(ls -A "$out")" ] || fail "$name: output left behind: $(ls -A "$out")"
	echo "ok: $name: $(cat err.txt)"
}
