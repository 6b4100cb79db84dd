#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# docs/guide.md's status paragraph on the crash tests' predictions ("The model's predictions") quotes each
# test's end: "APS3 (...) stops it at 3.74 m at 0.5865 s with a largest 50-ms deceleration of 10.80 g", "APS4
# (...) lets it through at 26.3 mph at 0.238 s with 5.74 g". Each is read from the paragraph and checked
# against the pinned predictions (tests/predictions/crash-tests.csv, which test_io_crash_tests holds the
# engine to): the penetration, the exit speed and the deceleration to the decimals printed, the stop or exit
# time to every digit it has. Runs no program; a number the test no longer finds in the paragraph fails it, and
# the test is then updated with the prose.
source "$(dirname "$0")/lib.sh"
awk '/^- The model.s predictions \(`cablesim run examples\/aps\*.yaml`/ { on = 1 } on && /^- / && !/predictions/ { exit } on' \
    docs/guide.md | tr '\n' ' ' | tr -s ' ' >"$tmp/para.txt"
check "the paragraph is in docs/guide.md" '[ -s "$tmp/para.txt" ]'
for test in aps1 aps3 aps4; do
    name=$(tr a-z A-Z <<<"$test")
    row=$(grep "^$test," tests/predictions/crash-tests.csv)
    IFS=, read -r _ outcome time decel penetration exit_speed _ <<<"$row"
    if [ "$outcome" = stopped ]; then
        # "APS3 (...) stops it at P m at T s with ... of G g", "APS1 stops it at P m at T s with G g"
        quoted=$(grep -oE "$name( \([^)]*\))? stops it at [0-9.]+ m at [0-9.]+ s with (a largest 50-ms deceleration of )?[0-9.]+ g" "$tmp/para.txt" | head -1)
        check "$name: the paragraph quotes its stop" '[ -n "$quoted" ]'
        read -r pen t g <<<"$(sed -E 's/.* at ([0-9.]+) m at ([0-9.]+) s with (a largest 50-ms deceleration of )?([0-9.]+) g$/\1 \2 \4/' <<<"$quoted")"
        check "$name: $pen m, the pinned penetration ($penetration m)" '[ "$pen" = "$(printf "%.2f" "$penetration")" ]'
    else
        # "APS4 (...) lets it through at S mph at T s with G g"
        quoted=$(grep -oE "$name( \([^)]*\))? lets it through at [0-9.]+ mph at [0-9.]+ s with [0-9.]+ g" "$tmp/para.txt" | head -1)
        check "$name: the paragraph quotes its exit ($outcome)" '[ -n "$quoted" ]'
        read -r mph t g <<<"$(sed -E 's/.* at ([0-9.]+) mph at ([0-9.]+) s with ([0-9.]+) g$/\1 \2 \3/' <<<"$quoted")"
        check "$name: $mph mph, the pinned exit speed ($exit_speed m/s)" \
            '[ "$mph" = "$(awk -v v="$exit_speed" "BEGIN { printf \"%.1f\", v / 0.44704 }")" ]'
    fi
    check "$name: $t s, the pinned time ($time s)" 'awk -v a="$t" -v b="$time" "BEGIN { exit !(a + 0 == b + 0) }"'
    check "$name: $g g, the pinned deceleration ($decel g)" '[ "$g" = "$(printf "%.2f" "$decel")" ]'
done
finish
