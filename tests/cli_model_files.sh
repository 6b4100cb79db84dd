#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Model files are untrusted input (docs/robustness.md, "A user's files and machine"): a file: and a
# study's model: are found from the file naming them and read only inside the folder of the file named
# on the command line (and below), the parts library's, or a folder --allow-path allows; only regular
# files are read (a FIFO is refused at once), at most 64 MB; a named file that is not a model is reported
# at its place, never by its text; `designer` embeds only the files so read. The examples need no leave.
source "$(dirname "$0")/lib.sh"
mkdir -p "$tmp/m/sub" "$tmp/outside"
cp tests/good/base.yaml "$tmp/outside/base.yaml"
cp tests/good/base.yaml "$tmp/m/sub/base.yaml"
model() { printf 'name: t\nbarrier: {file: %s}\nvehicle: M\nscenario: {speed: 40 mph, impact_x: 28 ft, t_end: 1 s}\n' "$2" >"$1"; }

# a file outside the model's folder: refused at the place that names it, relative or absolute
model "$tmp/m/rel.yaml" ../outside/base.yaml
out=$("$cs" check "$tmp/m/rel.yaml" 2>&1)
check "a ../ file outside: exit 2, at 2:17, with the folders and --allow-path" '[ $? -eq 2 ] && grep -qF "$tmp/m/rel.yaml:2:17: barrier.file: '"'"'../outside/base.yaml'"'"' is outside the folders a model may read (expected a file in " <<<"$out" && grep -qF -- "--allow-path DIR allows another folder" <<<"$out" || { echo "$out"; false; }'
model "$tmp/m/abs.yaml" "$tmp/outside/base.yaml"
out=$("$cs" check "$tmp/m/abs.yaml" 2>&1)
check "an absolute path outside: exit 2, at its place" '[ $? -eq 2 ] && grep -qF "$tmp/m/abs.yaml:2:17: barrier.file: '"'"'$tmp/outside/base.yaml'"'"' is outside the folders" <<<"$out"'
out=$("$cs" check "$tmp/m/rel.yaml" --allow-path "$tmp/outside" 2>&1)
check "--allow-path DIR: the same file is read" '[ $? -eq 0 ] && grep -qF "is a valid model (2 cables" <<<"$out" || { echo "$out"; false; }'
out=$("$cs" run "$tmp/m/rel.yaml" -o "$tmp/run" 2>&1)
check "run: refused, nothing written" '[ $? -eq 2 ] && grep -qF "is outside the folders" <<<"$out" && [ ! -e "$tmp/run" ]'
out=$("$cs" check "$tmp/m/rel.yaml" --allow-path "$tmp/nowhere" 2>&1)
check "--allow-path of no folder: exit 2, why" '[ $? -eq 2 ] && grep -qF -- "--allow-path $tmp/nowhere: No such file or directory" <<<"$out"'
model "$tmp/m/down.yaml" sub/base.yaml
check "a subfolder's file needs no leave" '"$cs" check "$tmp/m/down.yaml" >/dev/null 2>&1'
ln -s "$tmp/outside/base.yaml" "$tmp/m/sub/link.yaml"
model "$tmp/m/link.yaml" sub/link.yaml
out=$("$cs" check "$tmp/m/link.yaml" 2>&1)
check "a link inside to a file outside: refused" '[ $? -eq 2 ] && grep -qF "'"'"'sub/link.yaml'"'"' is outside the folders" <<<"$out"'

