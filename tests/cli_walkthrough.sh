#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's, docs/guide.md's and docs/tutorial.md's commands run as written: every line of their ```sh
# blocks, in order (README.md first, then the guide), but the set-up ones (make, cmake --install, cc,
# LD_LIBRARY_PATH=...), is run in a fresh folder holding examples/ and build/cablesim, as a reader would
# run them in the checkout. Each must
# exit 0 (validate: 0, or 3 when its targets are missed, its documented status for results outside
# them), each -o DIR must then hold files, and the demo's run (the README's first command, as make demo
# runs it) must still hold its plots, report and its own command line at the end: no later command wrote
# over it. A build without the designer page skips the designer's line; a sanitized build, the lines of
# validate and sweep (tests/lib.sh, plain_only).
source "$(dirname "$0")/lib.sh"
repo=$PWD
w="$tmp/walk"
mkdir -p "$w/build"
ln -s "$repo/examples" "$w/examples"
ln -s "$(cd "$(dirname "$cs")" && pwd)/$(basename "$cs")" "$w/build/cablesim"
# the shell blocks' lines, a trailing backslash joining a line to the next
commands() {
    awk '/^```sh$/ { on = 1; next } /^```/ { on = 0 } on' README.md docs/guide.md docs/tutorial.md |
        awk '{ if (sub(/\\$/, "")) { held = held $0; next } print held $0; held = "" }' |
        grep -vE '^(make|cmake|cc|sudo|apt)( |$)|^LD_LIBRARY_PATH='
}
n=0
demo_cmd=""
while IFS= read -r line; do
    n=$((n + 1))
    [ -z "$demo_cmd" ] && demo_cmd=${line%%#*}
    if [[ $line == *" designer "* ]] && ! "$cs" designer --help 2>/dev/null | grep -q .; then
        continue
    fi
    # the studies (hundreds of runs) under the sanitizers are cli_validate's and cli_sweep's own cases
    if [[ ${line%%#*} =~ \ (validate|sweep)\  ]] && ! plain_only "line $n: $line"; then
        continue
    fi
    out=$(cd "$w" && bash -c "$line" 2>&1 </dev/null)
    rc=$?
    ok=0
    [ $rc -eq 0 ] && ok=1
    [[ $line == *" validate "* ]] && [ $rc -eq 3 ] && ok=1
    echo "line $n: $line" >&2
    check "line $n runs (exit $rc): $line" '[ $ok -eq 1 ] || { echo "$out" | tail -5; false; }'
    if [[ ${line%%#*} =~ -o\ ([^ ]+) ]]; then
        d=${BASH_REMATCH[1]}
        check "line $n: its -o $d holds files" '[ -n "$(ls -A "$w/$d" 2>/dev/null)" ]'
    fi
done < <(commands)
check "the blocks gave at least 20 commands" '[ $n -ge 20 ]'
check "the demo's run is intact: its report, plots and its own command line" \
    '[ -s "$w/results/aps3/report.html" ] && ls "$w/results/aps3/plots/"*.png >/dev/null 2>&1 && grep -qF "\"command\":\"build/cablesim run examples/aps3.yaml -o results/aps3 --plots --report\"" "$w/results/aps3/summary.json"'
check "the demo's command is make demo's" 'grep -qF "run examples/aps3.yaml -o \$(DEMO_OUT) --plots --report" Makefile && [ "$(echo $demo_cmd)" = "build/cablesim run examples/aps3.yaml -o results/aps3 --plots --report" ]'
finish
