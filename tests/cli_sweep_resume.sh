#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A sweep stopped by a signal writes the runs it finished, marked partial, and `sweep --resume DIR` completes
# it: runs.csv then equals, byte for byte, that of the same sweep never stopped. Stopped twice ways: by
# CABLESIM_SWEEP_STOP_AFTER (it raises SIGINT once that many runs are done: a fixed point to stop at) and
# by SIGTERM from this script while the runs go on. A resume refuses a folder whose study changed, and one
# whose runs.csv lacks columns this cablesim writes; a folder whose study is whole has nothing to run. A new
# study (no --resume) into a stopped study's folder is refused, the folder left byte for byte as it was,
# and --force starts it afresh in the stopped study's place.
source "$(dirname "$0")/lib.sh"
# snapshot DIR: every name under DIR and the SHA-256 of every file's bytes
snapshot() { (cd "$1" && find . | LC_ALL=C sort && find . -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum); }

# the whole study, never stopped: tests/sweep/lhs.yaml's 4 runs, with runs.nc
"$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/whole" --netcdf --quiet >/dev/null 2>&1
check "the whole sweep exits 0" '[ $? -eq 0 ]'

dir="$tmp/stopped"
CABLESIM_SWEEP_STOP_AFTER=1 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$dir" --netcdf --threads 1 >"$tmp/stop.out" 2>"$tmp/stop.err"
check "stopped by SIGINT after 1 run: exit 130" '[ $? -eq 130 ] || { cat "$tmp/stop.err"; false; }'
check "it says so, and how to go on" 'grep -qxF "cablesim sweep: stopped by SIGINT: 1 of 4 runs done, written to $dir (partial); \`cablesim sweep --resume $dir\` runs the other 3" "$tmp/stop.err"'
check "runs.csv: the header and the one run done, as the whole sweep has it" '[ "$(wc -l <"$dir/runs.csv")" -eq 2 ] && cmp -s "$dir/runs.csv" <(head -2 "$tmp/whole/runs.csv")'
check "summary.json: partial, 1 run done, by SIGINT" 'grep -q "^\"partial\":true,\"runs_done\":1,\"stopped_by\":\"SIGINT\"," "$dir/summary.json"'
check "summary.md: a partial note first" '[ "$(sed -n 3p "$dir/summary.md")" = "**Partial**: 1 of 4 runs were run before SIGINT stopped the sweep; the tables below are of those. \`cablesim sweep --resume $dir\` runs the rest and completes these files." ]'
check "a partial sweep writes no runs.nc" '[ ! -e "$dir/runs.nc" ]'
# the same command again, without --resume (a re-run by habit after Ctrl-C): refused, nothing written
before=$(snapshot "$dir")
"$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$dir" --netcdf --threads 1 >"$tmp/again.out" 2>"$tmp/again.err"
check "a new study into the stopped study's folder: refused, exit 1" '[ $? -eq 1 ] || { cat "$tmp/again.err"; false; }'
check "the refusal names the folder, the 1 run done and the two ways on" 'grep -qxF "cablesim sweep: nothing run: $dir holds a stopped study, 1 run done saved in $dir/runs.csv: \`cablesim sweep --resume $dir\` runs the rest of it, or --force starts this study afresh and replaces it" "$tmp/again.err" || { cat "$tmp/again.err"; false; }'
check "the refused study leaves the folder byte for byte as it was" '[ "$(snapshot "$dir")" = "$before" ] && [ ! -s "$tmp/again.out" ]'
"$cs" sweep --resume "$dir" --threads 2 >"$tmp/resume.out" 2>&1
check "--resume exits 0" '[ $? -eq 0 ] || { cat "$tmp/resume.out"; false; }'
check "--resume ran the other 3" 'grep -qxF "sweep: 1 runs read back from $dir/runs.csv, 3 run now" "$tmp/resume.out"'
check "runs.csv: byte for byte the whole sweep's" 'cmp "$dir/runs.csv" "$tmp/whole/runs.csv"'
check "summary.json: no longer partial" 'grep -q "^\"partial\":false,\"runs_done\":4,\"stopped_by\":null," "$dir/summary.json"'
check "summary.md: no partial note" '! grep -q "Partial" "$dir/summary.md"'
check "runs.nc now written (--netcdf kept)" '[ -s "$dir/runs.nc" ]'
out=$("$cs" sweep --resume "$dir" 2>&1)
check "--resume of a whole study: nothing to run, exit 0" '[ $? -eq 0 ] && grep -qxF "sweep: $dir holds the whole study (4 runs): nothing to run" <<<"$out"'

# --force: a new study into a stopped study's folder starts afresh and replaces it; a file of the user's
# there is kept (and, without --force, the stopped study is what the refusal names: --force passes both)
CABLESIM_SWEEP_STOP_AFTER=1 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/forced" --threads 1 --quiet >/dev/null 2>&1
echo "my notes" >"$tmp/forced/notes.txt"
out=$("$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/forced" --quiet 2>&1)
check "a stopped study and a file of the user's: exit 1, the stopped study named" '[ $? -eq 1 ] && grep -qF "holds a stopped study, 1 run done saved in $tmp/forced/runs.csv" <<<"$out" || { echo "$out"; false; }'
out=$("$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/forced" --force --quiet 2>&1)
check "--force: the study run afresh, whole, in the stopped one's place" '[ $? -eq 0 ] && cmp "$tmp/forced/runs.csv" "$tmp/whole/runs.csv" && grep -q "^\"partial\":false,\"runs_done\":4," "$tmp/forced/summary.json" || { echo "$out"; false; }'
check "--force: the user's file kept" '[ "$(cat "$tmp/forced/notes.txt")" = "my notes" ]'