# a FIFO, as the model or as its file: refused without being opened (no writer ever comes, so an open
# would block for ever; `timeout 20` turns that into a failure)
mkfifo "$tmp/m/fifo.yaml"
out=$(timeout 20 "$cs" check "$tmp/m/fifo.yaml" 2>&1)
check "a FIFO as the model: exit 2, 'a FIFO, not a regular file'" '[ $? -eq 2 ] && grep -qF "$tmp/m/fifo.yaml: a FIFO, not a regular file" <<<"$out" || { echo "$out"; false; }'
model "$tmp/m/to-fifo.yaml" fifo.yaml
out=$(timeout 20 "$cs" check "$tmp/m/to-fifo.yaml" 2>&1)
check "a FIFO as a file: exit 2" '[ $? -eq 2 ] && grep -qF "fifo.yaml: a FIFO, not a regular file" <<<"$out" || { echo "$out"; false; }'
# a list of 100,000 items under a key that is not the model's, and a map of 20,000 keys with one given
# twice, are each refused at their place (the loader's work is linear in the model's size: counted by
# test_io_loader_work; timed by make bench)
{ cat examples/aps3.yaml; printf 'extra:\n'; seq 1 100000 | sed 's/^/  - /'; } >"$tmp/m/list.yaml"
out=$(timeout 20 "$cs" check "$tmp/m/list.yaml" --allow-path examples 2>&1)
check "a 100,000-item list: its key refused at its place" '[ $? -eq 2 ] && grep -q "list.yaml:[0-9]*:1: unknown key .extra." <<<"$out" || { echo "$out"; false; }'
{ cat examples/aps3.yaml; printf 'extra:\n'; seq 1 20000 | sed 's/^\(.*\)$/  k\1: 1/'; printf '  k7: 2\n'; } >"$tmp/m/map.yaml"
out=$(timeout 20 "$cs" check "$tmp/m/map.yaml" --allow-path examples 2>&1)
check "a map of 20,000 keys: refused at its place" '[ $? -eq 2 ] && grep -q "map.yaml:[0-9]*:1: unknown key .extra." <<<"$out" || { echo "$out"; false; }'
{ cat examples/aps3.yaml; printf 'description: one\ndescription: two\n'; } >"$tmp/m/twice.yaml"
out=$("$cs" check "$tmp/m/twice.yaml" --allow-path examples 2>&1)
check "a key given twice: the second named, with the first's place" '[ $? -eq 2 ] && grep -q "twice.yaml:[0-9]*:1: description: given twice (first at [0-9]*:1)" <<<"$out" || { echo "$out"; false; }'
out=$(timeout 20 "$cs" sweep "$tmp/m/fifo.yaml" -o "$tmp/fifo-sweep" 2>&1)
check "a FIFO as a sweep spec: exit 2, at once" '[ $? -eq 2 ] && grep -qF "a FIFO, not a regular file" <<<"$out" || { echo "$out"; false; }'

# larger than 64 MB (a sparse file): refused before it is read
truncate -s 65M "$tmp/m/big.yaml"
out=$(timeout 20 "$cs" check "$tmp/m/big.yaml" 2>&1)
check "a 65-MB model: exit 2, larger than 64 MB" '[ $? -eq 2 ] && grep -qF "68157440 bytes, larger than the 64 MB an input file may hold" <<<"$out" || { echo "$out"; false; }'

# a named file that is not a model: its place, not its text
printf 'user: alice\npassword: hunter2\n' >"$tmp/m/sub/secret.yaml"
model "$tmp/m/secret.yaml" sub/secret.yaml
out=$("$cs" check "$tmp/m/secret.yaml" 2>&1)
check "a file that is not a model: exit 2, its place, not its text" '[ $? -eq 2 ] && grep -qF "$tmp/m/secret.yaml:2:17: barrier.file: '"'"'sub/secret.yaml'"'"' is not a model file (at its line 1, column 1;" <<<"$out" && ! grep -qE "alice|hunter2|password" <<<"$out" || { echo "$out"; false; }'

# a study's model: outside the spec's folder is refused at its place; --allow-path allows it
printf 'model: ../outside/base.yaml\nmethod: grid\nvary: {scenario.speed: [30 mph, 40 mph]}\n' >"$tmp/m/spec.yaml"
out=$("$cs" check "$tmp/m/spec.yaml" 2>&1)
check "a study's model outside: exit 2, at 1:8" '[ $? -eq 2 ] && grep -qF "$tmp/m/spec.yaml:1:8: model: '"'"'$tmp/m/../outside/base.yaml'"'"' is outside the folders a study may read" <<<"$out" || { echo "$out"; false; }'
out=$("$cs" sweep "$tmp/m/spec.yaml" -o "$tmp/spec-out" 2>&1)
check "sweep: the same, nothing written" '[ $? -eq 2 ] && grep -qF "is outside the folders a study may read" <<<"$out" && [ ! -e "$tmp/spec-out" ]'
out=$("$cs" check "$tmp/m/spec.yaml" --allow-path "$tmp/outside" 2>&1)
check "check a study with --allow-path: valid" '[ $? -eq 0 ] && grep -qF "a valid sweep spec: grid of 2 runs" <<<"$out" || { echo "$out"; false; }'

# designer embeds only what the loader may read: the same refusal, nothing written
out=$("$cs" designer "$tmp/m/rel.yaml" -o "$tmp/designer" 2>&1)
check "designer: a file outside refused, nothing written" '[ $? -eq 2 ] && grep -qF "is outside the folders" <<<"$out" && [ ! -e "$tmp/designer" ]'

# every example loads as it is, with no leave
for f in examples/*.yaml examples/roadside/*.yaml; do
    check "$f loads with no --allow-path" '"$cs" check "$f" >/dev/null 2>&1 || "$cs" check "$f"'
done
finish
