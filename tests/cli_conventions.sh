#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The command line's conventions, for every subcommand: --help on stdout with exit 0; an unknown option
# named, with exit 2; an option without its value named; a file that cannot be opened given with the
# system's reason; an output folder that cannot be written refused before anything runs (a folder under a
# regular file: ENOTDIR even for root), leaving nothing behind. And every source file git tracks (C,
# headers, shell, CMake, JavaScript, Python) names its licence, the LICENSE's MIT, by its SPDX identifier.
# And the quick start's promises: README.md at most 150 lines; `make demo` builds the command alone (no
# test) and installs, on a machine that lacks every package, none of emscripten, chromium or the test
# toolchain (scripts/install-deps.sh --demo, with dpkg and apt-get stood in for).
source "$(dirname "$0")/lib.sh"

top=$("$cs" --help)
check "cablesim --help" 'grep -q "^Usage: cablesim run FILE" <<<"$top"'
check "one spelling: Usage: and   or:  (GNU's, as help2man reads them), never usage:" '( for s in "" run check sweep rate validate compare designer list schema; do h=$("$cs" $s --help); head -1 <<<"$h" | grep -q "^Usage: cablesim ${s:-run}" && ! sed 1d <<<"$h" | grep -qiE "^ *usage:" || exit 1; done ) && "$cs" --help | grep -q "^  or:  cablesim check"'
check "the top level gives validate's own exit status and a signal's" 'grep -qF "validate: 3 its targets missed; 128 + the signal" <<<"$top"'
check "no test-only environment variable in any help" '! { "$cs" --help; for s in run check sweep rate validate compare designer list schema; do "$cs" "$s" --help; done; } | grep -q "STOP_AFTER"'
for sub in run check sweep rate validate compare list schema designer; do
    out=$("$cs" "$sub" --help 2>&1)
    check "$sub --help: exit 0" '[ $? -eq 0 ]'
    check "$sub --help: its usage" 'grep -q "^Usage: cablesim $sub" <<<"$out"'
    check "$sub --help: its exit status" 'grep -q "^Exit status: 0 " <<<"$out"'
    out=$("$cs" "$sub" examples/aps3.yaml --foo 2>&1)
    check "$sub --foo: exit 2, the option named" '[ $? -eq 2 ] && grep -qxF "cablesim $sub: unknown option '"'"'--foo'"'"'" <<<"$out"'
    check "$sub --foo: the usage lines and a pointer to --help, not the whole help" '[ "$(grep -cv "^Usage: \|^  or:  \|^       \|^cablesim $sub: unknown option" <<<"$out")" -eq 1 ] && grep -qxF "(cablesim $sub --help: what it does and its options)" <<<"$out"'
    out=$("$cs" "$sub" --bar=1 2>&1)
    check "$sub --bar=1: the option named without its value" '[ $? -eq 2 ] && grep -qF "unknown option '"'"'--bar'"'"'" <<<"$out"'
done
# the bash completion offers the options of each command's usage and option lines (and --help, and --out
# beside -o), and no other
completion() { bash -c 'source app/cablesim.bash; COMP_WORDS=(cablesim "$1" -); COMP_CWORD=2; _cablesim; printf "%s\n" "${COMPREPLY[@]}"' _ "$1" | grep -vxE -- "--help|--out" | sort; }
for sub in run check sweep rate validate compare designer list schema; do
    help_opts=$("$cs" "$sub" --help | grep -E "^(Usage: |  or:  |       |  -)" | grep -oE -- "(^|[ [|,])--?[a-z][a-z-]*" | grep -oE -- "--?[a-z][a-z-]*" | grep -vxE -- "--help|--out" | sort -u)
    check "completion of $sub: the options of its --help" '[ "$(completion "$sub")" = "$help_opts" ] || { diff <(completion "$sub") <(echo "$help_opts"); false; }'
