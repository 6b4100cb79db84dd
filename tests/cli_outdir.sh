# SPDX-License-Identifier: MIT
# An output folder never loses a file cablesim did not write (src/io/out/outfile.c): a folder holding
# such files is refused, naming one, and --force writes beside them without removing or replacing any;
# a rerun removes only what the earlier run's manifest lists (never a path outside the folder); a
# second cablesim into a folder in use is kept out, naming the pid that holds it, and a dead holder's
# lock is taken over. The same rule for sweep, validate and compare.
# Usage: bash tests/cli_outdir.sh path/to/cablesim
source "$(dirname "$0")/lib.sh"
cs=$(cd "$(dirname "$cs")" && pwd)/$(basename "$cs")
src=$(pwd)

# A user's folder: their report, figure and diagram, and -o . into it.
user="$tmp/user"
mkdir -p "$user/plots"
echo "my report" >"$user/report.html"
echo "my figure" >"$user/plots/figure.png"
echo "my diagram" >"$user/plots/diagram.svg"
mine() { [ "$(cat "$user/report.html")" = "my report" ] && [ "$(cat "$user/plots/figure.png")" = "my figure" ] &&
    [ "$(cat "$user/plots/diagram.svg")" = "my diagram" ]; }
out=$(cd "$user" && "$cs" run "$src/examples/aps3.yaml" -o . --t-end "10 ms" --plots --report 2>&1)
check "a folder of the user's files is refused: status 1" '[ $? -eq 1 ]'
check "the refusal names one of them and says why" 'grep -qE "nothing run: \\. holds (report\\.html|plots/figure\\.png|plots/diagram\\.svg), which no cablesim run wrote there .*--force" <<<"$out" || { echo "$out"; false; }'
check "the refusal keeps the user's files and writes nothing" 'mine && [ "$(ls -A "$user" | tr "\\n" " ")" = "plots report.html " ] && [ "$(ls -A "$user/plots" | tr "\\n" " ")" = "diagram.svg figure.png " ]'

out=$(cd "$user" && "$cs" run "$src/examples/aps3.yaml" -o . --t-end "10 ms" --plots --report --force 2>&1)
check "--force does not write over a file of the user's: status 1, nothing written" '[ $? -eq 1 ] && grep -q "report.html: a file is there which no cablesim run wrote there" <<<"$out" && mine && [ ! -e "$user/summary.json" ] && [ -z "$(find "$user" -name ".cablesim*")" ]'
out=$(cd "$user" && "$cs" run "$src/examples/aps3.yaml" -o . --t-end "10 ms" --plots --force 2>&1)
check "--force writes beside the user's files" '[ $? -eq 0 ] && mine && [ -s "$user/summary.json" ] && [ -s "$user/plots/speed.png" ] || { echo "$out"; false; }'
check "the manifest lists the run's files, not the user's" 'grep -qP "^summary.json\\t$(stat -c %s "$user/summary.json")\\t[0-9a-f]{16}$" "$user/.cablesim-manifest" && grep -qP "^plots/speed.svg\\t" "$user/.cablesim-manifest" && ! grep -qE "report.html|figure|diagram" "$user/.cablesim-manifest"'
check "no lock or temporary is left" '[ ! -e "$user/.cablesim-lock" ] && [ -z "$(find "$user" -name ".cablesim-tmp.*")" ]'
out=$(cd "$user" && "$cs" run "$src/examples/aps3.yaml" -o . --t-end "10 ms" --force 2>&1)
check "a forced rerun removes the earlier run's plots, and only those" '[ $? -eq 0 ] && mine && [ -z "$(ls "$user/plots" | grep -v -e figure.png -e diagram.svg)" ] && [ -s "$user/summary.json" ]'

# A folder cablesim wrote is its own: a rerun needs no --force and removes what it does not write.
own="$tmp/own"
"$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" --plots --report >/dev/null 2>&1
"$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" --plots --report >"$tmp/own.out" 2>&1
check "a rerun into a folder cablesim wrote" '[ $? -eq 0 ] && [ -s "$own/plots/speed.png" ] || { cat "$tmp/own.out"; false; }'
"$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" >/dev/null 2>&1
check "a rerun without --plots and --report removes the earlier figures, the report and plots/" '[ $? -eq 0 ] && [ ! -e "$own/plots" ] && [ ! -e "$own/report.html" ] && [ "$(ls "$own" | tr "\\n" " ")" = "events.csv summary.json timeseries.csv " ]'

