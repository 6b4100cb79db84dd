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
finish
