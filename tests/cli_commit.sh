# SPDX-License-Identifier: MIT
# The commit's renames (src/io/out/outfile.c, docs/robustness.md "A user's files"): a name that held no
# file when the commit looked is renamed to only while it still holds none, so a file the user saves there
# in that instant is kept, and an earlier run's file the user writes over in that instant goes back to its
# name, as does one written over in the instant before its removal; the same where the file system cannot
# exchange; a rename that fails takes back those done before it, so the folder holds the earlier run's
# results, whole, and "nothing written" is true; one the system will not take back is named as this
# run's, and the manifest owns both runs' files, so the next run writes them all. gdb stops the command
# where it puts a file in place (renameat2, which only the commit's renames call) or moves one aside
# (rename) to do there, in that instant, what a user or the system does.
# Usage: bash tests/cli_commit.sh path/to/cablesim
source "$(dirname "$0")/lib.sh"
if ! command -v gdb >/dev/null; then
    echo "skipped: no gdb to stop the commit between its renames"
    exit 77
fi
if ! gdb -q -batch -iex "set debuginfod enabled off" -ex run --args true 2>&1 | grep -q "exited normally"; then
    echo "skipped: gdb cannot run a program here (ptrace refused)"
    exit 77
fi
# at_put N ACTION ARGS...: cablesim ARGS, stopped as it puts its N-th file in place to run the gdb command
# ACTION ("shell ..." or "kill"); its terminal output into $tmp/at.out, its exit status the function's
# (128 + the signal that ended it; 255: none, killed). With at_break=FUNCTION, stopped at that function's
# N-th call instead of renameat2's; with at_env=VAR=VALUE, run with that in its environment too; with
# at_signal=SIG, SIG is passed to the command, which gdb does not stop at.
at_put() {
    local n=$1 action=$2 more=() env=() pass=()
    shift 2
    for _ in $(seq 2 "$n"); do more+=(-ex continue); done
    [ -n "${at_env:-}" ] && env=(-ex "set environment $at_env")
    [ -n "${at_signal:-}" ] && pass=(-ex "handle $at_signal nostop noprint pass")
    # LeakSanitizer cannot run under ptrace: the sanitized build's leak check is off for these runs
    gdb -q -batch -iex "set debuginfod enabled off" "${pass[@]}" -ex "set breakpoint pending on" -ex "break ${at_break:-renameat2}" "${env[@]}" \
        -ex "set environment ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" -ex run "${more[@]}" -ex "$action" -ex delete -ex continue \
        -ex 'printf "exit status %d\n", $_exitcode' -ex 'printf "exit signal %d\n", $_exitsignal' --args "$cs" "$@" >"$tmp/at.out" 2>&1
    local status signal
    status=$(sed -n 's/^exit status \([0-9]*\)$/\1/p' "$tmp/at.out")
    signal=$(sed -n 's/^exit signal \([0-9]*\)$/\1/p' "$tmp/at.out")
    [ -z "$status" ] && [ -n "$signal" ] && status=$((128 + signal))
    return "${status:-255}"
}
# the files of the manifest of folder $1, in the order the commit put them in place
listed() { grep -v "^#" "$1/.cablesim-manifest" | cut -f1; }
# every file under $1 but the manifest, with its checksum
sums() { (cd "$1" && find . -type f ! -name .cablesim-manifest -exec md5sum {} + | sort); }
leftovers() { find "$1" -name ".cablesim-tmp.*" -o -name .cablesim-lock; }
run=(run examples/aps3.yaml --t-end "10 ms")