# A listed file is cablesim's only while it is as written: the manifest's size and hash (64-bit FNV-1a,
# checked against the published value for "a") tell an edited file from cablesim's.
fnv1a64() { # the 64-bit FNV-1a of a file's bytes, in bash's wrapping 64-bit arithmetic
    local h=$((0xcbf29ce484222325)) b
    for b in $(od -An -v -tu1 "$1"); do h=$(((h ^ b) * 0x100000001b3)); done
    printf '%016x' "$h"
}
check "FNV-1a 64 of \"a\" is the published af63dc4c8601ec8c" '[ "$(printf a >"$tmp/a" && fnv1a64 "$tmp/a")" = af63dc4c8601ec8c ]'
check "the manifest's hash is FNV-1a 64 of the file's bytes" 'grep -qP "^events.csv\\t$(stat -c %s "$own/events.csv")\\t$(fnv1a64 "$own/events.csv")$" "$own/.cablesim-manifest"'
cp "$own/summary.json" "$tmp/summary.before"
printf ' ' >>"$own/summary.json" # an edit: the file is the user's now
edited=$(sha256sum <"$own/summary.json")
out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
check "a file edited since cablesim wrote it is refused, named, and kept" '[ $? -eq 1 ] && grep -q "nothing run: $own holds summary.json, which has changed since cablesim wrote it there" <<<"$out" && [ "$(sha256sum <"$own/summary.json")" = "$edited" ] || { echo "$out"; false; }'
out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" --force 2>&1)
check "--force does not write over the edited file either" '[ $? -eq 1 ] && grep -q "summary.json: a file is there which has changed since cablesim wrote it there" <<<"$out" && [ "$(sha256sum <"$own/summary.json")" = "$edited" ] || { echo "$out"; false; }'
mv "$tmp/summary.before" "$own/summary.json"
# A name listed twice (the manifest a commit writes before its renames gives a name both runs write each
# run's size and hash): the file there is cablesim's if it is as either line says, the user's if neither.
other=$(printf 'summary.json\t5\t0123456789abcdef')
for order in after before; do
    cp "$own/.cablesim-manifest" "$tmp/manifest.before"
    { head -n 2 "$tmp/manifest.before"; [ $order = after ] || echo "$other"; tail -n +3 "$tmp/manifest.before"; [ $order = before ] || echo "$other"; } >"$own/.cablesim-manifest"
    out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
    check "a name listed twice, the file as written $order the other line: cablesim's, replaced, listed once" '[ $? -eq 0 ] && [ "$(grep -c "^summary.json	" "$own/.cablesim-manifest")" -eq 1 ] || { echo "$out"; false; }'
