#!/usr/bin/env bash
# Checks the tracked C++ sources against .clang-format with Debian's clang-format (package
# clang-format: 14 on bookworm; another major version formats some constructs differently), changing
# nothing. Exit 0 when every file is formatted; else 1 with one line saying how many files and places
# clang-format would change (-v also prints each place). To format: clang-format -i FILE...
# Usage: scripts/check-format.sh [-v] [FILE...]   (default: every tracked .cpp/.h/.hpp/.cc file)
# CLANG_FORMAT=/path/to/clang-format overrides the binary.
set -euo pipefail
cd "$(dirname "$0")/.."
verbose=0
if [ "${1:-}" = "-v" ]; then verbose=1; shift; fi
cf=${CLANG_FORMAT:-clang-format}
if ! command -v "$cf" > /dev/null; then
	echo "check-format: $cf not found (apt-get install clang-format)" >&2
	exit 2
fi
if [ $# -gt 0 ]; then
	files=("$@")
else
	if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
		mapfile -t files < <(git ls-files -- '*.cpp' '*.h' '*.hpp' '*.cc')
	else  # an export without .git: the same folders
		mapfile -t files < <(find modules apps bench fuzz tests -name '*.cpp' -o -name '*.h' -o -name '*.hpp' -o -name '*.cc' | sort)
	fi
fi
[ ${#files[@]} -gt 0 ] || { echo "check-format: no C++ files"; exit 0; }
version=$("$cf" --version | grep -oE '[0-9]+\.[0-9]+\.[0-9]+' | head -1)
report=$(mktemp)
trap 'rm -f "$report"' EXIT
# One process for all files; every place to change is one "warning:" line on stderr.
"$cf" --style=file --dry-run --Werror "${files[@]}" 2> "$report" > /dev/null || true
places=$(grep -c ': warning: \|: error: ' "$report" || true)
if [ "$places" -eq 0 ]; then
	echo "check-format: ${#files[@]} files formatted (clang-format $version)"
	exit 0
fi
[ "$verbose" -eq 0 ] || grep ': warning: \|: error: ' "$report" >&2
nfiles=$(grep -oE '^[^:]+:[0-9]+:[0-9]+: (warning|error): ' "$report" | cut -d: -f1 | sort -u | wc -l)
echo "check-format: $nfiles of ${#files[@]} files not formatted, $places places (clang-format $version;" \
	"-v lists them, clang-format -i FILE formats)" >&2
exit 1
