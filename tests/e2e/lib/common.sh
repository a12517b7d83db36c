# Helpers of the end-to-end scripts: `. "$VLO_SRC/tests/e2e/lib/common.sh"` after `set -u`.
# Starts in a fresh $VLO_WORK; fail() counts, finish NAME reports and sets the exit code.
W="${VLO_WORK:?}"
rm -rf "$W" && mkdir -p "$W" && cd "$W" || exit 1
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
# jv FILE KEY: a value of a JSON file written by vlo-eval or vlo-run (one key per line)
jv() { grep -o "\"$2\": [^,]*" "$1" | head -1 | cut -d' ' -f2-; }
# below A B: A is a number and A < B
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a != "null" && a + 0 < b + 0) }'; }
# column CSV NAME: the values of one frames.csv column, one per line
column() { awk -F, -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next } { print $c }' "$1"; }
finish() {
	[ $fails -eq 0 ] && echo "$1: all passed" || echo "$1: $fails failure(s)"
	exit $((fails > 0))
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