done
cp "$own/summary.json" "$tmp/summary.before"
printf ' ' >>"$own/summary.json"
{ cat "$own/.cablesim-manifest"; echo "$other"; } >"$tmp/manifest.twice" && cp "$tmp/manifest.twice" "$own/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
check "a name listed twice, the file as neither line says: the user's, refused and kept" '[ $? -eq 1 ] && grep -q "nothing run: $own holds summary.json, which has changed since cablesim wrote it there" <<<"$out" && cmp -s "$own/.cablesim-manifest" "$tmp/manifest.twice" || { echo "$out"; false; }'
mv "$tmp/summary.before" "$own/summary.json"
head -n -1 "$tmp/manifest.twice" >"$own/.cablesim-manifest"
echo "my notes" >"$own/notes.txt"
printf 'notes.txt\n' >>"$own/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
check "a name typed into the manifest does not make a file cablesim's" '[ $? -eq 1 ] && grep -q "holds notes.txt, which .cablesim-manifest lists without the size and hash" <<<"$out" && [ "$(cat "$own/notes.txt")" = "my notes" ] || { echo "$out"; false; }'
printf 'notes.txt\t9\t0123456789abcdef\n' >>"$own/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" --force 2>&1)
check "nor does one typed with a wrong hash: --force writes beside it and keeps it" '[ $? -eq 0 ] && [ "$(cat "$own/notes.txt")" = "my notes" ] && ! grep -q "^notes.txt" "$own/.cablesim-manifest" || { echo "$out"; false; }'
rm "$own/notes.txt"
# The manifest is read as cablesim writes it: a size with a sign, a space or a leading zero, or a hash in
# capitals, is a line edited, and its file the user's.
cp "$own/.cablesim-manifest" "$tmp/manifest.before"
summary=$(sha256sum <"$own/summary.json")
for edit in 's/^summary.json\t/&+/' 's/^summary.json\t/& /' 's/^summary.json\t/&0/' 's/^\(summary.json\t[0-9]*\t\)\(.*\)$/\1\U\2/'; do
    sed "$edit" "$tmp/manifest.before" >"$own/.cablesim-manifest"
    out=$("$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
    check "a manifest line not as cablesim writes it ($edit) makes its file the user's" '[ $? -eq 1 ] && ! cmp -s "$own/.cablesim-manifest" "$tmp/manifest.before" && grep -q "holds summary.json, which .cablesim-manifest lists without the size and hash" <<<"$out" && [ "$(sha256sum <"$own/summary.json")" = "$summary" ] || { echo "$out"; false; }'
done
mv "$tmp/manifest.before" "$own/.cablesim-manifest"
cp "$own/events.csv" "$tmp/events.before"
truncate -s 64G "$own/events.csv" # sparse: no room taken, 64 GB to read
out=$(timeout -s KILL 20 "$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" 2>&1)
check "a listed file of another size is judged without reading it (64 GB, sparse)" '[ $? -eq 1 ] && grep -q "holds events.csv, which has changed since" <<<"$out" || { echo "$out"; false; }'
mv "$tmp/events.before" "$own/events.csv"

# The folder is judged again at the commit, not only before the run: an earlier run's file edited during
# the run is the user's then, kept; one this run would replace fails the commit, nothing written.
ed="$tmp/edited"
"$cs" run examples/aps3.yaml -o "$ed" --t-end "10 ms" --plots >/dev/null 2>&1
# edit_during EDIT: a run of a few seconds into $ed, EDIT run once it holds the folder and has judged it
# (the lock is taken just before the judging, which takes milliseconds; the run's steps take over 2 s);
# its status
edit_during() {
    "$cs" run examples/aps3.yaml -o "$ed" --t-end "20 ms" --dt "0.0005 ms" >"$tmp/ed.out" 2>&1 &
    local pid=$!
    for _ in $(seq 6000); do
        [ -e "$ed/.cablesim-lock" ] && break
        sleep 0.01
    done
    sleep 0.5
    eval "$1"
    wait "$pid"
}
edit_during 'echo "my notes" >"$ed/plots/speed.png"'
check "an earlier run's file edited during the run is kept, not removed" '[ $? -eq 0 ] && [ "$(cat "$ed/plots/speed.png")" = "my notes" ] && ! grep -q "^plots/speed.png" "$ed/.cablesim-manifest" && [ ! -e "$ed/plots/speed.svg" ] || { cat "$tmp/ed.out"; false; }'
rm "$ed/plots/speed.png"
edit_during 'printf " " >>"$ed/summary.json"; edited=$(sha256sum <"$ed/summary.json")'
check "one it would replace, edited during the run: nothing written, the edit kept" '[ $? -eq 1 ] && grep -q "nothing written: $ed/summary.json: a file is there which has changed since cablesim wrote it there" "$tmp/ed.out" && [ "$(sha256sum <"$ed/summary.json")" = "$edited" ] && [ -z "$(find "$ed" -name ".cablesim-tmp.*" -o -name .cablesim-lock)" ] || { cat "$tmp/ed.out"; false; }'

# An earlier run's file that cannot be removed once the new files are in place (plots/ made read-only)
# fails the command (status 1), which says the new results are written, names the file and why, and
# leaves it in the manifest, cablesim's: the next run removes it. Root ignores a folder's permissions, so
# as root the runs go as nobody, the binary, the model and the parts library copied where nobody reads them.
pub="$tmp/pub"
mkdir -p "$pub/ro"
cp "$cs" "$pub/cablesim" && cp -r "$src/data" "$pub/data" && cp examples/aps3.yaml "$pub/"
chmod -R a+rX "$pub" && chmod a+x "$tmp"
as=()
[ "$(id -u)" -eq 0 ] && as=(setpriv --reuid=65534 --regid=65534 --clear-groups) && chown 65534:65534 "$pub/ro"
if [ ${#as[@]} -gt 0 ] && ! command -v setpriv >/dev/null; then
    echo "skipped: an earlier file that cannot be removed (root, and no setpriv to run as nobody)"
else
    ro() { "${as[@]}" env CABLESIM_DATA="$pub/data" "$pub/cablesim" run "$pub/aps3.yaml" -o "$pub/ro" "$@" 2>&1; }
    ro --t-end "10 ms" --plots >/dev/null
    chmod a-w "$pub/ro/plots"
    out=$(ro --t-end "12 ms")
    check "an earlier file that cannot be removed: status 1, the new results written, the file named and why" '[ $? -eq 1 ] && grep -qE "^cablesim: the new results are in $pub/ro, but the earlier run.s plots/[a-z]+\.(png|svg) could not be removed: Permission denied \(and [0-9]+ more of its files\); .cablesim-manifest still lists it" <<<"$out" && ! grep -q "nothing written" <<<"$out" && grep -q "\"t_end_s\":0.012" "$pub/ro/summary.json" || { echo "$out"; false; }'
    check "the earlier files stay in the manifest with the new ones; no lock or temporary is left" 'grep -qP "^summary.json\t$(stat -c %s "$pub/ro/summary.json")\t" "$pub/ro/.cablesim-manifest" && grep -q "^plots/speed.png" "$pub/ro/.cablesim-manifest" && [ ! -e "$pub/ro/.cablesim-lock" ] && [ -z "$(find "$pub/ro" -name ".cablesim-tmp.*")" ]'
    chmod u+w "$pub/ro/plots"
    out=$(ro --t-end "12 ms")
    check "the next run removes them" '[ $? -eq 0 ] && [ ! -e "$pub/ro/plots" ] && ! grep -q "^plots/" "$pub/ro/.cablesim-manifest" || { echo "$out"; false; }'
fi

# A failed run leaves the folder as it was: an empty plots/ of the user's stays.
"$cs" run examples/aps3.yaml -o "$tmp/emptysub" --t-end "10 ms" >/dev/null 2>&1
mkdir "$tmp/emptysub/plots"
out=$(CABLESIM_TEST_DEV_FULL=plots/speed.png "$cs" run examples/aps3.yaml -o "$tmp/emptysub" --t-end "10 ms" --plots 2>&1)
check "a failed run keeps an empty subfolder that was there before it" '[ $? -eq 1 ] && grep -q "plots/speed.png: No space left on device" <<<"$out" && [ -d "$tmp/emptysub/plots" ] && [ -z "$(ls -A "$tmp/emptysub/plots")" ] || { echo "$out"; false; }'

# A failed run removes the folders it made, whatever the form of the path: one named with a '.' or a '..'
# in it too.
for o in made/. made2/a/../b; do
    out=$(cd "$tmp" && CABLESIM_TEST_DEV_FULL=summary.json "$cs" run "$src/examples/aps3.yaml" -o "$o" --t-end "10 ms" 2>&1)
    check "a failed run into $o removes the folders it made" '[ $? -eq 1 ] && grep -q "summary.json: No space left on device" <<<"$out" && [ ! -e "$tmp/${o%%/*}" ] || { echo "$out"; find "$tmp/${o%%/*}"; false; }'
done

# A folder holds one command's results: another command's are kept as the user's are (named in the
# refusal, and --force writes beside them), so a validate into a run's folder does not remove the run.
cmd="$tmp/cmd"
"$cs" run examples/aps3.yaml -o "$cmd" --t-end "10 ms" >/dev/null 2>&1
sums=$(cd "$cmd" && sha256sum events.csv summary.json timeseries.csv)
out=$("$cs" validate -o "$cmd" --only verification 2>&1)
check "validate into a run's folder is refused, naming the command that wrote it" '[ $? -eq 1 ] && grep -q "nothing run: $cmd holds [a-z.]*, which \`cablesim run\` wrote there: that command.s results, which \`cablesim validate\` does not replace" <<<"$out" && [ "$(cd "$cmd" && sha256sum events.csv summary.json timeseries.csv)" = "$sums" ] || { echo "$out"; false; }'
out=$("$cs" validate -o "$cmd" --only verification --force 2>&1)
check "validate --force writes beside the run's results and keeps them" '[ $? -eq 0 ] && [ -s "$cmd/validation.md" ] && [ "$(cd "$cmd" && sha256sum events.csv summary.json timeseries.csv)" = "$sums" ] && grep -qx "# written by: cablesim validate" "$cmd/.cablesim-manifest" && ! grep -q "^summary.json" "$cmd/.cablesim-manifest" || { echo "$out"; false; }'

# A folder an earlier version wrote (its manifest names its files without size or hash) is refused, saying
# so, and nothing in it is removed.
old="$tmp/oldversion"
mkdir -p "$old" && echo "old run" >"$old/summary.json"
printf '# cablesim: the files its last run wrote in this folder; the next run into it removes these and no other\nsummary.json\n' >"$old/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$old" --t-end "10 ms" 2>&1)
check "an earlier version's folder is refused, saying why, and kept" '[ $? -eq 1 ] && grep -q "holds summary.json, which an earlier version of cablesim may have written there, but its .cablesim-manifest gives no size and hash" <<<"$out" && [ "$(cat "$old/summary.json")" = "old run" ] || { echo "$out"; false; }'

# A manifest whose "written by" line names no command (edited), or names two, gives no command its files:
# they are kept as another command's.
wb="$tmp/writtenby"
"$cs" validate -o "$wb" --only verification >/dev/null 2>&1
sums=$(cd "$wb" && sha256sum validation.*)
sed -i 's/^# written by: cablesim validate$/# written by: cablesim validate!/' "$wb/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$wb" --t-end "10 ms" 2>&1)
check "a manifest naming no command: its files kept, the folder refused" '[ $? -eq 1 ] && grep -q "holds validation.[a-z]*, which a cablesim command wrote there that .cablesim-manifest does not name" <<<"$out" && [ "$(cd "$wb" && sha256sum validation.*)" = "$sums" ] || { echo "$out"; false; }'
sed -i 's/^# written by: cablesim validate!$/# written by: cablesim validate\n# written by: cablesim run/' "$wb/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$wb" --t-end "10 ms" --force 2>&1)
check "one naming two: --force writes beside its files and keeps them" '[ $? -eq 0 ] && [ -s "$wb/summary.json" ] && [ "$(cd "$wb" && sha256sum validation.*)" = "$sums" ] || { echo "$out"; false; }'

