#!/usr/bin/env bash
# The e2e helper column() reads CSV as CSV: a quoted cell with a comma (or a quote, or a line break) does not
# shift the columns after it; a missing column or a short row is an error, not an empty or wrong value.
set -u
. "$VLO_SRC/tests/e2e/lib/common.sh"

printf '%s\n' 'frame,vo_reason,lo_prior' '0,"initialised (F, 212 points)",none' '1,ok,external' \
	'2,"lost: ""few"", matches",constant_velocity' '3,"two' 'lines",external' > frames.csv
[ "$(column frames.csv lo_prior | paste -sd' ')" = "none external constant_velocity external" ] ||
	fail "lo_prior after a quoted comma: $(column frames.csv lo_prior | paste -sd' ')"
[ "$(column frames.csv vo_reason | head -1)" = "initialised (F, 212 points)" ] || fail "quoted cell not unquoted"
[ "$(column frames.csv vo_reason | sed -n 3p)" = 'lost: "few", matches' ] || fail "doubled quote not unescaped"
[ "$(column frames.csv frame | paste -sd' ')" = "0 1 2 3" ] || fail "first column"

column frames.csv no_such 2> err.txt > /dev/null && fail "missing column accepted"
grep -q "no column 'no_such'" err.txt || fail "missing column: $(cat err.txt)"
printf '%s\n' 'a,b,c' '1,2' > short.csv
column short.csv c 2> err.txt > /dev/null && fail "short row accepted"
grep -q "short.csv:2: 2 cells" err.txt || fail "short row: $(cat err.txt)"

finish csv_column
