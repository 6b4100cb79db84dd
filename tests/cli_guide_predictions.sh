#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# docs/guide.md's status paragraph on the crash tests' predictions ("The model's predictions") quotes each
# test's stop: "APS4 (also blind) at 4.35 m at 0.5565 s with 6.57 g". Each is read from the paragraph and
# checked against the pinned predictions (tests/predictions/crash-tests.csv, which test_io_crash_tests
# holds the engine to): the penetration and the deceleration to the 2 decimals printed, the stop time to
# every digit. Runs no program; a number the test no longer finds in the paragraph fails it, and the test
# is then updated with the prose.
source "$(dirname "$0")/lib.sh"
awk '/^- The model.s predictions \(`cablesim run examples\/aps\*.yaml`/ { on = 1 } on && /^- / && !/predictions/ { exit } on' \
    docs/guide.md | tr '\n' ' ' | tr -s ' ' >"$tmp/para.txt"
check "the paragraph is in docs/guide.md" '[ -s "$tmp/para.txt" ]'
for test in aps1 aps3 aps4; do
    name=$(tr a-z A-Z <<<"$test")
    # "APS3 (...) stops it at P m at T s with ... of G g", "APS4 (...) at P m at T s with G g"
    quoted=$(grep -oE "$name( \([^)]*\))?( stops it)? at [0-9.]+ m at [0-9.]+ s with (a largest 50-ms deceleration of )?[0-9.]+ g" "$tmp/para.txt" | head -1)
    check "$name: the paragraph quotes its stop" '[ -n "$quoted" ]'
    read -r pen t g <<<"$(sed -E 's/.* at ([0-9.]+) m at ([0-9.]+) s with (a largest 50-ms deceleration of )?([0-9.]+) g$/\1 \2 \4/' <<<"$quoted")"
    row=$(grep "^$test,stopped," tests/predictions/crash-tests.csv)
    check "$name: pinned as stopped" '[ -n "$row" ]'
    IFS=, read -r _ _ time decel penetration _ <<<"$row"
    check "$name: $pen m, the pinned penetration ($penetration m)" '[ "$pen" = "$(printf "%.2f" "$penetration")" ]'
    check "$name: $t s, the pinned stop time ($time s)" '[ "$t" = "$time" ]'
    check "$name: $g g, the pinned deceleration ($decel g)" '[ "$g" = "$(printf "%.2f" "$decel")" ]'
done
finish