# A sweep whose outputs failed (here on a full disk) keeps its runs in .cablesim-journal for --resume:
# another command's results into its folder keep it as the user's files are.
jr="$tmp/journal"
CABLESIM_TEST_DEV_FULL=runs.csv "$cs" sweep --allow-path examples tests/sweep/grid.yaml -o "$jr" --quiet >/dev/null 2>&1
journal=$(sha256sum <"$jr/.cablesim-journal")
out=$("$cs" run examples/aps3.yaml -o "$jr" --t-end "10 ms" 2>&1)
check "a run into a stopped sweep's folder is refused, naming its journal, which is kept" '[ $? -eq 1 ] && grep -q "nothing run: $jr holds .cablesim-journal, which a \`cablesim sweep\` stopped before its outputs left there" <<<"$out" && [ "$(sha256sum <"$jr/.cablesim-journal")" = "$journal" ] || { echo "$out"; false; }'
out=$("$cs" validate -o "$jr" --only verification --force 2>&1)
check "validate --force writes beside the journal and keeps it" '[ $? -eq 0 ] && [ -s "$jr/validation.md" ] && [ "$(sha256sum <"$jr/.cablesim-journal")" = "$journal" ] || { echo "$out"; false; }'
out=$("$cs" sweep --resume "$jr" --force --quiet 2>&1)
check "then sweep --resume reads the runs back from it" '[ $? -eq 0 ] && [ "$(wc -l <"$jr/runs.csv")" -eq 7 ] && [ ! -e "$jr/.cablesim-journal" ] || { echo "$out"; false; }'

