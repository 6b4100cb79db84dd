#!/usr/bin/env bash
# The command end to end: help, version, list, check, a short run of examples/aps3.yaml and its outputs,
# --set on the command line, that a refused model writes nothing, and that a run repeats byte for byte.
source "$(dirname "$0")/lib.sh"

check "--help" '"$cs" --help | grep -q "^Usage: cablesim run FILE"'
check "--version" '"$cs" --version | grep -q "^cablesim [0-9]"'
"$cs" frobnicate >/dev/null 2>&1
check "unknown command is status 2" '[ $? -eq 2 ]'
"$cs" run >/dev/null 2>&1
check "run without a file is status 2" '[ $? -eq 2 ]'
check "list exits 0 and names the parts" \
    '"$cs" list >"$tmp/list" && grep -q "^  M " "$tmp/list" && grep -q "A603-1.75in" "$tmp/list" && grep -q "HSS4x4x1/8" "$tmp/list"'
check "list names its folder: the source tree's data/ for a program of the build tree" \
    '"$cs" list | head -1 | grep -qx "Parts library: $PWD/data"'
mkdir "$tmp/parts" && cp data/*.yaml "$tmp/parts/" && sed -i 's/^    - name: H$/    - name: H-renamed/' "$tmp/parts/vehicles.yaml"
check "CABLESIM_DATA moves the parts library" \
    'CABLESIM_DATA="$tmp/parts" "$cs" list | grep -q "^  H-renamed " && CABLESIM_DATA="$tmp/parts" "$cs" list | head -1 | grep -qx "Parts library: $tmp/parts"'
CABLESIM_DATA="$tmp/none" "$cs" list >/dev/null 2>"$tmp/stderr"
check "a CABLESIM_DATA that is no folder: status 2, named" '[ $? -eq 2 ] && grep -q "^$tmp/none: cannot read the parts library (CABLESIM_DATA; " "$tmp/stderr"'
for f in examples/*.yaml; do
    check "check $f" '"$cs" check "$f" >/dev/null'
done
check "check --set" '"$cs" check examples/aps3.yaml --set scenario.speed="35 mph" --set "barrier.cables[0].pretension=8 kip" >/dev/null'

out="$tmp/aps3"
"$cs" run examples/aps3.yaml -o "$out" --t-end "20 ms" --set scenario.speed="35 mph" >"$tmp/stdout" 2>"$tmp/stderr"
check "run exits 0" '[ $? -eq 0 ] || { cat "$tmp/stderr"; false; }'
check "run prints a summary in SI and US units" 'grep -q "mph" "$tmp/stdout" && grep -q "kip" "$tmp/stdout" && grep -q " ft)" "$tmp/stdout"'
for f in timeseries.csv events.csv summary.json; do
    check "$f written" '[ -s "$out/$f" ]'
done
check "no temporaries left" '[ -z "$(ls "$out" | grep "\.tmp$")" ]'
check "timeseries header has units" 'head -1 "$out/timeseries.csv" | grep -q "^t_s,x_m,y_m,z_m,vx_mps,.*decel_50ms_g.*cable0_max_tension_n.*post0_state.*energy_balance_error$"'
check "timeseries has rows" '[ "$(wc -l <"$out/timeseries.csv")" -gt 10 ]'
check "events header" 'head -1 "$out/events.csv" | grep -q "^t_s,type,element_kind,element,value_si$"'
for key in max_50ms_decel_g max_dynamic_penetration_m max_barrier_deflection_m stopped stop_time_s exit_speed_mps \
    posts_failed_left posts_failed_right initial_kinetic_energy_j energy_balance_error events inputs; do
    check "summary.json has $key" 'grep -q "\"$key\":" "$out/summary.json"'
done
# Every field of the C summary (cs_summary in include/cablesim/sim.h) is a key of summary.json by the same name.
fields=$(sed -n '/^typedef struct cs_summary {/,/^} cs_summary;/p' include/cablesim/sim.h | perl -0pe 's{/\*.*?\*/}{}gs' |
    grep -v cs_summary | grep -oE '[a-z_0-9]+(\[[0-9]+\])?[,;]' | tr -d ',;' | sed 's/\[.*//')
check "the fields of cs_summary were read" '[ "$(wc -w <<<"$fields")" -ge 26 ]'
for key in $fields; do
    check "summary.json has cs_summary's $key" 'grep -q "\"$key\":" "$out/summary.json"'
done
check "--set reached the run" 'grep -q "\"speed\":15.6464" "$out/summary.json"'
check "no NaN or infinity in outputs" '! grep -qiE "(^|[,:[])-?(nan|inf)" "$out/timeseries.csv" "$out/summary.json" "$out/events.csv"'

cp "$out/summary.json" "$tmp/before.json"
"$cs" run examples/aps3.yaml -o "$out" --set scenario.speed="35 kg" >/dev/null 2>"$tmp/stderr"
check "a refused model is status 2" '[ $? -eq 2 ]'
check "the refusal names the place" 'grep -q "^--set scenario.speed=35 kg: .*not of speed" "$tmp/stderr"'
check "a refused run leaves earlier outputs alone" 'cmp -s "$tmp/before.json" "$out/summary.json"'
# Determinism: the same input twice gives byte-identical outputs (a run through the barrier's failures,
# 0.3 s of APS1: ropes or their anchors giving way and the end posts failing, exercises every stage of the
# step).
for k in 1 2; do
    "$cs" run examples/aps1.yaml -o "$tmp/twice$k" --t-end "300 ms" >/dev/null 2>&1
done
for f in timeseries.csv events.csv summary.json; do
    check "$f byte-identical on a second run" 'cmp -s "$tmp/twice1/$f" "$tmp/twice2/$f"'
done
check "the twice-run passed a rope or anchor failure" \
    'grep -qE "cable_break|termination_break|anchor_yield|anchor_pullout" "$tmp/twice1/events.csv"'
"$cs" run tests/bad/zero_spacing.yaml -o "$tmp/never" >/dev/null 2>&1
check "a bad model writes nothing" '[ $? -eq 2 ] && [ ! -e "$tmp/never" ]'

finish
