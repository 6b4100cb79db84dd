#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cablesim compare: two runs and a measured history made from the first (time in ms, speed in mph,
# penetration in ft): the measured history's 50-ms deceleration, found from its speed by the engine's
# rule, equals the run's to 0.1% and every difference of that run from it is under 0.1% (the penetration
# of a run that broke through is a lower bound, written "beyond" and not compared); the slower run
# differs; the page holds the table and five plots; bad input exits 2 naming the place, and writes nothing.
source "$(dirname "$0")/lib.sh"
# both with the ropes' end fittings at a quarter of their strength, both break through; run a written at
# every step, so that the measured history made from it resolves its breaks
weak=(--set "barrier.cables[0].termination_efficiency=0.25" --set "barrier.cables[1].termination_efficiency=0.25")
"$cs" run examples/aps3.yaml -o "$tmp/a" "${weak[@]}" --set "scenario.output_interval=0.5 ms" >/dev/null 2>&1
"$cs" run examples/aps3.yaml -o "$tmp/b" "${weak[@]}" --set 'scenario.speed=35 mph' >/dev/null 2>&1
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; print "time [ms],speed [mph],penetration (ft)"; next }
         { printf "%.6f,%.9f,%.9f\n", $c["t [s]"] * 1000, $c["forward_speed [m/s]"] / 0.44704, $c["penetration [m]"] / 0.3048 }' \
    "$tmp/a/timeseries.csv" >"$tmp/measured.csv"
out=$("$cs" compare "$tmp/a" "$tmp/b" --measured "$tmp/measured.csv" -o "$tmp/cmp" 2>&1)
check "compare runs (exit 0)" '[ $? -eq 0 ]'
csv="$tmp/cmp/compare.csv"
# column 3: run a, 4: run b, 5: measured, 6 and 7: a and b against the measured history in %
value() { awk -F, -v p="$1" -v c="$2" '$1 == p { print $c }' "$csv"; }
check "the measured 50-ms deceleration is the run's (0.1%)" \
    'awk -v a="$(value "max 50-ms deceleration" 3)" -v m="$(value "max 50-ms deceleration" 5)" "BEGIN { exit !(a > 1 && (a - m) / a < 1e-3 && (m - a) / a < 1e-3) }"'
for p in "max 50-ms deceleration" "speed at the end along the initial heading"; do
    check "run a against the measured history: $p under 0.1%" \
        'awk -v d="$(value "$p" 6)" "BEGIN { exit !(d != \"\" && d < 0.1 && d > -0.1) }"'
done
# run a broke through: as in its summary.json, it has no max dynamic penetration, and its "penetration
# beyond" is where it had got when the run ended, a lower bound, not compared
json() { grep -o "\"$1\":[^,]*" "$tmp/a/summary.json" | head -1 | cut -d: -f2; }
check "a breakthrough: max dynamic penetration empty, as null in summary.json" \
    '[ -z "$(value "max dynamic penetration" 3)" ] && [ "$(json max_dynamic_penetration_m)" = null ] && grep -q "^| max dynamic penetration | - " "$tmp/cmp/compare.md"'
check "a breakthrough: penetration beyond is summary.json's (1e-9), with no difference" \
    'awk -v a="$(value "penetration beyond" 3)" -v j="$(json penetration_beyond_m)" "BEGIN { exit !(a > 1 && (a - j) ^ 2 < (1e-9 * j) ^ 2) }" && [ -z "$(value "penetration beyond" 6)" ] && grep -q "^| penetration beyond | beyond " "$tmp/cmp/compare.md"'
check "the measured penetration is its own largest: run a's penetration beyond (0.1%)" \
    'awk -v a="$(value "penetration beyond" 3)" -v m="$(value "max dynamic penetration" 5)" "BEGIN { exit !(a > 1 && (a - m) / a < 1e-3 && (m - a) / a < 1e-3) }"'

# RS1's pickup is redirected: at the run's end it moves at 17.01 m/s (17.89 m/s at its exit), of which
# 13.52 m/s is along its first heading; the speed compared (the runs' forward_speed, a measured history's speed) is that
# component, and its row says so, as the plot of it does, beside the exit speed
"$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1" >/dev/null 2>&1
"$cs" compare "$tmp/rs1" -o "$tmp/cmp-rs1" >/dev/null 2>&1
rs1() { awk -F, -v p="$1" '$1 == p { print $3 }' "$tmp/cmp-rs1/compare.csv"; }
last=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } { v = $c["forward_speed [m/s]"] } END { print v }' "$tmp/rs1/timeseries.csv")
check "a redirected run: the speed at the end named along the initial heading, timeseries.csv's last forward_speed, beside the exit speed" \
    '[ -n "$(rs1 "speed at the end along the initial heading")" ] && [ "$(rs1 "speed at the end along the initial heading")" = "$last" ] && [ "$(rs1 "exit speed")" != "$last" ] && grep -q "^| speed at the end along the initial heading | " "$tmp/cmp-rs1/compare.md" || { cat "$tmp/cmp-rs1/compare.csv"; false; }'

