#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One run, one truth: APS3 as designed (the truck stopped), with its ropes' end fittings at a quarter
# of their strength (it breaks through), and APS1 with its ropes at half strength at the threaded posts'
# holes (a rope breaks at a post's hole: every output names that post), and roadside RS1 (redirected: the
# outcome's time is the loss of contact, its ropes peak between output frames), each read back from its terminal
# output, summary.json, report.html (its text made by the page's own code: tests/one_truth.mjs),
# events.csv and timeseries.csv:
# the designation as run, the peak deceleration and its time at the terminal's precision, the
# penetration (or how far beyond), the cables counted from 0, the end fittings' strength and the events
# agree, and report.html's data gives the unit of every number it holds, as the CSVs write it; compare's
# table gives each run's own numbers. The designation as run is also rate's row for the
# same condition and a sweep's runs.csv entries (with the ASTM F2656 penetration the label rests on, and
# SD-STD-02.01's), and rate's conclusion is its "rating". Exit 77 (skipped)
# for a build without node (no report.html). The designer page's numbers for the same run are checked
# against these outputs in a browser: designer_one_truth (report/test/designer_truth.mjs).
source "$(dirname "$0")/lib.sh"
command -v node >/dev/null || { echo "no node: skipped"; exit 77; }
weak=(--set "barrier.cables[0].termination_efficiency=0.25" --set "barrier.cables[1].termination_efficiency=0.25")
hole=(--set "barrier.cables[0].hole_efficiency=0.5" --set "barrier.cables[1].hole_efficiency=0.5")
for what in designed weak hole rs1; do
    extra=()
    [ "$what" = weak ] && extra=("${weak[@]}")
    [ "$what" = hole ] && extra=("${hole[@]}")
    model=examples/aps3.yaml
    [ "$what" = hole ] && model=examples/aps1.yaml
    [ "$what" = rs1 ] && model=examples/roadside/rs1.yaml
    "$cs" run "$model" -o "$tmp/$what" --report "${extra[@]}" >"$tmp/$what.term" 2>&1
    check "$what: the run (exit 0), with report.html" '[ $? -eq 0 ] && [ -s "$tmp/$what/report.html" ]'
    [ -s "$tmp/$what/report.html" ] || { [ "$what" = designed ] && grep -q "no report.html" "$tmp/$what.term" && exit 77; }
    out=$(node tests/one_truth.mjs "$tmp/$what" "$tmp/$what.term" 2>/dev/null)
    check "$what: every output agrees (tests/one_truth.mjs)" '[ $? -eq 0 ] && [ "$(grep -c "^ok " <<<"$out")" -ge 16 ] || { echo "$out"; false; }'
