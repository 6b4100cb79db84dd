#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cablesim-mpi sweep: the same runs.csv, runs.nc and summaries, byte for byte (the summaries but for the
# line that records the command line), on 1, 2 and 3 MPI ranks (3 splits 4 runs unevenly) and with 2
# threads on each of 2 ranks; a sweep stopped on 2 ranks and resumed on 2 gives the runs.csv of 1 rank,
# and so does one killed by SIGKILL on 2 ranks, whose journal holds the runs of both. Exit 77 (skipped)
# only when MPI or mpirun is absent.
set -u
cs=${1:-}
if [ -z "$cs" ]; then
    echo "SKIP: cablesim-mpi was not built (MPI not found: install libopenmpi-dev openmpi-bin, then re-run cmake)"
    exit 77
fi
if ! command -v mpirun >/dev/null 2>&1; then
    echo "SKIP: mpirun is absent (install openmpi-bin)"
    exit 77
fi
flags=(--oversubscribe)
[ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
source "$(dirname "$0")/lib.sh"
without_command() { grep -v "^Written by cablesim " | sed '1s/^{"cablesim":.*/{/'; }
specs=(lhs grid)
cases=("1 1" "2 1" "3 1" "2 2")
# under the sanitizers: the Latin hypercube on 1 rank and on 2 ranks of 2 threads each, the paths of the rest
if ! plain_only "the grid's sweeps, the Latin hypercube's on 2 and 3 ranks of 1 thread"; then
    specs=(lhs)
    cases=("1 1" "2 2")
fi
for spec in "${specs[@]}"; do
    for case in "${cases[@]}"; do
        set -- $case
        out="$tmp/$spec-$1-$2"
        if ! mpirun "${flags[@]}" -n "$1" "$cs" sweep --allow-path examples "tests/sweep/$spec.yaml" -o "$out" --threads "$2" --netcdf \
            >"$out.log" 2>&1; then
            echo "FAIL: $spec on $1 ranks x $2 threads"
            cat "$out.log"
            fail=$((fail + 1))
            continue
        fi
        grep -q "on $1 rank" "$out.log" || { echo "FAIL: $spec did not run on $1 ranks"; cat "$out.log"; fail=$((fail + 1)); }
        if [ "$1 $2" != "1 1" ]; then
            # the summaries record the command line, whose -o and --threads differ: compared without it
            for f in runs.csv runs.nc summary.md summary.json; do
                filter=cat
                [ "${f#summary}" != "$f" ] && filter=without_command
                if cmp <($filter <"$tmp/$spec-1-1/$f") <($filter <"$out/$f"); then
                    pass=$((pass + 1))
                else
                    echo "FAIL: $spec $f differs between 1 rank and $1 ranks x $2 threads"
                    fail=$((fail + 1))
                fi
            done
        fi
    done
done
# stopped on both ranks once each has done a run (CABLESIM_SWEEP_STOP_AFTER), then resumed on 2 ranks:
# runs.csv as the sweep never stopped
out="$tmp/stopped"
CABLESIM_SWEEP_STOP_AFTER=1 mpirun "${flags[@]}" -x CABLESIM_SWEEP_STOP_AFTER -n 2 "$cs" sweep --allow-path examples tests/sweep/lhs.yaml \
    -o "$out" --threads 1 >"$out.log" 2>&1
if grep -q "^\"partial\":true,\"runs_done\":2," "$out/summary.json" 2>/dev/null &&
    mpirun "${flags[@]}" -n 2 "$cs" sweep --resume "$out" --threads 1 >>"$out.log" 2>&1 &&
    cmp "$out/runs.csv" "$tmp/lhs-1-1/runs.csv"; then
    pass=$((pass + 1))
else
    echo "FAIL: lhs stopped after a run on each of 2 ranks, then resumed on 2: not the runs.csv of 1 rank"
    cat "$out.log"
    fail=$((fail + 1))
fi
# killed by SIGKILL on 2 ranks (mpirun and both ranks, no handler runs) once the journal holds 5 runs, one
# of them rank 1's (the odd ones): each rank's finished runs reach rank 0's journal as they end, and
# --resume on 2 ranks reads them back and gives the runs.csv of 1 rank
n=$(repeats 30 12 "runs in the killed sweep")
mc=(--allow-path examples tests/sweep/mc.yaml --runs "$n" --t-end "500 ms" --threads 1)
mpirun "${flags[@]}" -n 1 "$cs" sweep "${mc[@]}" -o "$tmp/mc-1" --quiet >"$tmp/mc-1.log" 2>&1
out="$tmp/mc-killed"
journal="$out/.cablesim-journal"
setsid mpirun "${flags[@]}" -n 2 "$cs" sweep "${mc[@]}" -o "$out" --quiet >"$out.log" 2>&1 &
pid=$!
odd_rows() { tail -n +3 "$journal" 2>/dev/null | awk -F, '$1 % 2 == 1' | wc -l; }
for _ in $(seq 6000); do # up to 60 s: a loaded machine is slow to start mpirun
    [ -e "$journal" ] && [ "$(wc -l <"$journal")" -ge 7 ] && [ "$(odd_rows)" -ge 1 ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
done
kill -KILL $(ps -o pid= --sid "$pid") 2>/dev/null # mpirun and each rank (a process group of its own)
wait "$pid" 2>/dev/null
rows=$(($(wc -l <"$journal") - 2))
odd=$(odd_rows)
if [ ! -e "$out/runs.csv" ] && [ "$odd" -ge 1 ] && [ "$rows" -gt "$odd" ] && [ "$rows" -lt "$n" ] &&
    mpirun "${flags[@]}" -n 2 "$cs" sweep --resume "$out" >>"$out.log" 2>&1 &&
    grep -qF "sweep: $rows runs read back from" "$out.log" && cmp "$out/runs.csv" "$tmp/mc-1/runs.csv"; then
    pass=$((pass + 1))
else
    echo "FAIL: a sweep on 2 ranks killed by SIGKILL: its journal held $rows runs, $odd of them rank 1's (expected some of each rank), or --resume did not give the runs.csv of 1 rank"
    cat "$out.log"
    fail=$((fail + 1))
fi
finish