# A file saved at a new name between the commit's look and its rename: kept, and the files put in place
# before it (this run's over an earlier run's, exchanged) taken back.
d="$tmp/saved"
"$cs" "${run[@]}" -o "$tmp/ref" --plots >/dev/null 2>&1
fourth=$(listed "$tmp/ref" | sed -n 4p) # the first of plots/, a name new to a run without plots
"$cs" "${run[@]}" -o "$d" >/dev/null 2>&1
before=$(sums "$d")
at_put 4 "shell echo mine >$d/$fourth" "${run[@]}" -o "$d" --plots --set "scenario.speed=30 mph"
check "a file saved at a new name during the commit: exit 1, the file named, nothing written" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing written: $d/$fourth: something appeared there during the commit, which is kept: move it away and run again" "$tmp/at.out" || { cat "$tmp/at.out"; false; }'
check "the file saved is kept, the earlier run whole, no temporary or lock left" '[ "$(cat "$d/$fourth")" = mine ] && [ "$(sums "$d" | grep -v "$fourth")" = "$before" ] && [ "$(ls "$d/plots")" = "$(basename "$fourth")" ] && [ -z "$(leftovers "$d")" ]'
check "the manifest lists both runs' files: each of the three names twice" '[ "$(listed "$d" | sort | uniq -c | awk "\$1 == 2 {print \$2}" | tr "\n" " ")" = "events.csv summary.json timeseries.csv " ] && [ "$(listed "$d" | grep -c ^plots/)" -eq "$(listed "$tmp/ref" | grep -c ^plots/)" ]'
rm "$d/$fourth"
out=$("$cs" "${run[@]}" -o "$d" --plots 2>&1)
check "the next run owns the earlier files by either listing, and lists its own once" '[ $? -eq 0 ] && [ "$(listed "$d")" = "$(listed "$tmp/ref")" ] && cmp -s "$d/timeseries.csv" "$tmp/ref/timeseries.csv" && [ -z "$(leftovers "$d")" ] || { echo "$out"; false; }'

# An earlier run's file the user writes over in the instant before its exchange: put back at its name,
# this run's taken back, nothing written.
d="$tmp/edited"
"$cs" "${run[@]}" -o "$d" >/dev/null 2>&1
before=$(sums "$d")
at_put 1 "shell echo mine >$d/timeseries.csv" "${run[@]}" -o "$d" --set "scenario.speed=30 mph"
check "an earlier file written over during the commit: exit 1, the file named, nothing written" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing written: $d/timeseries.csv: something appeared there during the commit, which is kept: move it away and run again" "$tmp/at.out" || { cat "$tmp/at.out"; false; }'
check "the user's file kept at its name, the earlier run's others as they were, no temporary or lock left" '[ "$(cat "$d/timeseries.csv")" = mine ] && [ "$(sums "$d" | grep -v timeseries.csv)" = "$(echo "$before" | grep -v timeseries.csv)" ] && [ -z "$(leftovers "$d")" ]'

# Killed (kill -9) between two renames: the folder holds the earlier run's files and this run's, which the
# manifest lists both, so the next run owns them all and replaces them.
d="$tmp/killed"
"$cs" "${run[@]}" -o "$d" >/dev/null 2>&1
at_put 2 kill "${run[@]}" -o "$d" --t-end "12 ms"
check "killed between two renames: timeseries.csv this run's, summary.json the earlier run's" '[ $? -eq 255 ] && [ "$(tail -1 "$d/timeseries.csv" | cut -d, -f1)" = 0.012 ] && grep -q "\"t_end_s\":0.01," "$d/summary.json" && [ -e "$d/.cablesim-lock" ] || { cat "$tmp/at.out"; false; }'
out=$("$cs" "${run[@]}" -o "$d" 2>&1)
check "the next run owns both runs' files: no refusal, its own in place, no temporary or lock left" '[ $? -eq 0 ] && cmp -s "$d/timeseries.csv" "$tmp/ref/timeseries.csv" && [ "$(listed "$d" | tr "\n" " ")" = "timeseries.csv events.csv summary.json " ] && [ -z "$(leftovers "$d")" ] || { echo "$out"; false; }'

# The same into a new folder: the files put before are removed again.
d="$tmp/new"
at_put 2 "shell mkdir -p $d/events.csv/x" "${run[@]}" -o "$d"
check "a folder made at a new name during the commit: exit 1, nothing written, only that folder left" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing written: $d/events.csv: something appeared there during the commit, which is kept: move it away and run again" "$tmp/at.out" && [ "$(ls -A "$d")" = events.csv ] && [ -d "$d/events.csv/x" ] || { cat "$tmp/at.out"; ls -A "$d"; false; }'

