#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A sweep survives kill -9 (docs/robustness.md): each run's row is appended to DIR/.cablesim-journal and
# fsync'ed as it finishes, so a sweep killed with SIGKILL (no handler runs) loses at most the runs under
# way, and `sweep --resume DIR` runs the rest and writes the same runs.csv, byte for byte, as a sweep never
# stopped. The journal is removed once the outputs hold its runs; a failed write of the outputs keeps it. A
# new study (no --resume) into the killed sweep's folder is refused, the journal kept.
source "$(dirname "$0")/lib.sh"
# kill_when DIR LINES [SIGNAL...]: SIGKILL the sweep $pid (or send it the SIGNALs, one after the other)
# once DIR's journal has LINES lines (waiting up to 60 s: a loaded machine is slow to start it), and wait
# for it; its exit status is wait's
kill_when() {
    for _ in $(seq 6000); do
        [ -e "$1/.cablesim-journal" ] && [ "$(wc -l <"$1/.cablesim-journal")" -ge "$2" ] && break
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.01
    done
    local s
    for s in "${@:3}"; do
        kill -"$s" "$pid" 2>/dev/null
    done
    [ $# -gt 2 ] || kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
}
# 30 runs of 150 ms of APS3 (0.01-0.04 s each on one thread; 12 under the sanitizers, about five times as
# slow): the kill comes once 5 rows are journalled
n=$(repeats 30 12 "runs a sweep")
spec=(--allow-path examples tests/sweep/mc.yaml --runs "$n" --t-end "150 ms")
"$cs" sweep "${spec[@]}" -o "$tmp/whole" --quiet >/dev/null 2>&1
check "the whole sweep: runs.csv of $n runs, no journal left" '[ "$(wc -l <"$tmp/whole/runs.csv")" -eq $((n + 1)) ] && [ ! -e "$tmp/whole/.cablesim-journal" ]'

"$cs" sweep "${spec[@]}" -o "$tmp/killed" --threads 1 --quiet >/dev/null 2>&1 &
pid=$!
journal="$tmp/killed/.cablesim-journal"
kill_when "$tmp/killed" 7 # the record, the header, 5 runs
check "kill -9: the sweep died by SIGKILL (exit 137)" '[ $? -eq 137 ]'
rows=$(($(wc -l <"$journal") - 2))
check "kill -9: the journal holds the runs done ($rows of $n), no outputs" '[ "$rows" -ge 5 ] && [ "$rows" -lt "$n" ] && [ ! -e "$tmp/killed/runs.csv" ] && head -1 "$journal" | grep -q "^{\"cablesim\":{\"version\":.*\"partial\":true,\"inputs_hash\":\"[0-9a-f]\{16\}\",\"resume\":{\"spec\":"'
# the same command again, without --resume: refused (the killed sweep's lock taken over), the journal kept
# byte for byte, and --resume below still reads its runs back
cp "$journal" "$tmp/journal.before"
out=$("$cs" sweep "${spec[@]}" -o "$tmp/killed" --threads 1 --quiet 2>&1)
check "kill -9, then a new study into its folder: exit 1, the journal's runs named, the journal as it was" '[ $? -eq 1 ] && grep -qxF "cablesim sweep: nothing run: $tmp/killed holds a stopped study, $rows runs done saved in $journal: \`cablesim sweep --resume $tmp/killed\` runs the rest of it, or --force starts this study afresh and replaces it" <<<"$out" && cmp "$journal" "$tmp/journal.before" && [ ! -e "$tmp/killed/runs.csv" ] || { echo "$out"; false; }'
out=$("$cs" sweep --resume "$tmp/killed" 2>&1)
check "--resume after kill -9: exit 0, the journalled runs read back" '[ $? -eq 0 ] && grep -qF "sweep: $rows runs read back from" <<<"$out" || { echo "$out"; false; }'
check "--resume after kill -9: runs.csv byte for byte the whole sweep's" 'cmp "$tmp/killed/runs.csv" "$tmp/whole/runs.csv"'
check "--resume after kill -9: the journal is gone, the manifest lists runs.csv" '[ ! -e "$journal" ] && grep -qP "^runs.csv\\t[0-9]+\\t[0-9a-f]{16}$" "$tmp/killed/.cablesim-manifest"'

# a second Ctrl-C (SIGINT twice) ends the sweep at once (exit 130), its temporaries and lock removed and
# its journal kept, or after it wrote the runs done if it got there first: either way --resume gives the
# whole sweep's runs.csv
"$cs" sweep "${spec[@]}" -o "$tmp/int2" --threads 1 --quiet >/dev/null 2>&1 &
pid=$!
kill_when "$tmp/int2" 7 INT INT
check "SIGINT twice: the sweep ends by SIGINT (exit 130)" '[ $? -eq 130 ]'
check "SIGINT twice: no temporary or lock is left, the journal or the outputs kept" '[ -z "$(find "$tmp/int2" -name ".cablesim-tmp.*")" ] && [ ! -e "$tmp/int2/.cablesim-lock" ] && { [ -s "$tmp/int2/.cablesim-journal" ] || [ -s "$tmp/int2/runs.csv" ]; }'
"$cs" sweep --resume "$tmp/int2" --quiet >/dev/null 2>&1
check "--resume after SIGINT twice: runs.csv byte for byte the whole sweep's" '[ $? -eq 0 ] && cmp "$tmp/int2/runs.csv" "$tmp/whole/runs.csv"'

# a journal row cut short by the kill (no newline yet) is dropped: its run runs again
"$cs" sweep "${spec[@]}" -o "$tmp/cut" --threads 1 --quiet >/dev/null 2>&1 &
pid=$!
kill_when "$tmp/cut" 4
printf '7,5.3 kip,6' >>"$tmp/cut/.cablesim-journal" # half a row
"$cs" sweep --resume "$tmp/cut" --quiet >/dev/null 2>&1
check "a half-written last row is dropped: runs.csv the whole sweep's" '[ $? -eq 0 ] && cmp "$tmp/cut/runs.csv" "$tmp/whole/runs.csv"'

# a journal of another study is refused, not mixed in
"$cs" sweep "${spec[@]}" -o "$tmp/other" --threads 1 --quiet >/dev/null 2>&1 &
pid=$!
kill_when "$tmp/other" 4
sed -i '1s/"inputs_hash":"[0-9a-f]*"/"inputs_hash":"0000000000000000"/' "$tmp/other/.cablesim-journal"
out=$("$cs" sweep --resume "$tmp/other" 2>&1)
check "a changed study's journal: exit 2, why" '[ $? -eq 2 ] && grep -qF "the study has changed since it was stopped" <<<"$out"'
finish