# A file of the user's named .cablesim-journal (one that does not begin as a sweep's journal does, with
# its study's record) is not one: a sweep into its folder is refused, with --force too, and keeps it.
uj="$tmp/userjournal"
mkdir -p "$uj" && echo "my notes" >"$uj/.cablesim-journal"
for force in "" --force; do
    out=$("$cs" sweep --allow-path examples tests/sweep/grid.yaml -o "$uj" --quiet $force 2>&1)
    check "a file of text named .cablesim-journal: sweep ${force:-without --force} refuses it and keeps it" '[ $? -eq 1 ] && grep -qF "nothing run: $uj/.cablesim-journal: not a journal of cablesim" <<<"$out" && [ "$(cat "$uj/.cablesim-journal")" = "my notes" ] && [ "$(ls -A "$uj")" = .cablesim-journal ] || { echo "$out"; ls -A "$uj"; false; }'
done

# A manifest names files inside its folder only: a line that leaves it removes nothing.
echo outside >"$tmp/victim.txt"
mkdir -p "$tmp/linked" && echo linked >"$tmp/linked/x.csv"
ln -s "$tmp/linked" "$own/sub"
printf '../victim.txt\n%s\nsub/x.csv\n' "$tmp/victim.txt" >>"$own/.cablesim-manifest"
"$cs" run examples/aps3.yaml -o "$own" --t-end "10 ms" --force >/dev/null 2>&1 # --force: sub is not its own
check "a manifest's paths out of the folder, absolute or through a link remove nothing" '[ $? -eq 0 ] && [ "$(cat "$tmp/victim.txt")" = outside ] && [ "$(cat "$tmp/linked/x.csv")" = linked ]'
rm "$own/sub"

# The lock: a run into a folder in use is refused with the holder's pid; a dead holder's lock is taken.
busy="$tmp/busy"
"$cs" run examples/aps3.yaml -o "$busy" --dt "0.0002 ms" >/dev/null 2>&1 &
holder=$!
for _ in $(seq 200); do
    [ -s "$busy/.cablesim-lock" ] && break
    sleep 0.05