# An earlier run's file this run does not write, which the user writes over in the instant before it is
# removed: moved aside, found not to be the earlier run's, and put back; the run's own files in place.
# (rename's first call in a commit writes the manifest; its second moves the first file to remove aside.)
d="$tmp/removed"
"$cs" "${run[@]}" -o "$d" --plots >/dev/null 2>&1
first=$(listed "$d" | grep ^plots/ | head -1)
at_break=rename at_put 2 "shell echo mine >$d/$first" "${run[@]}" -o "$d" --set "scenario.speed=30 mph"
check "an earlier file written over before its removal: the run ends well, the user's file kept" '[ $? -eq 0 ] && [ "$(cat "$d/$first")" = mine ] && [ "$(ls "$d/plots")" = "$(basename "$first")" ] && ! listed "$d" | grep -q ^plots/ && [ -z "$(leftovers "$d")" ] || { cat "$tmp/at.out"; ls -A "$d" "$d/plots"; false; }'
out=$("$cs" "${run[@]}" -o "$d" 2>&1)
check "the next run refuses the folder: the user's file named" '[ $? -ne 0 ] && echo "$out" | grep -qF "$first" || { echo "$out"; false; }'

# A file system that cannot exchange or refuse a replacement (renameat2 failing with EINVAL, as where it
# has no such flags: a library put before the C library's): new names by link and unlink, an earlier
# run's files renamed over once checked again, and one the user writes over in the instant kept. (A
# summary names its folder in its command line: the runs are compared without it.)
shim="$tmp/noexchange.so"
if ! printf '#include <errno.h>\nint renameat2(int a, const char *b, int c, const char *d, unsigned f) {\n(void)a, (void)b, (void)c, (void)d, (void)f;\nerrno = EINVAL;\nreturn -1;\n}\n' |
    cc -shared -fPIC -o "$shim" -x c - 2>/dev/null; then
    echo "skipped: a file system without renameat2's flags (no C compiler to build the library that refuses them)"
else
    plain() { LD_PRELOAD="$shim" ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 "$cs" "$@"; }
    d="$tmp/noexchange"
    out=$(plain "${run[@]}" -o "$d" --plots 2>&1)
    check "no exchange: a first run's files put at their names by link and unlink" '[ $? -eq 0 ] && [ "$(sums "$d" | grep -v summary.json)" = "$(sums "$tmp/ref" | grep -v summary.json)" ] && [ "$(listed "$d")" = "$(listed "$tmp/ref")" ] && [ -z "$(leftovers "$d")" ] || { echo "$out"; false; }'
    out=$(plain "${run[@]}" -o "$d" --set "scenario.speed=30 mph" 2>&1)
    "$cs" "${run[@]}" -o "$tmp/slower" --set "scenario.speed=30 mph" >/dev/null 2>&1
    check "no exchange: a rerun renames over the earlier files and removes the plots it does not write" '[ $? -eq 0 ] && [ "$(sums "$d" | grep -v summary.json)" = "$(sums "$tmp/slower" | grep -v summary.json)" ] && [ ! -e "$d/plots" ] && [ -z "$(leftovers "$d")" ] || { echo "$out"; ls -A "$d"; false; }'
    before=$(sums "$d")
    at_env="LD_PRELOAD=$shim" at_put 1 "shell echo mine >$d/timeseries.csv" "${run[@]}" -o "$d"
    check "no exchange: an earlier file written over during the commit kept, nothing written" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing written: $d/timeseries.csv: something appeared there during the commit, which is kept: move it away and run again" "$tmp/at.out" && [ "$(cat "$d/timeseries.csv")" = mine ] && [ "$(sums "$d" | grep -v timeseries.csv)" = "$(echo "$before" | grep -v timeseries.csv)" ] && [ -z "$(leftovers "$d")" ] || { cat "$tmp/at.out"; false; }'
fi

