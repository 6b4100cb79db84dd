#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A sweep needs cairo for its figures (always drawn) and netCDF for runs.nc (--netcdf, or `netcdf: true`);
# both are loaded by dlopen when first used (src/io/out/dynlib.h). On a machine without one of them the
# sweep refuses at once, before any run and before its folder is made, naming the library and what needs
# it; it once ran every run and failed only at the writing. CABLESIM_TEST_NO_LIB=WHAT makes the library
# WHAT fail to load as on such a machine (the sanitized build links both: the hook still holds).
source "$(dirname "$0")/lib.sh"
sweep=(sweep --allow-path examples tests/sweep/lhs.yaml --quiet)

out=$(CABLESIM_TEST_NO_LIB=netCDF "$cs" "${sweep[@]}" -o "$tmp/nc" --netcdf 2>&1)
check "--netcdf without netCDF: exit 1 at once, naming the library and runs.nc" '[ $? -eq 1 ] && grep -qF "cablesim sweep: nothing run: netCDF (" <<<"$out" && grep -qF "could not be loaded" <<<"$out" && grep -qF "runs.nc (--netcdf" <<<"$out" || { echo "$out"; false; }'
check "--netcdf without netCDF: no folder made, no run journalled" '[ ! -e "$tmp/nc" ]'

sed "s|^model: .*|model: $PWD/examples/aps3.yaml|; s|^seed: 7|&\nnetcdf: true|" tests/sweep/lhs.yaml >"$tmp/lhs-nc.yaml"
out=$(CABLESIM_TEST_NO_LIB=netCDF "$cs" sweep --allow-path examples "$tmp/lhs-nc.yaml" -o "$tmp/nc2" --quiet 2>&1)
check "netcdf: true in the spec without netCDF: refused the same" '[ $? -eq 1 ] && grep -qF "nothing run: netCDF (" <<<"$out" && [ ! -e "$tmp/nc2" ] || { echo "$out"; false; }'

out=$(CABLESIM_TEST_NO_LIB=netCDF "$cs" "${sweep[@]}" -o "$tmp/plain" 2>&1)
check "without --netcdf, netCDF is not needed: the sweep runs" '[ $? -eq 0 ] && [ -s "$tmp/plain/runs.csv" ] && [ ! -e "$tmp/plain/runs.nc" ] || { echo "$out"; false; }'

out=$(CABLESIM_TEST_NO_LIB=cairo "$cs" "${sweep[@]}" -o "$tmp/cairo" 2>&1)
check "without cairo: exit 1 at once, naming cairo and the study's figures" '[ $? -eq 1 ] && grep -qF "cablesim sweep: nothing run: cairo (" <<<"$out" && grep -qF "plots/study-*.png" <<<"$out" && [ ! -e "$tmp/cairo" ] || { echo "$out"; false; }'

# --resume checks them too: a study whose runs.csv could not be written keeps its runs' journal
CABLESIM_TEST_DEV_FULL=runs.csv "$cs" "${sweep[@]}" -o "$tmp/kept" >/dev/null 2>&1
out=$(CABLESIM_TEST_NO_LIB=cairo "$cs" sweep --resume "$tmp/kept" 2>&1)
check "--resume without cairo: refused at once, the journal kept" '[ $? -eq 1 ] && grep -qF "nothing run: cairo (" <<<"$out" && [ "$(ls -A "$tmp/kept")" = .cablesim-journal ] || { echo "$out"; ls -A "$tmp/kept"; false; }'
out=$("$cs" sweep --resume "$tmp/kept" 2>&1)
check "--resume with cairo: the study written" '[ $? -eq 0 ] && [ -s "$tmp/kept/runs.csv" ] || { echo "$out"; false; }'
finish