done
check "hole: APS1's ropes at half strength at the holes break at a post's hole, and every output says where" 'grep -q "at post [0-9]*'"'"'s hole$" "$tmp/hole.term" && node tests/one_truth.mjs "$tmp/hole" "$tmp/hole.term" 2>/dev/null | grep -q "^ok breaks at a hole: report.html"'
check "designed: the truck stops, the breakthrough gets through" 'grep -q "\"outcome\":\"stopped\"" "$tmp/designed/summary.json" && grep -q "\"outcome\":\"breakthrough\"" "$tmp/weak/summary.json"'
# compare of the two runs: each column of compare.csv gives its run's summary.json, to the digit written
"$cs" compare "$tmp/designed" "$tmp/weak" -o "$tmp/compare" >/dev/null 2>&1
check "compare: exit 0 and compare.csv" '[ $? -eq 0 ] && [ -s "$tmp/compare/compare.csv" ]'
out=$(node -e '
const fs = require("fs"), [csv, ...runs] = process.argv.slice(1);
const rows = fs.readFileSync(csv, "utf8").trim().split("\n").map((l) => l.split(","));
const keys = { outcome: "outcome", "max 50-ms deceleration": "max_50ms_decel_g",
  "time of the max 50-ms deceleration": "t_max_50ms_decel_s", "max dynamic penetration": "max_dynamic_penetration_m",
  "penetration beyond": "penetration_beyond_m", "max barrier deflection": "max_barrier_deflection_m",
  "working width": "working_width_m", "exit speed": "exit_speed_mps", "max cable tension": "max_cable_tension_n" };
let bad = 0, seen = 0;
runs.forEach((dir, k) => {
  const sj = JSON.parse(fs.readFileSync(dir + "/summary.json", "utf8"));
  for (const r of rows) {
    const key = keys[r[0]];
    if (!key) continue;
    const want = sj[key], got = r[2 + k];
    const same = want === null ? got === "" : typeof want === "string" ? got === want : Math.abs(Number(got) - want) <= 1e-9 * Math.abs(want);
    seen++;
    if (!same) { bad++; console.log(`${dir}: ${r[0]}: compare.csv ${got}, summary.json ${want}`); }
  }
});
console.log(`${seen} values, ${bad} differ`);
process.exit(bad || seen < 18 ? 1 : 0);' "$tmp/compare/compare.csv" "$tmp/designed" "$tmp/weak")
check "compare: compare.csv gives each run's summary.json values" '[ $? -eq 0 ] || { echo "$out"; false; }'
# a standard's label of the run's designation as run in summary.json: astm-f2656 or sd-std-02.01
label() { grep -o '"standard":"'"${2:-astm-f2656}"'","label":"[^"]*"' "$1/summary.json" | cut -d'"' -f8; }
check "summary.json: APS3's designation as run is M40/P2" '[ "$(label "$tmp/designed")" = M40/P2 ]'
# rate at the run's own condition (M40) gives the run's designation on its row, and calls its conclusion
# the rating
rate=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M40 2>&1)
check "rate --class M40: its row is the run's designation as run" 'grep -qE "^  M    40 mph  stopped +penetration [0-9.]+ m .* designation as run $(label "$tmp/designed")$" <<<"$rate"'
check "rate --class M40: its conclusion is the rating, in the run's words" 'grep -qxF "rating: $(grep -o "ASTM F2656 M40/P2 (penetration .*)$" "$tmp/designed.term" | head -1)" <<<"$rate"'
# a sweep of one run of the same model: runs.csv gives the same designations as run, ASTM F2656's with
# the penetration `run` prints for it (to its 2 decimals), SD-STD-02.01's as `run` has it
printf 'model: %s/examples/aps3.yaml\nmethod: grid\nvary:\n  scenario.speed: [40 mph]\n' "$PWD" >"$tmp/one.yaml"
"$cs" sweep "$tmp/one.yaml" -o "$tmp/sweep" --threads 1 --quiet --allow-path "$PWD/examples" >/dev/null 2>&1
cell() { # runs.csv's cell of its one run in the column headed $1
    local col
    col=$(head -1 "$tmp/sweep/runs.csv" | tr , '\n' | grep -nxF "$1" | cut -d: -f1)
    [ -n "$col" ] && sed -n 2p "$tmp/sweep/runs.csv" | cut -d, -f"$col"
}
check "runs.csv: astm_f2656_as_run is the run's designation as run" '[ "$(cell astm_f2656_as_run)" = "$(label "$tmp/designed")" ]'
pen=$(cell "astm_f2656_penetration [m]")
check "runs.csv: astm_f2656_penetration is the penetration run prints for that designation" '[ -n "$pen" ] && grep -qF "ASTM F2656 $(label "$tmp/designed") (penetration $(printf "%.2f" "$pen") m " "$tmp/designed.term"'
check "runs.csv: sd_std_02_01_as_run is the run's SD-STD-02.01 designation as run" '[ -n "$(label "$tmp/designed" sd-std-02.01)" ] && [ "$(cell sd_std_02_01_as_run)" = "$(label "$tmp/designed" sd-std-02.01)" ] && grep -qF "SD-STD-02.01 $(cell sd_std_02_01_as_run) (" "$tmp/designed.term"'
# a dead-man that rises out of the soil (APS3 with the dead-men's skin at the beta method's friction):
# summary.json's lift_m, the terminal's rise and timeseries.csv's last anchor0_lift are one number
beta=(--set "barrier.anchors.start.footing.skin_friction=25.4 kPa/m" --set "barrier.anchors.end.footing.skin_friction=25.4 kPa/m")
"$cs" run examples/aps3.yaml -o "$tmp/rise" "${beta[@]}" >"$tmp/rise.term" 2>&1
lift=$(grep -o '"anchor_start":{[^}]*"lift_m":[^,]*' "$tmp/rise/summary.json" | sed 's/.*"lift_m"://')
col=$(head -1 "$tmp/rise/timeseries.csv" | tr , '\n' | grep -nxF "anchor0_lift [m]" | cut -d: -f1)
last=$(tail -1 "$tmp/rise/timeseries.csv" | cut -d, -f"$col")
check "rise: summary.json's lift_m, the terminal's and timeseries.csv's last row agree (> 0)" \
    'awk -v a="$lift" -v b="$last" "BEGIN { exit !(a > 0.01 && a == b) }" && grep -qF "start anchor" "$tmp/rise.term" && grep -q "risen $(printf "%.3f" "$lift") m" "$tmp/rise.term"'
finish