# the measured history with every cell quoted, as spreadsheets write CSV (RFC 4180): read as the same file
# unquoted, its parameters the same to the last digit written
sed 's/[^,]*/"&"/g' "$tmp/measured.csv" >"$tmp/quoted.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/quoted.csv" -o "$tmp/cmpq" 2>&1)
check "a measured history of quoted cells (exit 0)" '[ $? -eq 0 ] || { echo "$out"; false; }'
quoted() { awk -F, -v p="$1" '$1 == p { print $4 }' "$tmp/cmpq/compare.csv"; }
for p in "max 50-ms deceleration" "max dynamic penetration" "speed at the end along the initial heading"; do
    check "quoted cells: the measured $p is the unquoted one's" \
        '[ -n "$(value "$p" 5)" ] && [ "$(quoted "$p")" = "$(value "$p" 5)" ]'
done

# a run's own timeseries.csv as the measured history: read as that run's (its own 50-ms average), so its
# parameters are run a's: the 50-ms deceleration to 1e-6, the largest penetration to 0.1%
out=$("$cs" compare "$tmp/b" --measured "$tmp/a/timeseries.csv" -o "$tmp/own" 2>&1)
check "compare --measured takes a run's own timeseries.csv (exit 0)" '[ $? -eq 0 ] || { echo "$out"; false; }'
own() { awk -F, -v p="$1" -v c="$2" '$1 == p { print $c }' "$tmp/own/compare.csv"; }
check "a run's timeseries.csv as measured: its 50-ms deceleration is the run's (1e-6)" \
    'awk -v a="$(value "max 50-ms deceleration" 3)" -v m="$(own "max 50-ms deceleration" 4)" "BEGIN { exit !(a > 1 && (a - m) ^ 2 < (1e-6 * a) ^ 2) }"'
check "a run's timeseries.csv as measured: its largest penetration is the run's penetration beyond (0.1%)" \
    'awk -v a="$(value "penetration beyond" 3)" -v m="$(own "max dynamic penetration" 4)" "BEGIN { exit !(a > 1 && (a - m) ^ 2 < (1e-3 * a) ^ 2) }"'

# saved again by a spreadsheet as "CSV UTF-8", a byte order mark before its header: still read as the run's
{ printf '\357\273\277'; cat "$tmp/a/timeseries.csv"; } >"$tmp/bom.csv"
out=$("$cs" compare "$tmp/b" --measured "$tmp/bom.csv" -o "$tmp/own-bom" 2>&1)
check "a run's timeseries.csv after a byte order mark: read as the run's, the same parameters" \
    '[ $? -eq 0 ] && cmp -s <(cut -d, -f1,4 "$tmp/own/compare.csv" | sed 1d) <(cut -d, -f1,4 "$tmp/own-bom/compare.csv" | sed 1d) || { echo "$out"; false; }'

check "run b (35 mph) differs in its 50-ms deceleration by over 5%" \
    'awk -v d="$(value "max 50-ms deceleration" 7)" "BEGIN { exit !(d > 5 || d < -5) }"'
check "outcomes in the table" 'grep -q "^outcome,,breakthrough,breakthrough," "$csv"'
check "the page has the table and five plots" \
    '[ "$(grep -o "<svg" "$tmp/cmp/compare.html" | wc -l)" -eq 5 ] && grep -q "<table>" "$tmp/cmp/compare.html"'
check "five PNG and five SVG plots" '[ "$(ls "$tmp/cmp/plots" | grep -c "^compare-.*\.png$")" -eq 5 ] && [ "$(ls "$tmp/cmp/plots" | grep -c "^compare-.*\.svg$")" -eq 5 ]'
# Validation metrics (NCHRP W179): run a against itself gives M = P = 0; against its own speed divided by
# 1.1 (at the same times) the run's speed is 1.1 times the measured one: M = 0.1, P = 0
m="$tmp/cmp/metrics.csv"
metric() { awk -F, -v r="$2" -v c="$3" '$2 == r && $1 ~ /\/a"?$/ { print $c }' "$1"; }
check "metrics.csv: run a's speed against itself, M and P 0" \
    'awk -v M="$(metric "$m" speed 4)" -v P="$(metric "$m" speed 5)" "BEGIN { exit !(M != \"\" && M < 1e-6 && M > -1e-6 && P < 1e-3) }" && [ "$(metric "$m" speed 9)" = pass ]'
