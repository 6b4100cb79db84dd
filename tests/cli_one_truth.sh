#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One run, one truth: APS3 as designed (the truck stopped) and with its ropes' end fittings at a quarter
# of their strength (it breaks through), each read back from its terminal output, summary.json,
# report.html (its text made by the page's own code: tests/one_truth.mjs), events.csv and timeseries.csv:
# the designation as run, the peak deceleration and its time at the terminal's precision, the
# penetration (or how far beyond), the cables counted from 0, the end fittings' strength and the events
# agree. The designation as run is also rate's row for the same condition and a sweep's runs.csv entry,
# and rate's conclusion is its "rating". Exit 77 (skipped) for a build without node (no report.html).
source "$(dirname "$0")/lib.sh"
command -v node >/dev/null || { echo "no node: skipped"; exit 77; }
weak=(--set "barrier.cables[0].termination_efficiency=0.25" --set "barrier.cables[1].termination_efficiency=0.25")
for what in designed weak; do
    extra=()
    [ "$what" = weak ] && extra=("${weak[@]}")
    "$cs" run examples/aps3.yaml -o "$tmp/$what" --report "${extra[@]}" >"$tmp/$what.term" 2>&1
    check "$what: the run (exit 0), with report.html" '[ $? -eq 0 ] && [ -s "$tmp/$what/report.html" ]'
    [ -s "$tmp/$what/report.html" ] || { [ "$what" = designed ] && grep -q "no report.html" "$tmp/$what.term" && exit 77; }
    out=$(node tests/one_truth.mjs "$tmp/$what" "$tmp/$what.term" 2>/dev/null)
    check "$what: every output agrees (tests/one_truth.mjs)" '[ $? -eq 0 ] && [ "$(grep -c "^ok " <<<"$out")" -ge 16 ] || { echo "$out"; false; }'
done
check "designed: the truck stops, the breakthrough gets through" 'grep -q "\"outcome\":\"stopped\"" "$tmp/designed/summary.json" && grep -q "\"outcome\":\"breakthrough\"" "$tmp/weak/summary.json"'
label() { grep -o '"standard":"astm-f2656","label":"[^"]*"' "$1/summary.json" | cut -d'"' -f8; }
check "summary.json: APS3's designation as run is M40/P2" '[ "$(label "$tmp/designed")" = M40/P2 ]'
# rate at the run's own condition (M40) gives the run's designation on its row, and calls its conclusion
# the rating
rate=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M40 2>&1)
check "rate --class M40: its row is the run's designation as run" 'grep -qE "^  M    40 mph  stopped +penetration [0-9.]+ m .* designation as run $(label "$tmp/designed")$" <<<"$rate"'
check "rate --class M40: its conclusion is the rating, in the run's words" 'grep -qxF "rating: $(grep -o "ASTM F2656 M40/P2" "$tmp/designed.term" | head -1)" <<<"$rate"'
# a sweep of one run of the same model: runs.csv gives the same designation as run
printf 'model: %s/examples/aps3.yaml\nmethod: grid\nvary:\n  scenario.speed: [40 mph]\n' "$PWD" >"$tmp/one.yaml"
"$cs" sweep "$tmp/one.yaml" -o "$tmp/sweep" --threads 1 --quiet --allow-path "$PWD/examples" >/dev/null 2>&1
col=$(head -1 "$tmp/sweep/runs.csv" | tr , '\n' | grep -nx astm_f2656_as_run | cut -d: -f1)
check "runs.csv: astm_f2656_as_run is the run's designation as run" '[ -n "$col" ] && [ "$(sed -n 2p "$tmp/sweep/runs.csv" | cut -d, -f"$col")" = "$(label "$tmp/designed")" ]'
finish
