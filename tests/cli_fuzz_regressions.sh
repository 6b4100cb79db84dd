#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every input on which the loader's fuzzer once found a bug (tests/fuzz-regressions/) is now handled:
# `cablesim check` exits 0 (a valid model) or 2 (a bad one), never crashes, and no sanitizer reports (in the
# sanitizer build). A file's "#set PATH=VALUE" lines are passed as --set, as fuzz/fuzz_loader.c queues them.
set -u
cs=${1:?usage: bash tests/cli_fuzz_regressions.sh path/to/cablesim}
# udunits2 leaks a few bytes on some bad units (fuzz/lsan.supp): not this program's leak
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp}
pass=0
fail=0
shopt -s nullglob
for f in tests/fuzz-regressions/*.yaml; do
    args=()
    while IFS= read -r s; do
        args+=(--set "$s")
    done < <(sed -n 's/^#set \(.\)/\1/p' "$f")
    out=$("$cs" check "$f" "${args[@]}" 2>&1)
    rc=$?
    if { [ "$rc" -eq 0 ] || [ "$rc" -eq 2 ]; } && ! grep -qE 'runtime error|Sanitizer' <<<"$out"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL $f: exit status $rc (expected 0 or 2)"
        echo "$out" | tail -20
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