check "the terminal and the page give the metrics" 'grep -qE "^validation metrics \(NCHRP W179\)" <<<"$out" && grep -q "<h2>Validation metrics (NCHRP W179)</h2>" "$tmp/cmp/compare.html"'
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; print "time [s],speed [m/s]"; next }
         { printf "%.9f,%.12g\n", $c["t [s]"], $c["forward_speed [m/s]"] / 1.1 }' "$tmp/a/timeseries.csv" >"$tmp/slow.csv"
"$cs" compare "$tmp/a" --measured "$tmp/slow.csv" -o "$tmp/cmp11" >/dev/null 2>&1
check "run a against its speed / 1.1: Sprague-Geers M = 0.1, P = 0" \
    'awk -v M="$(metric "$tmp/cmp11/metrics.csv" speed 4)" -v P="$(metric "$tmp/cmp11/metrics.csv" speed 5)" "BEGIN { exit !(M != \"\" && M - 0.1 < 1e-6 && 0.1 - M < 1e-6 && P < 1e-3) }"'

# bad input
# a column is compared as what its name says, its unit checked against it: a length named foo is not read
# as the penetration, nor a speed given in metres
printf 'time [s],speed [mph],foo [m]\n0,40,1\n0.001,40,1\n' >"$tmp/noname.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/noname.csv" -o "$tmp/bad0" 2>&1)
rc=$?
check "a column whose name names no quantity exits 2 at line 1, column 22" \
    '[ $rc -eq 2 ] && grep -qF "noname.csv:1:22: '"'"'foo [m]'"'"' names no quantity compared (expected a name holding decel, accel, speed, velocity, penetration or tension" <<<"$out" && [ ! -e "$tmp/bad0" ]'
printf 'time [s],speed [m]\n0,1\n0.001,1\n' >"$tmp/badunit.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/badunit.csv" -o "$tmp/bad1" 2>&1)
rc=$?
check "a unit that does not fit the name exits 2 at line 1, column 10" \
    '[ $rc -eq 2 ] && grep -qF "badunit.csv:1:10: '"'"'speed [m]'"'"' names a speed: '"'"'m'"'"' is a unit of length, not of speed (expected mph, km/h or m/s)" <<<"$out" && [ ! -e "$tmp/bad1" ]'
printf 'time [s],speed [mph]\n0,40\n0.002,x\n' >"$tmp/badcell.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/badcell.csv" -o "$tmp/bad2" 2>&1)
check "a cell that is not a number exits 2 at its place" '[ $? -eq 2 ] && grep -q "badcell.csv:3:7: .x. is not a number" <<<"$out"'
printf 'time [s],speed [mph]\n0,40\n0.002,"4O"\n' >"$tmp/quotedtext.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/quotedtext.csv" -o "$tmp/bad-quoted" 2>&1)
check "a quoted cell that is not a number exits 2 at its place" '[ $? -eq 2 ] && grep -q "quotedtext.csv:3:7: .4O. is not a number" <<<"$out" && [ ! -e "$tmp/bad-quoted" ]'
# a row the CSV reader cannot cut (text after a closing quote, a quote not closed) is the file's fault, at its
# place, in a data row and in the header alike: not "out of memory"
printf 'time [s],speed [mph]\n0,40\n0.002,"4"0\n' >"$tmp/afterquote.csv"
printf '"time [s],speed [mph]\n0,40\n0.002,40\n' >"$tmp/openquote.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/afterquote.csv" -o "$tmp/bad-after" 2>&1)
rc=$?
out2=$("$cs" compare "$tmp/a" --measured "$tmp/openquote.csv" -o "$tmp/bad-open" 2>&1)
check "a row that cannot be cut exits 2 at its place, the header's too" \
    '[ $rc -eq 2 ] && grep -q "afterquote.csv:3:10: .0. after a quoted cell.s closing quote" <<<"$out" && grep -q "openquote.csv:1:1: a quoted cell not closed" <<<"$out2" && ! grep -q "out of memory" <<<"$out$out2" && [ ! -e "$tmp/bad-after" ] && [ ! -e "$tmp/bad-open" ]'