done
out=$("$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" 2>&1)
check "a second run into a folder in use is refused, naming the pid holding it" '[ $? -eq 1 ] && grep -q "nothing run: $busy is in use by another cablesim (pid $holder holds $busy/.cablesim-lock)" <<<"$out" || { echo "$out"; false; }'
kill -KILL "$holder" # no handler runs: the lock stays
wait "$holder" 2>/dev/null
check "the killed run left its lock: cablesim's text, its pid and host" '[ "$(cat "$busy/.cablesim-lock")" = "$(printf "cablesim lock\npid %s\nhost %s" "$holder" "$(uname -n)")" ]'
out=$("$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" 2>&1)
check "a dead run's lock is taken over" '[ $? -eq 0 ] && [ -s "$busy/summary.json" ] && [ ! -e "$busy/.cablesim-lock" ] || { echo "$out"; false; }'
printf 'cablesim lock\npid 999999999\nhost %s\n' "$(uname -n)" >"$busy/.cablesim-lock"
check "a lock naming a process that has ended is taken over" '"$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" >/dev/null 2>&1 && [ ! -e "$busy/.cablesim-lock" ]'
# a running cablesim holds its lock's fcntl lock: a lock naming a running process that does not hold it
# (its pid reused since, or a killed run not yet reaped) is an ended run's
printf 'cablesim lock\npid %s\nhost %s\n' "$$" "$(uname -n)" >"$busy/.cablesim-lock"
check "a lock naming a running process that does not hold it is taken over" '"$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" >/dev/null 2>&1 && [ ! -e "$busy/.cablesim-lock" ]'
printf 'cablesim lock\npid 999999999\nhost another-machine\n' >"$busy/.cablesim-lock"
out=$("$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" 2>&1)
check "a lock of another machine is kept, the folder in use" '[ $? -eq 1 ] && grep -qF "(pid 999999999 on another-machine holds $busy/.cablesim-lock)" <<<"$out" && grep -q "^host another-machine$" "$busy/.cablesim-lock" || { echo "$out"; false; }'
# A file of the user's named .cablesim-lock that holds a number (no process of that pid) is not a lock:
# kept, and the folder refused, with --force too.
echo 999999998 >"$busy/.cablesim-lock"
out=$("$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" 2>&1)
check "a file of a number named .cablesim-lock is the user's: refused and kept" '[ $? -eq 1 ] && grep -qF "nothing run: $busy/.cablesim-lock: not a lock of cablesim" <<<"$out" && [ "$(cat "$busy/.cablesim-lock")" = 999999998 ] || { echo "$out"; false; }'
out=$("$cs" run examples/aps3.yaml -o "$busy" --t-end "10 ms" --force 2>&1)
check "--force refuses it too, saying so, and keeps it" '[ $? -eq 1 ] && grep -qF "the folder cannot be locked beside it, even with --force" <<<"$out" && [ "$(cat "$busy/.cablesim-lock")" = 999999998 ] || { echo "$out"; false; }'
rm "$busy/.cablesim-lock"
# Ctrl-C (SIGINT) or SIGTERM leaves the folder as it was before the command: no temporary, no lock, the
# folders the command made removed, an earlier run's files byte for byte; the command then dies by the
# signal (exit 128 + the signal). validate begins its two files before it runs anything, so the signal
# finds both temporaries there. `env --default-signal`: a script's background job ignores SIGINT, and
# cablesim keeps a signal it was started ignoring ignored.
# interrupt SIGNAL COMMAND...: COMMAND (run or validate into $dir) started, sent SIGNAL once $dir holds
# WAIT_FOR (waiting up to 60 s: a loaded machine is slow to start it), and waited for; the status is its
interrupt() {
    local sig=$1
    shift
    env --default-signal="$sig" "$cs" "$@" >/dev/null 2>&1 &
    local pid=$!
    for _ in $(seq 6000); do
        [ -n "$(find "$dir" -maxdepth 1 -name "$wait_for" 2>/dev/null)" ] && break
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.01
    done
    kill -"$sig" "$pid"
    wait "$pid"
}
# every file under $1, hidden ones too, with its checksum
sums() { (cd "$1" && find . -type f -exec md5sum {} + | sort); }
wait_for=".cablesim-tmp.validation.csv.*"
mkdir -p "$tmp/sig"
for s in INT:130 TERM:143; do
    dir="$tmp/sig/new/deeper"
    interrupt "${s%:*}" validate --only sensitivity -o "$dir"
    check "validate stopped by SIG${s%:*} into a new folder: exit ${s#*:}, the folders it made removed" '[ $? -eq "${s#*:}" ] && [ ! -e "$tmp/sig/new" ] || { find "$tmp/sig/new"; false; }'
    dir="$tmp/sig/kept"
    [ -d "$dir" ] || "$cs" validate --only bogie -o "$dir" >/dev/null 2>&1
    before=$(sums "$dir")
    interrupt "${s%:*}" validate --only sensitivity -o "$dir"
    check "validate stopped by SIG${s%:*} into an earlier run's folder: exit ${s#*:}, no temporary or lock, its files byte for byte" '[ $? -eq "${s#*:}" ] && [ "$(sums "$dir")" = "$before" ] && [ "$(ls -A "$dir" | tr "\n" " ")" = ".cablesim-manifest validation.csv validation.md " ] || { ls -A "$dir"; false; }'
done
dir="$tmp/sig/run"
wait_for=.cablesim-lock
interrupt INT run examples/aps3.yaml -o "$dir" --dt "0.0002 ms"
check "run stopped by SIGINT: exit 130, the folder it made removed" '[ $? -eq 130 ] && [ ! -e "$dir" ]'
# a SIGINT the command was started ignoring stays ignored; SIGTERM then ends it
env --ignore-signal=INT "$cs" run examples/aps3.yaml -o "$dir" --dt "0.0002 ms" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 6000); do
    [ -e "$dir/.cablesim-lock" ] && break
    sleep 0.01
done
kill -INT "$pid"
sleep 0.3
check "a run started ignoring SIGINT goes on after one" 'kill -0 "$pid"'
kill -TERM "$pid"
wait "$pid"
check "then SIGTERM ends it: exit 143, the folder it made removed" '[ $? -eq 143 ] && [ ! -e "$dir" ]'

# A FIFO named .cablesim-manifest is refused at once, not waited on.
mkdir -p "$tmp/fifo"
mkfifo "$tmp/fifo/.cablesim-manifest"
out=$(timeout 10 "$cs" run examples/aps3.yaml -o "$tmp/fifo" --t-end "10 ms" 2>&1)
check "a FIFO as the manifest is refused at once" '[ $? -eq 1 ] && grep -q "nothing run: $tmp/fifo/.cablesim-manifest: not a regular file" <<<"$out" && [ "$(ls -A "$tmp/fifo")" = .cablesim-manifest ] || { echo "$out"; false; }'