# a study that changed is refused: another value of the model
CABLESIM_SWEEP_STOP_AFTER=1 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/changed" --threads 1 --quiet >/dev/null 2>&1
sed -i 's/"set":\[\]/"set":["scenario.stop_speed=0.2 m\/s"]/' "$tmp/changed/summary.json"
out=$("$cs" sweep --resume "$tmp/changed" 2>&1)
check "--resume of a changed study: exit 2, why" '[ $? -eq 2 ] && grep -qF "the study has changed since it was stopped" <<<"$out"'
out=$("$cs" sweep --resume "$tmp/changed" tests/sweep/lhs.yaml 2>&1)
check "--resume with a spec: exit 2" '[ $? -eq 2 ] && grep -qF -- "--resume DIR takes the study as DIR/summary.json records it" <<<"$out"'

# a folder of a cablesim whose runs.csv had no astm_f2656_penetration and sd_std_02_01_as_run: refused, the
# columns named, rather than completed with runs that lack them
CABLESIM_SWEEP_STOP_AFTER=1 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/older" --threads 1 --quiet >/dev/null 2>&1
cut -d, -f7,8 --complement "$tmp/older/runs.csv" >"$tmp/older.csv" && mv "$tmp/older.csv" "$tmp/older/runs.csv"
out=$("$cs" sweep --resume "$tmp/older" 2>&1)
check "--resume of an older cablesim's runs.csv: exit 2, the columns it lacks named" '[ $? -eq 2 ] && grep -qxF "cablesim sweep: $tmp/older/runs.csv:1: written by an older cablesim, without the columns astm_f2656_penetration [m], sd_std_02_01_as_run: run the study again without --resume" <<<"$out" || { echo "$out"; false; }'

# a study stopped with --dt: --resume runs the rest at its time step (runs.csv byte for byte the whole sweep's
# at --dt 0.2 ms), and refuses a --dt or --t-end of its own, named as the user gave it, rather than mix runs
# made at two time steps
CABLESIM_SWEEP_STOP_AFTER=1 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/dt" --dt "0.2 ms" --threads 1 --quiet >/dev/null 2>&1
"$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/whole-dt" --dt "0.2 ms" --quiet >/dev/null 2>&1
for opt in "--dt|0.1 ms" "--t-end|1 s" "--dt=0.1 ms|"; do
    args=("${opt%%|*}")
    [ -n "${opt#*|}" ] && args+=("${opt#*|}")
    given=$(sed 's/=/ /; s/|/ /; s/ $//' <<<"$opt")
    out=$("$cs" sweep --resume "$tmp/dt" --threads 1 "${args[@]}" 2>&1)
    check "--resume with ${args[*]}: exit 2, the option named as given, why" '[ $? -eq 2 ] && grep -qF -- "cablesim sweep: $given with --resume: --resume DIR takes the study as DIR/summary.json records it and makes the runs left as those done, with one model, values, time step and end" <<<"$out" || { echo "$out"; false; }'
done
check "the refused --resume runs nothing: 1 run done still" 'grep -q "^\"partial\":true,\"runs_done\":1," "$tmp/dt/summary.json"'
"$cs" sweep --resume "$tmp/dt" --threads 1 --quiet >/dev/null 2>&1
check "--resume of a study run with --dt 0.2 ms: runs.csv byte for byte the whole sweep's at 0.2 ms (not the spec's step's)" '[ $? -eq 0 ] && cmp "$tmp/dt/runs.csv" "$tmp/whole-dt/runs.csv" && ! cmp -s "$tmp/dt/runs.csv" "$tmp/whole/runs.csv"'

# The stop by SIGTERM: two sweeps of 120 runs, in the plain suite; under the sanitizers the stop by SIGINT
# above is the representative case of a stop and its resume.
if plain_only "the stop by SIGTERM and its resume (240 runs)"; then
    # SIGTERM from outside while the runs go on (120 runs of 150 ms, 0.01-0.04 s each on one thread by the
    # machine: the signal comes 0.3 s after the sweep has started them)
    spec=(--allow-path examples tests/sweep/mc.yaml --runs 120 --t-end "150 ms")
    "$cs" sweep "${spec[@]}" -o "$tmp/whole-mc" --quiet >/dev/null 2>&1
    "$cs" sweep "${spec[@]}" -o "$tmp/term" --threads 1 >"$tmp/term.out" 2>"$tmp/term.err" &
    pid=$!
    for _ in $(seq 100); do grep -q "^sweep: 120 runs" "$tmp/term.err" && break; sleep 0.05; done
    sleep 0.3
    kill -TERM "$pid"
    wait "$pid"
    check "SIGTERM: exit 143" '[ $? -eq 143 ] || { cat "$tmp/term.err"; false; }'
    done_runs=$(($(wc -l <"$tmp/term/runs.csv") - 1))
    check "SIGTERM: some runs done, not all ($done_runs)" '[ "$done_runs" -ge 1 ] && [ "$done_runs" -lt 120 ] && grep -q "^\"partial\":true,\"runs_done\":$done_runs,\"stopped_by\":\"SIGTERM\"," "$tmp/term/summary.json"'
    "$cs" sweep --resume "$tmp/term" --quiet >/dev/null 2>&1
    check "SIGTERM, then --resume: runs.csv byte for byte the whole sweep's" '[ $? -eq 0 ] && cmp "$tmp/term/runs.csv" "$tmp/whole-mc/runs.csv"'
fi
finish
