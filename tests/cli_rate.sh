#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cablesim rate: the standard's test condition against a model's barrier, with the model's own vehicle
# (every class ASTM F2656 tests: a PU model, --set vehicle=C); a vehicle the standard does not test, or a
# --class of another vehicle, refused with exit 2; `run` and `rate` in the same words (the
# designation as run; `rate` concludes the rating); usage errors exit 2.
source "$(dirname "$0")/lib.sh"
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M30 --set 'scenario.t_end=0.05 s' 2>&1)
rc=$?
check "rate runs (exit 0)" '[ $rc -eq 0 ]'
check "one trial row for M30" '[ "$(grep -c "^  M    30 mph" <<<"$out")" -eq 1 ]'
check "a run cut at 50 ms is not rated, and says why" 'grep -qxF "rating: ASTM F2656 not rated (the run ended at its time limit with the vehicle still moving)" <<<"$out"'
"$cs" rate examples/aps3.yaml --standard pas-68 >/dev/null 2>&1
check "unknown standard exits 2" '[ $? -eq 2 ]'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M45 2>&1)
check "unknown class exits 2, naming the classes" '[ $? -eq 2 ] && grep -q "^cablesim rate: --class M45: ASTM F2656 has no such class (expected one of C40, C50, C60, PU40, PU50, PU60, M30, M40, M50, H30, H40, H50)" <<<"$out"'
"$cs" rate --standard astm-f2656 >/dev/null 2>&1
check "no model file exits 2" '[ $? -eq 2 ]'
# what the standard's tests set themselves cannot be --set: refused rather than dropped; an option twice too
out=$("$cs" rate examples/aps3.yaml --standard mash --test 3-11 --set 'scenario.speed=10 mph' 2>&1)
check "--set scenario.speed with mash: refused, saying the tests set it" '[ $? -eq 2 ] && grep -qF -- "cablesim rate: --set scenario.speed=10 mph: the standard'"'"'s tests set the impact speed, so it would not be used" <<<"$out"'
out=$("$cs" rate examples/roadside/rs1.yaml --standard mash --test 3-11 --set 'vehicle.mass=2100 kg' 2>&1)
check "--set vehicle.mass with mash: refused (the tests run their own vehicles)" '[ $? -eq 2 ] && grep -qF "the standard'"'"'s tests run their own vehicles" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --set 'scenario.angle=60 deg' 2>&1)
check "--set scenario.angle with astm-f2656: refused (head-on)" '[ $? -eq 2 ] && grep -qF "the standard'"'"'s tests set the impact angle" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --standard mash 2>&1)
check "--standard twice: refused" '[ $? -eq 2 ] && grep -qxF "cablesim rate: --standard given twice (expected it once)" <<<"$out"'

# A model whose vehicle is the library's PU (the rest APS3's): PU40 runs it at 40 mph, and it stops 1.79 m
# past the cable line, 1.69 m past the protected face (P2 is 1.01-7 m: the label holds for any penetration
# within 0.6 m of it).
cp examples/aps3.yaml "$tmp/aps3.yaml" # beside the model: its files may not leave its folder
printf 'name: aps3-pu\nbarrier: {file: aps3.yaml}\nvehicle: PU\nscenario: {file: aps3.yaml}\n' >"$tmp/pu.yaml"
out=$("$cs" rate "$tmp/pu.yaml" --standard astm-f2656 --class PU40 2>&1)
check "rate --class PU40 on a PU model (exit 0)" '[ $? -eq 0 ] || { echo "$out"; false; }'
check "PU40: the model's PU at 40 mph, stopped, P2" 'grep -qE "^  PU   40 mph  stopped +penetration [0-9.]+ m .* designation as run PU40/P2$" <<<"$out" && grep -qE "^rating: ASTM F2656 PU40/P2 \(penetration [0-9.]+ m \([0-9.]+ ft\), vehicle front, from the barrier.s protected-side face\)$" <<<"$out"'
check "PU40: its own vehicle named" 'grep -q "(test vehicle PU, the model.s 2300 kg;" <<<"$out"'
check "PU40: the penetration as ASTM F2656 measures a PU's" 'grep -qxF "  penetration as the standard measures it: vehicle front, from the barrier'"'"'s protected-side face" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M40 2>&1)
check "M40: the penetration from the M's cargo bed, named" 'grep -qxF "  penetration as the standard measures it: front of the cargo bed, from the barrier'"'"'s protected-side face" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard sd-std-02.01 --class K8 2>&1)
check "K8: the penetration from the attack face, named" 'grep -qxF "  penetration as the standard measures it: vehicle front, from the attack face to where it stopped" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --set vehicle=C --class C50 --set 'scenario.t_end=0.05 s' 2>&1)
check "--set vehicle=C is honoured: the C runs" '[ $? -eq 0 ] && grep -q "(test vehicle C, the model.s 1102 kg;" <<<"$out" && grep -q "^  C    50 mph " <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class PU50 2>&1)
check "--class PU50 of a model with the M truck: exit 2, the fix named" '[ $? -eq 2 ] && grep -q "class PU50 is for the PU vehicle (2300 kg), but the model.s vehicle is M (6804 kg): give --set vehicle=PU" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard sd-std-02.01 --set vehicle=C 2>&1)
check "SD-STD with a car: exit 2, not its test vehicle" '[ $? -eq 2 ] && grep -q "the model.s vehicle (1102 kg) is not a test vehicle of SD-STD-02.01" <<<"$out"'
out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --set vehicle=2000P 2>&1)
check "ASTM with NCHRP 350's 2000P: exit 2, not its test vehicle" '[ $? -eq 2 ] && grep -q "the model.s vehicle (2000 kg) is not a test vehicle of ASTM F2656 (C 1,100 kg, PU 2,300 kg, M 6,800 kg or H 29,500 kg" <<<"$out"'