printf 'time [s],speed [mph]\n0,1e300\n0.1,1e300\n0.2,0\n' >"$tmp/huge.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/huge.csv" -o "$tmp/bad-huge" 2>&1)
check "a value beyond any crash history (its metrics would be inf) exits 2 at its place" '[ $? -eq 2 ] && grep -q "huge.csv:2:3: .1e300. is too large" <<<"$out" && [ ! -e "$tmp/bad-huge" ]'
# a run's folder is read as strictly as a measured history: a nan in timeseries.csv, a summary that is not
# JSON or holds text where a number belongs, each at its place
mkdir -p "$tmp/d1" "$tmp/d2" "$tmp/d3"
cp "$tmp/a/summary.json" "$tmp/d1/" && sed -E '3s/^(([^,]*,){4})[^,]*/\1nan/' "$tmp/a/timeseries.csv" >"$tmp/d1/timeseries.csv"
out=$("$cs" compare "$tmp/d1" -o "$tmp/bad-nan" 2>&1)
check "a nan in a run's timeseries.csv exits 2 at its place" '[ $? -eq 2 ] && grep -qE "d1/timeseries.csv:3:[0-9]+: .nan. is not a number" <<<"$out" && [ ! -e "$tmp/bad-nan" ]'
cp "$tmp/a/timeseries.csv" "$tmp/d2/" && head -c 40 "$tmp/a/summary.json" >"$tmp/d2/summary.json"
out=$("$cs" compare "$tmp/d2" -o "$tmp/bad-cut" 2>&1)
check "a cut summary.json exits 2 at where it ends" '[ $? -eq 2 ] && grep -qE "d2/summary.json:[0-9]+:[0-9]+: not JSON: it ends too soon" <<<"$out"'
cp "$tmp/a/timeseries.csv" "$tmp/d3/" && sed 's/"max_50ms_decel_g": *[0-9.e+-]*/"max_50ms_decel_g": "abc"/' "$tmp/a/summary.json" >"$tmp/d3/summary.json"
out=$("$cs" compare "$tmp/d3" -o "$tmp/bad-text" 2>&1)
check "text where summary.json has a number exits 2, naming it" '[ $? -eq 2 ] && grep -qF "d3/summary.json: max_50ms_decel_g is \"abc\" (expected a number" <<<"$out"'
out=$("$cs" compare "$tmp/a" --measured -o "$tmp/bad-opt" 2>&1)
check "--measured followed by an option: its value left out, said so" '[ $? -eq 2 ] && grep -qxF "cablesim compare: option '"'"'--measured'"'"' needs a value, and '"'"'-o'"'"' is an option" <<<"$out" && [ ! -e "$tmp/bad-opt" ]'
printf 'time [s],speed [mph],speed [km/h]\n0,40,64\n' >"$tmp/twice.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/twice.csv" -o "$tmp/bad-twice" 2>&1)
check "a quantity in two columns: both named, at the second" '[ $? -eq 2 ] && grep -qF "twice.csv:1:22: '"'"'speed [km/h]'"'"' is a second column of the quantity of '"'"'speed [mph]'"'"' (the header'"'"'s column 2, at 1:10)" <<<"$out"'
printf 'time [s],speed [mph] [km/h]\n0,40\n0.1,38\n' >"$tmp/twounits.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/twounits.csv" -o "$tmp/bad-units" 2>&1)
check "a column named with two units: both named, at its place, nothing written" '[ $? -eq 2 ] && grep -qF "twounits.csv:1:10: '"'"'speed [mph] [km/h]'"'"' names two units of a speed, '"'"'mph'"'"' and '"'"'km/h'"'"'" <<<"$out" && [ ! -e "$tmp/bad-units" ]'
printf 'time [s],speed [mph]\n0,40\n0,39\n' >"$tmp/back.csv"
out=$("$cs" compare "$tmp/a" --measured "$tmp/back.csv" -o "$tmp/bad3" 2>&1)
check "time that does not grow exits 2" '[ $? -eq 2 ] && grep -q "back.csv:3:1: the time goes back or stands" <<<"$out"'
# A measured history is read whole, from a regular file only: /dev/zero, which grew the reader to 8 GB, and a
# FIFO, which blocked it, are refused at once (within the 10 s the test gives them).
out=$(timeout 10 "$cs" compare "$tmp/a" --measured /dev/zero -o "$tmp/bad5" 2>&1)
check "/dev/zero as the measured history is refused at once (exit 2)" \
    '[ $? -eq 2 ] && grep -q "/dev/zero: a character device, not a regular file" <<<"$out" && [ ! -e "$tmp/bad5" ]'
mkfifo "$tmp/fifo.csv"
out=$(timeout 10 "$cs" compare "$tmp/a" --measured "$tmp/fifo.csv" -o "$tmp/bad6" 2>&1)
check "a FIFO as the measured history is refused at once (exit 2)" \
    '[ $? -eq 2 ] && grep -q "fifo.csv: a FIFO, not a regular file" <<<"$out" && [ ! -e "$tmp/bad6" ]'
out=$("$cs" compare "$tmp/nothing" -o "$tmp/bad4" 2>&1)
check "a missing run folder exits 2 with the system's reason" '[ $? -eq 2 ] && grep -q "nothing/summary.json: No such file or directory" <<<"$out"'
out=$("$cs" compare "$tmp/a" --frobnicate 2>&1)
check "an unknown option is named (exit 2)" '[ $? -eq 2 ] && grep -q "unknown option .--frobnicate." <<<"$out"'
"$cs" compare --help >/dev/null 2>&1
check "--help exits 0" '[ $? -eq 0 ]'
finish