# A file named like a temporary that cablesim does not make (not .cablesim-tmp.NAME.XXXXXX, or below a
# subfolder) is the user's: refused, named and kept; the temporaries a killed run left are removed.
tn="$tmp/tmpnames"
mkdir -p "$tn/sub/deeper" "$tn/plots"
echo "my notes" >"$tn/.cablesim-tmp.notes"
echo "kept" >"$tn/sub/deeper/.cablesim-tmp.summary.json.AbC123"
out=$("$cs" run examples/aps3.yaml -o "$tn" --t-end "10 ms" 2>&1)
check "files named like temporaries cablesim does not make are refused, and kept" '[ $? -eq 1 ] && grep -qE "holds (\.cablesim-tmp\.notes|sub/deeper/\.cablesim-tmp\.summary\.json\.AbC123), which no cablesim run wrote there" <<<"$out" && [ "$(cat "$tn/.cablesim-tmp.notes")" = "my notes" ] && [ "$(cat "$tn/sub/deeper/.cablesim-tmp.summary.json.AbC123")" = kept ] || { echo "$out"; false; }'
rm -r "$tn/.cablesim-tmp.notes" "$tn/sub"
echo stale >"$tn/.cablesim-tmp.summary.json.AbC123"
echo stale >"$tn/plots/.cablesim-tmp.speed.png.x1Y2z3"
out=$("$cs" run examples/aps3.yaml -o "$tn" --t-end "10 ms" 2>&1)
check "a killed run's temporaries, in the folder and in plots/, are removed" '[ $? -eq 0 ] && [ -z "$(find "$tn" -name ".cablesim-tmp.*")" ] || { echo "$out"; false; }'

# A manifest larger than any cablesim writes is not one: refused at once, and kept.
mkdir -p "$tmp/bigman"
truncate -s 64G "$tmp/bigman/.cablesim-manifest" # sparse: no room taken
out=$(timeout -s KILL 20 "$cs" run examples/aps3.yaml -o "$tmp/bigman" --t-end "10 ms" 2>&1)
check "a manifest of 64 GB (sparse) is refused at once, not read" '[ $? -eq 1 ] && grep -q "nothing run: $tmp/bigman/.cablesim-manifest: 68719476736 bytes, more than a manifest of cablesim.s holds" <<<"$out" && [ "$(stat -c %s "$tmp/bigman/.cablesim-manifest")" = 68719476736 ] || { echo "$out"; false; }'
{ echo "# cablesim: the files its last run wrote in this folder"; seq -f "f%g" 120000; } >"$tmp/bigman/.cablesim-manifest"
out=$(timeout -s KILL 20 "$cs" run examples/aps3.yaml -o "$tmp/bigman" --t-end "10 ms" 2>&1)
check "one of 120,000 names is refused at once" '[ $? -eq 1 ] && grep -q "nothing run: $tmp/bigman/.cablesim-manifest: lists more than 256 files" <<<"$out" && [ "$(wc -l <"$tmp/bigman/.cablesim-manifest")" -eq 120001 ] || { echo "$out"; false; }'

# A file named .cablesim-lock that no cablesim made (a hard link to a file elsewhere, or a file of text) is
# not a lock: it is refused, even with --force, and neither truncated nor removed.
echo "precious data" >"$tmp/precious.txt"
mkdir -p "$tmp/hardlinked"
ln "$tmp/precious.txt" "$tmp/hardlinked/.cablesim-lock"
out=$("$cs" run examples/aps3.yaml -o "$tmp/hardlinked" --t-end "10 ms" --force 2>&1)
check "a hard link named .cablesim-lock is refused, the file it shares kept" '[ $? -eq 1 ] && grep -q "nothing run: $tmp/hardlinked/.cablesim-lock: not a lock of cablesim" <<<"$out" && [ "$(cat "$tmp/precious.txt")" = "precious data" ] && [ -e "$tmp/hardlinked/.cablesim-lock" ] && [ ! -e "$tmp/hardlinked/summary.json" ] || { echo "$out"; false; }'
mkdir -p "$tmp/textlock"
echo "my notes" >"$tmp/textlock/.cablesim-lock"
out=$("$cs" run examples/aps3.yaml -o "$tmp/textlock" --t-end "10 ms" 2>&1)
check "a file of text named .cablesim-lock is refused and kept" '[ $? -eq 1 ] && grep -q "not a lock of cablesim" <<<"$out" && [ "$(cat "$tmp/textlock/.cablesim-lock")" = "my notes" ] || { echo "$out"; false; }'

# A file named .cablesim-manifest that does not begin as every manifest cablesim writes does (a file of
# notes, an empty file) is not one: the folder is refused, even with --force (the run's manifest goes at
# that name), and the file kept.
tm="$tmp/textmanifest"
mkdir -p "$tm"
echo "my notes" >"$tm/.cablesim-manifest"
out=$("$cs" run examples/aps3.yaml -o "$tm" --t-end "10 ms" 2>&1)
check "a file of text named .cablesim-manifest is refused and kept, nothing written" '[ $? -eq 1 ] && grep -qF "nothing run: $tm/.cablesim-manifest: not a manifest of cablesim" <<<"$out" && [ "$(cat "$tm/.cablesim-manifest")" = "my notes" ] && [ "$(ls -A "$tm")" = .cablesim-manifest ] || { echo "$out"; false; }'
out=$("$cs" run examples/aps3.yaml -o "$tm" --t-end "10 ms" --force 2>&1)
check "--force refuses it too, saying so, and keeps it" '[ $? -eq 1 ] && grep -q "the folder cannot hold cablesim.s beside it, even with --force" <<<"$out" && [ "$(cat "$tm/.cablesim-manifest")" = "my notes" ] && [ "$(ls -A "$tm")" = .cablesim-manifest ] || { echo "$out"; false; }'
: >"$tm/.cablesim-manifest"
out=$("$cs" sweep --allow-path examples tests/sweep/grid.yaml -o "$tm" --quiet 2>&1)
check "an empty .cablesim-manifest is refused by sweep too, and kept" '[ $? -eq 1 ] && grep -qF "nothing run: $tm/.cablesim-manifest: not a manifest of cablesim" <<<"$out" && [ -f "$tm/.cablesim-manifest" ] && [ ! -s "$tm/.cablesim-manifest" ] && [ "$(ls -A "$tm")" = .cablesim-manifest ] || { echo "$out"; false; }'

