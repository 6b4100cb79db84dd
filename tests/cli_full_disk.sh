#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A full disk (docs/robustness.md): an output that cannot be written says which file and the system's
# reason ("No space left on device"), and leaves no half-written result: the folder keeps the run before,
# whole, and no temporary. CABLESIM_TEST_DEV_FULL=NAME writes the output NAME to /dev/full, where every
# write fails with ENOSPC as on a full disk. A sweep whose outputs fail so keeps its runs' journal, and
# `sweep --resume` then writes the same runs.csv as a sweep that never failed.
source "$(dirname "$0")/lib.sh"
run=(run examples/aps3.yaml -o "$tmp/r" --t-end "20 ms")
"$cs" "${run[@]}" --plots >/dev/null 2>&1
check "a first run, with plots" '[ $? -eq 0 ] && [ -s "$tmp/r/timeseries.csv" ] && [ -s "$tmp/r/plots/speed.png" ]'
cp -r "$tmp/r" "$tmp/before"
for name in timeseries.csv summary.json plots/speed.png plots/cables.svg; do
    out=$(CABLESIM_TEST_DEV_FULL=$name "$cs" "${run[@]}" --plots --set "scenario.speed=30 mph" 2>&1)
    check "$name on a full disk: exit 1, the file and 'No space left on device'" '[ $? -eq 1 ] && grep -qF "cablesim: nothing written: $tmp/r/$name: No space left on device" <<<"$out" || { echo "$out"; false; }'
    check "$name on a full disk: the run before is whole, no temporary left" 'diff -r "$tmp/before" "$tmp/r" >/dev/null && [ -z "$(find "$tmp/r" -name ".cablesim-tmp.*")" ]'
done

# a sweep: runs.csv on a full disk; the journal keeps the runs, --resume writes them
"$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/whole" --quiet >/dev/null 2>&1
out=$(CABLESIM_TEST_DEV_FULL=runs.csv "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/s" --quiet 2>&1)
check "sweep, runs.csv on a full disk: exit 1, the file, the reason, the journal kept" '[ $? -eq 1 ] && grep -qF "nothing written: $tmp/s/runs.csv: No space left on device; the runs done are kept in $tmp/s/.cablesim-journal" <<<"$out" && [ "$(ls -A "$tmp/s")" = .cablesim-journal ] || { echo "$out"; false; }'
out=$("$cs" sweep --resume "$tmp/s" 2>&1)
check "sweep --resume once there is room: the 4 runs read back, runs.csv the whole sweep's" '[ $? -eq 0 ] && grep -qF "sweep: 4 runs read back" <<<"$out" && cmp "$tmp/s/runs.csv" "$tmp/whole/runs.csv" || { echo "$out"; false; }'
finish