done
out=$("$cs" frobnicate 2>&1)
check "an unknown command named in one line, exit 2" '[ $? -eq 2 ] && [ "$out" = "cablesim: unknown command '"'"'frobnicate'"'"' (cablesim --help: the commands)" ]'
out=$("$cs" compare 2>&1)
check "compare without a run: exit 2, named" '[ $? -eq 2 ] && grep -qxF "cablesim compare: no run to compare" <<<"$out"'
out=$("$cs" compare "$tmp" -o 2>&1)
check "compare -o without its value: named, exit 2" '[ $? -eq 2 ] && grep -qF "option '"'"'-o'"'"' needs a value" <<<"$out"'
out=$("$cs" sweep tests/sweep/lhs.yaml -o "$tmp/quiet" --threads 1 --runs 2 --quiet --allow-path examples 2>&1)
check "sweep --quiet: exit 0, nothing printed" '[ $? -eq 0 ] && [ -z "$out" ] && [ -s "$tmp/quiet/runs.csv" ]'
for sub in run check rate sweep; do
    out=$("$cs" "$sub" examples/aps3.yaml --set 2>&1)
    check "$sub --set without its value: named, exit 2" '[ $? -eq 2 ] && grep -qF "option '"'"'--set'"'"' needs a value" <<<"$out"'
done
out=$("$cs" list extra 2>&1)
check "list takes no argument" '[ $? -eq 2 ] && grep -qF "takes no argument" <<<"$out"'
out=$("$cs" run examples/aps3.yaml examples/aps1.yaml 2>&1)
check "two model files: exit 2, both named" '[ $? -eq 2 ] && grep -qF "more than one model file ('"'"'examples/aps3.yaml'"'"' and '"'"'examples/aps1.yaml'"'"')" <<<"$out"'
out=$("$cs" run examples/aps3.yaml -o "$tmp/o1" --t-end "5 ms" --plots 2>&1)
check "options after the file, and before it" '[ $? -eq 0 ] && "$cs" run --t-end "5 ms" -o "$tmp/o2" examples/aps3.yaml >/dev/null 2>&1'

# files it cannot open: the system's reason
out=$("$cs" run "$tmp/nowhere.yaml" 2>&1)
check "run: a missing file, its reason" '[ $? -eq 2 ] && grep -qF "$tmp/nowhere.yaml: cannot open the file: No such file or directory" <<<"$out"'
out=$("$cs" check "$tmp" 2>&1)
check "check: a folder, its reason" '[ $? -eq 2 ] && grep -qF "$tmp: cannot open the file: Is a directory" <<<"$out"'
out=$("$cs" rate "$tmp/nowhere.yaml" --standard astm-f2656 2>&1)
check "rate: a missing file, its reason" '[ $? -eq 2 ] && grep -qF "No such file or directory" <<<"$out"'
out=$("$cs" sweep "$tmp/nowhere.yaml" 2>&1)
check "sweep: a missing spec, its reason" '[ $? -eq 2 ] && grep -qF "$tmp/nowhere.yaml: cannot open the file: No such file or directory" <<<"$out"'
out=$("$cs" designer "$tmp/nowhere.yaml" 2>&1)
check "designer: a missing file, its reason" '[ $? -eq 2 ] && grep -qF "$tmp/nowhere.yaml: cannot open the file: No such file or directory" <<<"$out"'
out=$("$cs" designer examples/aps3.yaml examples/aps1.yaml 2>&1)
check "designer: two model files, exit 2" '[ $? -eq 2 ] && grep -qF "more than one model file" <<<"$out"'
out=$("$cs" sweep --resume "$tmp/nothing" 2>&1)
check "sweep --resume: a folder with no sweep, its reason" '[ $? -eq 2 ] && grep -qF "$tmp/nothing/summary.json: No such file or directory" <<<"$out"'

