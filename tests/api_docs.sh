#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The API reference (make docs): Doxygen over include/cablesim/ without a single warning, so every
# declaration of the public headers is documented, and the pages name the whole path a program takes.
# $1 is the build tree's Doxyfile. Skipped (77) without doxygen.
set -u
doxyfile=${1:?usage: bash tests/api_docs.sh BUILD/Doxyfile}
# A struct that grows, returned by value from the library, would be written at the library's size into
# the program's smaller one: the definitions' defaults are inline in the headers (def.h). Checked first,
# doxygen or not.
headers=$(cd "$(dirname "$0")/../include/cablesim" && pwd)
[ -s "$headers/def.h" ] || { echo "FAIL: no headers at $headers"; exit 1; }
if grep -nE "^CS_API (const )?cs_[a-z_]+_def cs_" "$headers"/*.h; then
    echo "FAIL: a library function returns a growing struct by value"
    exit 1
fi
command -v doxygen >/dev/null || { echo "SKIP: doxygen is not installed (bash scripts/install-deps.sh)"; exit 77; }
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi; }

{ cat "$doxyfile"; echo "OUTPUT_DIRECTORY = $tmp"; echo "WARN_AS_ERROR = FAIL_ON_WARNINGS"; } | doxygen - >"$tmp/log" 2>&1
check "doxygen ran without a warning" '[ $? -eq 0 ] && [ ! -s "$tmp/log" ] || { cat "$tmp/log"; false; }'
check "the first page is docs/library.md" 'grep -q "cablesim as a C library" "$tmp/html/index.html"'
check "the first page shows a study and a comparison" 'grep -q "cs_sweep_study" "$tmp/html/index.html" && grep -q "cs_compare_create" "$tmp/html/index.html"'
for h in cablesim export def sim loader output rating sweep compare; do
    check "a page for $h.h" '[ -s "$tmp/html/${h}_8h.html" ]'
done
for f in cs_loader_create cs_loader_set cs_loader_load cs_loader_build cs_state_create cs_run cs_state_summary \
    cs_record_create cs_record_vehicle cs_write_outputs cs_version cs_rate cs_state_energy cs_state_cable_summary \
    cs_state_sudden_losses cs_default_sweep_def cs_sweep_study cs_sweep_run_summary cs_default_compare_def \
    cs_compare_create cs_compare_get cs_compare_write; do
    check "$f has its documentation" 'grep -q "</span>$f()</h2>" "$tmp"/html/*_8h.html'
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
