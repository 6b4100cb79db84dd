#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every model in tests/bad/ is refused by `cablesim check` with exit status 2, and the problems it reports
# are exactly those its "# expect: LINE:COL: text" lines name, at those places.
# Files of tests/good may be named (--allow-path tests/good); no other folder beyond tests/bad.
source "$(dirname "$0")/lib.sh"
files=0
for f in tests/bad/*.yaml; do
    files=$((files + 1))
    out=$("$cs" check --allow-path tests/good "$f" 2>&1)
    expect_problems "$f" "$out" $?
done
check "at least 25 bad files ($files)" '[ "$files" -ge 25 ]'
# a --set the engine refuses for an element that takes it from the soil is blamed on that --set
out=$("$cs" check tests/good/base.yaml --set "barrier.soil.dynamic_factor=20" 2>&1)
check "--set barrier.soil.dynamic_factor=20: blamed on the --set, not on a file's line" '[ $? -eq 2 ] && grep -qF -- "--set barrier.soil.dynamic_factor=20: post 0: soil dynamic factor 20 must be in [1, 10]" <<<"$out" && ! grep -q "^tests/good/base.yaml:" <<<"$out" || { echo "$out"; false; }'
# a check of a cable's height against a post's is blamed on the --set of the post's, not on the cable's line
out=$("$cs" check tests/good/base.yaml --set "barrier.posts[0].height=3 ft" 2>&1)
check "--set barrier.posts[0].height=3 ft: the cable above the post blamed on the --set" '[ $? -eq 2 ] && grep -qxF -- "--set barrier.posts[0].height=3 ft: the cable (1.2192 m) is above the top of the post at x = 2.4384 m (0.9144 m) (expected a height up to the posts'"'"' tops)" <<<"$out" && ! grep -q "^tests/good/base.yaml:" <<<"$out" || { echo "$out"; false; }'
# values of 1e30 by --set, as fuzz/fuzz_set.sh gives them: refused at once, at the --set, with the range
# in the unit given and why (tests/bad/rail_ranges.yaml holds them in a file)
for set in "barrier.rails[0].modulus=1e30 Pa|'1e30 Pa' is too large for modulus (expected 1 Pa to 2e+12 Pa: " \
    "barrier.rails[0].mass_per_length=1e30 kg/m|'1e30 kg/m' is too large for mass_per_length (expected 0 or 0.001 kg/m to 1e+04 kg/m: " \
    "barrier.posts[0].height=1e30 ft|'1e30 ft' is too large for height (expected 0.0003281 ft to 3.281e+04 ft: "; do
    out=$(timeout 20 "$cs" check examples/aps3.yaml --set "${set%%|*}" 2>&1)
    check "--set ${set%%|*}: refused at the --set, with the range and why" '[ $? -eq 2 ] && grep -qF -- "--set ${set%%|*}: ${set#*|}" <<<"$out" && [ "$(grep -c "^--set " <<<"$out")" -eq 1 ] || { echo "$out"; false; }'
done
finish