# run and rate give a run's designation as run in the same words: APS3's truck at its 40 mph gets through
# where the ropes' end fittings hold a quarter of their strength; rate's conclusion is its "rating"
weak=(--set "barrier.cables[0].termination_efficiency=0.25" --set "barrier.cables[1].termination_efficiency=0.25")
run_out=$("$cs" run examples/aps3.yaml -o "$tmp/run" "${weak[@]}" 2>&1)
rate_out=$("$cs" rate examples/aps3.yaml --standard astm-f2656 --class M40 "${weak[@]}" 2>&1)
check "run: the designation as run" 'grep -qxF "  designation (as run) ASTM F2656 M40/P4 (the vehicle got through)" <<<"$run_out"'
check "run: SD-STD-02.01 too, for its truck" 'grep -qxF "                       SD-STD-02.01 none (the vehicle got through; L1 needs it stopped within 15 m)" <<<"$run_out"'
check "rate --class M40: the same designation as run, and the rating it concludes" 'grep -qE "^  M    40 mph  breakthrough +penetration through the barrier +designation as run M40/P4$" <<<"$rate_out" && grep -qxF "rating: ASTM F2656 M40/P4 (the vehicle got through)" <<<"$rate_out"'
check "summary.json: the same words" 'grep -qF "\"label\":\"M40/P4\",\"text\":\"ASTM F2656 M40/P4 (the vehicle got through)\"" "$tmp/run/summary.json"'
out=$("$cs" run examples/roadside/design.yaml -o "$tmp/design" --t-end "20 ms" 2>&1)
check "run of MASH 2270P (within 5% of the PU) at 25 deg: not rated, and why" 'grep -qxF "  designation (as run) ASTM F2656 not rated (the impact is at 25.0 deg; its test is head-on, at 90 deg)" <<<"$out"'
# Roadside test conditions: the tests of a level, or one; each a row with its deflection and working width.
out=$("$cs" rate examples/roadside/rs1.yaml --standard mash --set 'scenario.t_end=0.3 s' 2>&1)
check "mash TL-3 runs 3-10 and 3-11 (exit 0)" '[ $? -eq 0 ] && [ "$(grep -cE "^  3-1[01] +(1100C|2270P) +100 km/h 25 deg .* deflection [0-9.]+ m .* working width [0-9.]+ m" <<<"$out")" -eq 2 ]'
out=$("$cs" rate examples/roadside/rs1.yaml --standard nchrp-350 --test 3-11 --set 'scenario.t_end=0.3 s' 2>&1)
check "nchrp-350 3-11 alone with the 2000P" '[ "$(grep -cE "^  3-11 2000P +100 km/h 25 deg" <<<"$out")" -eq 1 ]'
# the criteria of NCHRP 350's 3-11, in order, each with a verdict; a run stopped by its time limit (0.3 s,
# mid-collision) has A not judged, and F and L, within their limits so far, not judged either (what comes
# after its end is not known); D and K are never passed
check "nchrp-350 3-11 lists A D F L K M with verdicts" '[ "$(grep -oE "^       [A-Z] +(pass|FAIL|not judged) " <<<"$out" | awk "{print \$1}" | tr -d "\n")" = "ADFLKM" ]'
check "a run at its time limit: A not judged" 'grep -qE "^       A +not judged .*time_limit" <<<"$out"'
check "a run at its time limit: its level's line says it ended mid-collision, not that the vehicle got through" 'grep -qxF "3-11: not known to be contained in every test (a run ended mid-collision: time_limit)" <<<"$out"'
check "D and K listed as not judged, no pass implied" 'grep -qE "^3-11: not judged \(the model cannot tell; no pass implied\): A, D, F, L, K, M$" <<<"$out"'
check "a run at its time limit: F and L within their limits so far, not judged" 'grep -qE "^       F +not judged .*over the run, which ended before the collision did" <<<"$out" && grep -qE "^       L +not judged .*\(a lower bound: the run ended, time_limit, before the collision did\)$" <<<"$out"'
out=$("$cs" rate examples/roadside/rs1.yaml --standard mash --test 3-11 2>&1)
check "mash 3-11 to its end: occupant risk and the exit box judged" 'grep -qE "^       occupant risk \(CG, CFC 180\): OIV [0-9.]+ / [0-9.]+ m/s" <<<"$out" && grep -qE "^       exit box +(pass|FAIL) .* \\(box 10.0 m\\)" <<<"$out" && grep -qE "^       H +(pass|FAIL) " <<<"$out"'
# The MASH design example is test 3-11 as its model runs it: run and rate give its occupant impact at the
# same time from the same point (after the first contact), where rate's criteria give times of the run
out=$("$cs" rate examples/roadside/design.yaml --standard mash --test 3-11 2>&1)
run_out=$("$cs" run examples/roadside/design.yaml -o "$tmp/design-3-11" 2>&1)
at=$(grep -oE "^  occupant impact +[0-9.]+ s after first contact" <<<"$run_out" | grep -oE "[0-9.]+ s after first contact")
check "design under mash 3-11: the occupant impact's time and its reference as run gives them" '[ -n "$at" ] && grep -qE "^       occupant risk \(CG, CFC 180\): OIV [0-9.]+ / [0-9.]+ m/s at $at, ORA " <<<"$out" || { echo "$at"; grep "occupant risk" <<<"$out"; false; }'
# The issue's two cases to their ends: RS1 under NCHRP 350 (3-10: A D F H I K M; 3-11: A D F L K M) and the
# MASH design example under MASH (each test A D F H I and the exit box), a verdict for every criterion
criteria() {
    awk -v t="$2" '/^  [0-9]-1[0-2] / {on = $1 == t} /^[^ ]/ {on = 0}
        on && /^       / && ($2 ~ /^(pass|FAIL|not)$/ || ($1 == "exit" && $3 ~ /^(pass|FAIL|not)$/)) {printf "%s ", $1 == "exit" ? "box" : $1}' <<<"$1"
}
out=$("$cs" rate examples/roadside/rs1.yaml --standard nchrp-350 2>&1)
check "RS1 under nchrp-350: 3-10's criteria, each with a verdict" '[ "$(criteria "$out" 3-10)" = "A D F H I K M " ]'
check "RS1 under nchrp-350: 3-11's criteria, each with a verdict" '[ "$(criteria "$out" 3-11)" = "A D F L K M " ]'
check "RS1 under nchrp-350: the level's last lines" 'grep -qxE "TL-3: not judged \(the model cannot tell; no pass implied\): D, K" <<<"$out"'
out=$("$cs" rate examples/roadside/design.yaml --standard mash 2>&1)
for t in 3-10 3-11; do
    check "the design under mash: $t's criteria, each with a verdict" '[ "$(criteria "$out" $t)" = "A D F H I box " ]'
done
check "the design under mash: D not judged, never passed" 'grep -qxE "TL-3: not judged \(the model cannot tell; no pass implied\): D" <<<"$out"'
"$cs" rate examples/roadside/rs1.yaml --standard mash --test 5-12 >/dev/null 2>&1
check "unknown roadside test exits 2" '[ $? -eq 2 ]'
"$cs" rate examples/roadside/rs1.yaml --standard mash --class M30 >/dev/null 2>&1
check "an anti-ram class with a roadside standard exits 2" '[ $? -eq 2 ]'
finish
