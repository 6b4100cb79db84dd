#!/usr/bin/env bash
# cablesim rate: the standard's test condition against a model's barrier; usage errors exit 2.
source "$(dirname "$0")/lib.sh"
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M30 --set 'scenario.t_end=0.05 s' 2>&1)
rc=$?
check "rate runs (exit 0)" '[ $rc -eq 0 ]'
check "one trial row for M30" '[ "$(grep -c "^  M    30 mph" <<<"$out")" -eq 1 ]'
check "a rating line" 'grep -qE "^rating: (M30/P[1-4]|none)" <<<"$out"'
"$cs" rate examples/aps3.yaml --standard pas-68 >/dev/null 2>&1
check "unknown standard exits 2" '[ $? -eq 2 ]'
"$cs" rate examples/aps3.yaml --standard astm-f2656 --class M45 >/dev/null 2>&1
check "unknown class exits 2" '[ $? -eq 2 ]'
"$cs" rate --standard astm-f2656 >/dev/null 2>&1
check "no model file exits 2" '[ $? -eq 2 ]'
out=$("$cs" run examples/aps3.yaml -o "$tmp/run" --set 'scenario.t_end=0.05 s' 2>&1)
check "run prints the rating of its standard vehicle" 'grep -q "rating (as run)      ASTM F2656 M40/P[1-4]; SD-STD-02.01 " <<<"$out"'
# Roadside test conditions: the tests of a level, or one; each a row with its deflection and working width.
out=$("$cs" rate examples/roadside/rs1.yaml --standard mash --set 'scenario.t_end=0.3 s' 2>&1)
check "mash TL-3 runs 3-10 and 3-11 (exit 0)" '[ $? -eq 0 ] && [ "$(grep -cE "^  3-1[01] +(1100C|2270P) +100 km/h 25 deg .* deflection [0-9.]+ m .* working width [0-9.]+ m" <<<"$out")" -eq 2 ]'
out=$("$cs" rate examples/roadside/rs1.yaml --standard nchrp-350 --test 3-11 --set 'scenario.t_end=0.3 s' 2>&1)
check "nchrp-350 3-11 alone with the 2000P" '[ "$(grep -cE "^  3-11 2000P +100 km/h 25 deg" <<<"$out")" -eq 1 ]'
"$cs" rate examples/roadside/rs1.yaml --standard mash --test 5-12 >/dev/null 2>&1
check "unknown roadside test exits 2" '[ $? -eq 2 ]'
"$cs" rate examples/roadside/rs1.yaml --standard mash --class M30 >/dev/null 2>&1
check "an anti-ram class with a roadside standard exits 2" '[ $? -eq 2 ]'
finish