# A rename the system refuses after others, which it refuses to take back too (the folder made
# immutable): the message names the file in place as this run's and says to run again; the next run does.
probe="$tmp/probe"
mkdir "$probe"
if ! chattr +i "$probe" 2>/dev/null; then
    echo "skipped: a rename that cannot be taken back (chattr +i is refused here: not root, or not ext4)"
else
    chattr -i "$probe"
    d="$tmp/stuck"
    "$cs" "${run[@]}" -o "$d" >/dev/null 2>&1
    at_put 2 "shell chattr +i $d" "${run[@]}" -o "$d" --t-end "12 ms"
    status=$?
    chattr -i "$d"
    check "a rename refused and not taken back: exit 1, which file is this run's, what to do" '[ $status -eq 1 ] && grep -qxF "cablesim: $d/events.csv: Operation not permitted; $d holds this run'"'"'s timeseries.csv, the rest as before the command: run it again to write them all" "$tmp/at.out" && ! grep -q "nothing written" "$tmp/at.out" || { cat "$tmp/at.out"; false; }'
    check "timeseries.csv is this run's, summary.json the earlier run's, the manifest owns both" '[ "$(tail -1 "$d/timeseries.csv" | cut -d, -f1)" = 0.012 ] && grep -q "\"t_end_s\":0.01," "$d/summary.json" && [ "$(listed "$d" | grep -c "^timeseries.csv$")" -eq 2 ] || { tail -1 "$d/timeseries.csv"; false; }'
    out=$("$cs" "${run[@]}" -o "$d" --t-end "12 ms" 2>&1)
    check "run again: all this run's, no temporary or lock left" '[ $? -eq 0 ] && grep -q "\"t_end_s\":0.012" "$d/summary.json" && [ "$(listed "$d" | tr "\n" " ")" = "timeseries.csv events.csv summary.json " ] && [ -z "$(leftovers "$d")" ] || { echo "$out"; false; }'
fi

# A signal as a sweep begins, before its runs (here as it writes its journal to the disk, its first fsync,
# the folder made and locked): the sweep ends by it, its folder as it was: the folder it made removed.
sw=(sweep --allow-path examples tests/sweep/grid.yaml --quiet)
pid_of() { echo "\$(sed -n 's/^pid //p' $1/.cablesim-lock)"; } # the shell text of the pid holding $1's lock
d="$tmp/sweepstart"
at_signal=SIGINT at_break=fsync at_put 1 "shell kill -INT $(pid_of "$d")" "${sw[@]}" -o "$d"
check "SIGINT as a sweep writes its journal, before its runs: exit 130, the folder it made removed" '[ $? -eq 130 ] && [ ! -e "$d" ] || { cat "$tmp/at.out"; find "$d"; false; }'

# A signal during a sweep's commit, its runs done on two threads: the threads that ran them block SIGINT
# and SIGTERM, so the study's handler runs in the thread that writes the folder, which takes it once the
# files are in place: the folder holds the new study whole, no temporary or lock left.
d="$tmp/sweepcommit"
"$cs" "${sw[@]}" --threads 2 -o "$d" >/dev/null 2>&1
"$cs" "${sw[@]}" --threads 2 -o "$tmp/sweepref" --set "scenario.speed=30 mph" >/dev/null 2>&1
at_signal=SIGINT at_put 2 "shell kill -INT $(pid_of "$d")" "${sw[@]}" --threads 2 -o "$d" --set "scenario.speed=30 mph"
check "SIGINT during a sweep's commit on two threads: exit 130 once the files are in place" '[ $? -eq 130 ] || { cat "$tmp/at.out"; false; }'
check "the folder holds the new study whole, no temporary or lock left" 'cmp -s "$d/runs.csv" "$tmp/sweepref/runs.csv" && [ "$(listed "$d")" = "$(listed "$tmp/sweepref")" ] && [ "$(sums "$d" | grep plots/)" = "$(sums "$tmp/sweepref" | grep plots/)" ] && [ -z "$(leftovers "$d")" ] || { ls -A "$d"; cat "$d/.cablesim-manifest"; false; }'
finish