# A model's name never steers where the files go: results/NAME with a NAME of '..' is refused at its
# place, and nothing is written (tests/bad/name_*.yaml: the other refusals).
mkdir -p "$tmp/cwd/a/b"
out=$(cd "$tmp/cwd/a/b" && "$cs" run "$src/tests/good/base.yaml" --t-end "5 ms" --set "name=../../../victim" 2>&1)
check "a name out of results/ is refused at its place, nothing written" '[ $? -eq 2 ] && grep -qF -- "--set name=../../../victim: not a name for the output folder results/NAME" <<<"$out" && [ -z "$(find "$tmp/cwd" -mindepth 3)" ] && [ ! -e "$tmp/victim" ]'
out=$(cd "$tmp/cwd/a/b" && "$cs" designer "$src/tests/bad/name_path.yaml" 2>&1)
check "designer refuses it too (results/NAME-designer)" '[ $? -eq 2 ] && [ -z "$(find "$tmp/cwd" -mindepth 3)" ] && grep -q "name_path.yaml:2:7: name: not a name for the output folder" <<<"$out"'

# The other commands keep their folders by the same rule.
out=$("$cs" sweep --allow-path examples tests/sweep/grid.yaml -o "$user" --quiet 2>&1)
check "sweep refuses the user's folder before any run" '[ $? -eq 1 ] && grep -q "nothing run: .*which no cablesim run wrote there" <<<"$out" && mine'
out=$("$cs" validate -o "$user" --only verification 2>&1)
check "validate refuses the user's folder" '[ $? -eq 1 ] && grep -q "nothing run: .*which no cablesim run wrote there" <<<"$out" && mine'
out=$("$cs" compare "$own" -o "$user" 2>&1)
check "compare refuses the user's folder" '[ $? -eq 1 ] && grep -q "nothing written: .*which no cablesim run wrote there" <<<"$out" && mine'
out=$("$cs" compare "$own" -o "$user" --force 2>&1)
check "compare --force writes beside them" '[ $? -eq 0 ] && [ -s "$user/compare.csv" ] && mine || { echo "$out"; false; }'
out=$("$cs" designer examples/aps3.yaml -o "$user" 2>&1)
if grep -q "built without emscripten" <<<"$out"; then
    echo "skipped: designer (this cablesim was built without emscripten)"
else
    check "designer refuses the user's folder" '[ $? -eq 1 ] && grep -q "nothing written: .*which no cablesim run wrote there" <<<"$out" && mine'
fi
"$cs" compare "$own" -o "$tmp/cmp" >/dev/null 2>&1
check "compare reruns into its own folder" '"$cs" compare "$own" -o "$tmp/cmp" >/dev/null 2>&1 && [ -s "$tmp/cmp/compare.csv" ]'
# compare into the folder of a run it compares would remove that run's files (its manifest's): refused.
cp -r "$own" "$tmp/own2"
before=$(cd "$own" && md5sum * | sort)
out=$("$cs" compare "$own" "$tmp/own2" -o "$own/" --force 2>&1)
check "compare into a run's folder it compares is refused, the run kept" '[ $? -eq 1 ] && grep -qF "nothing written: $own/ is the folder of the run $own compared" <<<"$out" && [ "$(cd "$own" && md5sum * | sort)" = "$before" ] && [ ! -e "$own/compare.csv" ] || { echo "$out"; false; }'
out=$(cd "$own" && "$cs" compare "$tmp/own2" --measured timeseries.csv -o . 2>&1)
check "compare into the folder of its measured history is refused, the run there kept" '[ $? -eq 1 ] && grep -qF "nothing written: . is the folder of the measured history timeseries.csv compared" <<<"$out" && [ "$(cd "$own" && md5sum * | sort)" = "$before" ] || { echo "$out"; false; }'
mkdir -p "$tmp/measured" && cp "$own/timeseries.csv" "$tmp/measured/test.csv"
out=$("$cs" compare "$tmp/own2" --measured "$tmp/measured/test.csv" -o "$tmp/measured" --force 2>&1)
check "compare --force writes beside a measured history in a folder of the user's" '[ $? -eq 0 ] && [ -s "$tmp/measured/compare.csv" ] && cmp -s "$own/timeseries.csv" "$tmp/measured/test.csv" || { echo "$out"; false; }'

finish