# an output folder it cannot write: refused before anything runs, nothing left
echo "a file" >"$tmp/file"
out=$("$cs" run examples/aps3.yaml -o "$tmp/file/sub" 2>&1)
check "run -o FILE/sub: exit 1, why, before the run" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing run: $tmp/file/sub: Not a directory" <<<"$out"'
out=$("$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/file/sub" 2>&1)
check "sweep -o FILE/sub: exit 1, why, before any run" '[ $? -eq 1 ] && grep -qxF "cablesim sweep: nothing run: $tmp/file/sub: Not a directory" <<<"$out" && ! grep -q "^sweep: [0-9]* runs" <<<"$out"'
out=$("$cs" validate --only verification -o "$tmp/file/sub" 2>&1)
check "validate -o FILE/sub: exit 1, why, before any run" '[ $? -eq 1 ] && grep -qxF "cablesim validate: nothing run: $tmp/file/sub: Not a directory" <<<"$out"'
out=$("$cs" designer examples/aps3.yaml -o "$tmp/file/sub" 2>&1)
check "designer -o FILE/sub: exit 1, nothing written" '[ $? -eq 1 ] && grep -qF "cablesim designer: nothing written: " <<<"$out"'
check "the file is as it was" '[ "$(cat "$tmp/file")" = "a file" ]'
# the folders made for a run that then cannot write its files (a 1-KiB file size limit) are removed again;
# those of a run that can are kept
mkdir -p "$tmp/made"
out=$(trap "" XFSZ; ulimit -f 1; "$cs" run examples/aps3.yaml -o "$tmp/made/a/b" --t-end "5 ms" 2>&1)
check "a run that cannot write: exit 1, why, its new folders gone" '[ $? -eq 1 ] && grep -qxF "cablesim: nothing written: $tmp/made/a/b/timeseries.csv: File too large" <<<"$out" && [ -z "$(ls -A "$tmp/made")" ]'
out=$("$cs" run examples/aps3.yaml -o "$tmp/made/a/b" --t-end "5 ms" 2>&1)
check "a run into new folders keeps them" '[ $? -eq 0 ] && [ -s "$tmp/made/a/b/summary.json" ]'
# every source file git tracks names its licence, the LICENSE's, by its SPDX identifier in its first lines
# (a check of the source tree, which runs no program: left to the plain suite under the sanitizers)
if git rev-parse --is-inside-work-tree >/dev/null 2>&1 && plain_only "the source files' SPDX lines"; then
    unmarked=$(git ls-files -- '*.c' '*.h' '*.sh' '*.bash' '*.js' '*.mjs' '*.py' '*.cmake' '*.cmake.in' '*.pc.in' \
        CMakeLists.txt '*/CMakeLists.txt' ':!:tests/good' ':!:tests/bad' ':!:tests/fuzz-regressions' ':!:.ci' |
        while IFS= read -r f; do head -3 "$f" | grep -q "SPDX-License-Identifier: MIT" || echo "$f"; done)
    check "the LICENSE is MIT's" 'head -1 LICENSE | grep -qx "MIT License"'
    check "every tracked source file has SPDX-License-Identifier: MIT" '[ -z "$unmarked" ] || { echo "$unmarked" | head; false; }'
fi
check "README.md is at most 150 lines" '[ "$(wc -l <README.md)" -le 150 ]'
demo=$(make -n demo BUILD="$tmp/demo-build" 2>&1)
check "make demo builds the command's target alone, no test" '[ "$(grep -c "cmake --build" <<<"$demo")" -eq 1 ] && grep -q "cmake --build .* --target cablesim_cmd$" <<<"$demo" || { echo "$demo"; false; }'
mkdir -p "$tmp/stub"
printf '#!/bin/sh
exit 1
' >"$tmp/stub/dpkg"                       # every package missing
printf '#!/bin/sh
echo "apt-get $*"
' >"$tmp/stub/apt-get"          # what it would install
printf '#!/bin/sh
"$@"
' >"$tmp/stub/sudo"
chmod +x "$tmp/stub/dpkg" "$tmp/stub/apt-get" "$tmp/stub/sudo"
asked=$(PATH="$tmp/stub:$PATH" bash scripts/install-deps.sh --demo 2>&1)
check "install-deps.sh --demo installs the command's libraries" 'grep -q "^apt-get install .* libyaml-dev .*libudunits2-dev" <<<"$asked" || { echo "$asked"; false; }'
check "install-deps.sh --demo installs no emscripten, chromium, cmocka, clang or MPI" '! grep -qwE "emscripten|chromium|libcmocka-dev|clang|libopenmpi-dev" <<<"$asked"'
asked=$(PATH="$tmp/stub:$PATH" bash scripts/install-deps.sh 2>&1)
check "install-deps.sh without --demo installs them (the stand-ins see the whole list)" 'grep -qw emscripten <<<"$asked" && grep -qw chromium <<<"$asked"'
finish
