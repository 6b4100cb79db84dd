#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The command end to end: help, version, list, check, a short run of examples/aps3.yaml and its outputs,
# --set on the command line, that a refused model writes nothing, and that a run repeats byte for byte.
source "$(dirname "$0")/lib.sh"

check "--help" '"$cs" --help | grep -q "^Usage: cablesim run FILE"'
check "--version" '"$cs" --version | grep -q "^cablesim [0-9]"'
"$cs" frobnicate >/dev/null 2>&1
check "unknown command is status 2" '[ $? -eq 2 ]'
"$cs" run >/dev/null 2>&1
check "run without a file is status 2" '[ $? -eq 2 ]'
check "list exits 0 and names the parts" \
    '"$cs" list >"$tmp/list" && grep -q "^  M " "$tmp/list" && grep -q "A603-1.75in" "$tmp/list" && grep -q "HSS4x4x1/8" "$tmp/list"'
check "list names its folder: the source tree's data/ for a program of the build tree" \
    '"$cs" list | head -1 | grep -qx "Parts library: $PWD/data"'
mkdir "$tmp/parts" && cp data/*.yaml "$tmp/parts/" && sed -i 's/^    - name: H$/    - name: H-renamed/' "$tmp/parts/vehicles.yaml"
check "CABLESIM_DATA moves the parts library" \
    'CABLESIM_DATA="$tmp/parts" "$cs" list | grep -q "^  H-renamed " && CABLESIM_DATA="$tmp/parts" "$cs" list | head -1 | grep -qx "Parts library: $tmp/parts"'
CABLESIM_DATA="$tmp/none" "$cs" list >/dev/null 2>"$tmp/stderr"
check "a CABLESIM_DATA that is no folder: status 2, named" '[ $? -eq 2 ] && grep -q "^$tmp/none: cannot read the parts library (CABLESIM_DATA; " "$tmp/stderr"'
for f in examples/*.yaml; do
    check "check $f" '"$cs" check "$f" >/dev/null'
done
check "check --set" '"$cs" check examples/aps3.yaml --set scenario.speed="35 mph" --set "barrier.cables[0].pretension=8 kip" >/dev/null'
# A shallow angle: at 3 deg the face's centre at APS3's impact point puts its leading corner on the cable
# line 22.93 m (1.2 m / sin 3 deg) before it, outside the barrier: refused, not run as a ride over ropes it
# never met; with impact_at: corner the corner strikes there and the ropes take the vehicle (a glancing
# contact: the face pushes the line out and the ropes do work on it).
"$cs" run examples/aps3.yaml -o "$tmp/shallow" --set "scenario.angle=3 deg" >/dev/null 2>"$tmp/stderr"
check "a vehicle that would pass the barrier's end is refused (status 2), where and why" \
    '[ $? -eq 2 ] && grep -q "at 3 deg the leading front corner of the vehicle.s 2.40-m face meets the cable line at x = -2.20 m" "$tmp/stderr" && [ ! -e "$tmp/shallow" ]'
"$cs" run examples/aps3.yaml -o "$tmp/shallow" --t-end "0.3 s" --set "scenario.angle=3 deg" --set scenario.impact_at=corner >"$tmp/stdout" 2>&1
check "at 3 deg to the corner the ropes take the vehicle" \
    'grep -oE "\"max_barrier_deflection_m\":[0-9.]+" "$tmp/shallow/summary.json" | awk -F: "{ exit !(\$2 > 0.1) }"'
# At 1 deg and at 179 deg (the same approach from the other side) the corner glances along the line: each
# run gives what happened (the ropes pushed out, the vehicle still going at 0.3 s: time_limit), and the two,
# mirror images, agree within 2% in the barrier's deflection.
for a in 1 179; do
    "$cs" run examples/aps3.yaml -o "$tmp/glance$a" --t-end "0.3 s" --set "scenario.angle=$a deg" \
        --set scenario.impact_at=corner >/dev/null 2>&1
done
defl() { grep -oE '"max_barrier_deflection_m":[0-9.e-]+' "$tmp/glance$1/summary.json" | cut -d: -f2; }
check "at 1 and 179 deg the ropes are pushed out and the vehicle goes on (time_limit)" \
    '[ "$(cat "$tmp"/glance{1,179}/summary.json | grep -c "\"outcome\":\"time_limit\"")" -eq 2 ] && awk -v d="$(defl 1)" "BEGIN { exit !(d > 0.01) }"'
check "at 1 and 179 deg the deflections agree within 2% (mirror images)" \
    'awk -v a="$(defl 1)" -v b="$(defl 179)" "BEGIN { exit !(a > 0 && (a - b) ^ 2 <= (0.02 * a) ^ 2) }"'

out="$tmp/aps3"
"$cs" run examples/aps3.yaml -o "$out" --t-end "20 ms" --set scenario.speed="35 mph" >"$tmp/stdout" 2>"$tmp/stderr"
check "run exits 0" '[ $? -eq 0 ] || { cat "$tmp/stderr"; false; }'
check "run prints a summary in SI and US units" 'grep -q "mph" "$tmp/stdout" && grep -q "kip" "$tmp/stdout" && grep -q " ft)" "$tmp/stdout"'
for f in timeseries.csv events.csv summary.json; do
    check "$f written" '[ -s "$out/$f" ]'
done
check "no temporaries left" '[ -z "$(ls "$out" | grep "\.tmp$")" ]'
check "timeseries header has units" 'head -1 "$out/timeseries.csv" | grep -q "^t \[s\],x \[m\],y \[m\],z \[m\],vx \[m/s\],.*decel_50ms \[g\].*cable0_max_tension \[N\],cable0_state.*post0_state.*energy_balance_error \[1\]$"'
check "every header cell of timeseries.csv and events.csv is \"name [unit]\" or a name alone (no unit suffix)" \
    'cells=$(head -qn1 "$out/timeseries.csv" "$out/events.csv" | tr , "\n"); [ "$(wc -l <<<"$cells")" -gt 20 ] && ! grep -vqE "^[a-z0-9_]+( \[[^]]+\])?\$" <<<"$cells" && ! grep -qE "_(s|m|n|j|g|rad|mps|mps2|si)\$" <<<"$cells"'
check "timeseries has rows" '[ "$(wc -l <"$out/timeseries.csv")" -gt 10 ]'
check "events header" 'head -1 "$out/events.csv" | grep -q "^t \[s\],type,element_kind,element,value,value_unit,cable_end,cable,post$"'
# APS3's first events: its middle posts hinge at their plastic moment, Zx Fy = 7,270.57 N m; every
# event's value has its unit, and none but a termination event has a cable end
check "a hinge's moment in N m" 'grep -qE "^[0-9.]+,post_hinge,post,[0-9]+,7270\.57[0-9]*,N m,,,$" "$out/events.csv"'
check "every event has a unit" 'awk -F, "NR > 1 && \$6 == \"\" { bad = 1 } END { exit bad }" "$out/events.csv"'
check "no cable end but a termination event's" 'awk -F, "NR > 1 && \$2 !~ /^termination_/ && \$7 != \"\" { bad = 1 } END { exit bad }" "$out/events.csv"'

# A rope end of its own: cable 0's fitting at the end anchor at 0.2 Fu (81.3 kN of the 1-in rope's
# 406.6 kN) lets go there, first, in events.csv, summary.json and the terminal; the start's holds.
"$cs" run tests/good/base.yaml -o "$tmp/end" --t-end "30 ms" --set "barrier.cables[0].end.termination_efficiency=0.2" >"$tmp/end.out" 2>&1
e="$tmp/end/events.csv"
check "an end's fitting: events.csv gives the end and its span's tension" '[ "$(grep -c termination_break "$e")" -eq 1 ] && awk -F, "\$2 == \"termination_break\" && \$3 == \"cable\" && \$4 == 0 && \$5 > 81313.5 && \$5 < 0.9 * 406567.5 && \$7 == \"end\" { ok = 1 } END { exit !ok }" "$e"'
check "an end's fitting: summary.json gives the end" 'grep -qE "\"type\":\"termination_break\",\"element\":\"cable 0\",\"value\":[0-9.e+]+,\"unit\":\"N\",\"cable_end\":\"end\"}" "$tmp/end/summary.json"'
check "an end's fitting: the terminal gives the end" 'grep -qE "^ +[0-9.]+ s  termination_break +cable 0 at the end anchor$" "$tmp/end.out"'
check "an end's fitting: echoed in the inputs" 'grep -qF "\"end\":{\"termination\":null,\"termination_efficiency\":0.2,\"slip_load\":0,\"slip_travel\":0}" "$tmp/end/summary.json"'
# Clips that slip: cable 0's at 10 kip (44,482 N, above its 5-kip pretension) with 6 in of turn-back. Both
# its ends start to slip, neither above 10 kip and the solve's tolerance (1e-4 Fu = 41 N), and the rope
# runs out at one of them, its end span then at 10 kip within that tolerance.
"$cs" run tests/good/base.yaml -o "$tmp/slip" --set "barrier.cables[0].slip_load=10 kip" \
    --set "barrier.cables[0].slip_travel=6 in" >"$tmp/slip.out" 2>&1
e="$tmp/slip/events.csv"
check "a slipping fitting: each end of cable 0 starts to slip at its slip load" '[ "$(awk -F, "\$2 == \"termination_slip\" && \$4 == 0 && \$5 < 44482.2 + 41" "$e" | cut -d, -f7 | sort | tr "\n" " ")" = "end start " ]'
check "a slipping fitting: the rope runs out of it at its slip load" 'awk -F, "\$2 == \"termination_break\" && \$4 == 0 && \$5 > 44482.2 - 41 && \$5 < 44482.2 + 41 { ok = 1 } END { exit !ok }" "$e"'
check "a slipping fitting: the terminal gives the end" 'grep -qE "^ +[0-9.]+ s  termination_slip +cable 0 at the start anchor$" "$tmp/slip.out"'
for key in max_50ms_decel_g max_dynamic_penetration_m max_barrier_deflection_m stopped stop_time_s exit_speed_mps \
    posts_failed_left posts_failed_right initial_kinetic_energy_j energy_balance_error events inputs; do
    check "summary.json has $key" 'grep -q "\"$key\":" "$out/summary.json"'
done
# Every field of the C summary (cs_summary in include/cablesim/sim.h) but its size (the struct's, for the
# library to fill it to) is a key of summary.json by the same name.
fields=$(sed -n '/^typedef struct cs_summary {/,/^} cs_summary;/p' include/cablesim/sim.h | perl -0pe 's{/\*.*?\*/}{}gs' |
    grep -v cs_summary | grep -oE '[a-z_0-9]+(\[[A-Z_0-9]+\])?[,;]' | tr -d ',;' | sed 's/\[.*//' | grep -vx size)
check "the fields of cs_summary were read" '[ "$(wc -w <<<"$fields")" -ge 26 ]'
for key in $fields; do
    check "summary.json has cs_summary's $key" 'grep -q "\"$key\":" "$out/summary.json"'
done
# Each cable's peak tension and work on the vehicle: summary.json's cables, a line each in the terminal
check "summary.json: each cable's peak and work" 'grep -qE "\"cables\":\[\{\"index\":0,\"peak_tension_n\":[0-9.e+]+,\"peak_tension_time_s\":[0-9.e+-]+,\"work_on_vehicle_j\":-?[0-9.e+-]+,\"energy_share\":-?[0-9.e+-]+\},\{\"index\":1," "$out/summary.json"'
check "summary.json: the sudden losses" 'grep -qE "\"sudden_loss_count\":[0-9]+,\"sudden_losses\":\[" "$out/summary.json"'
check "the terminal: a line per cable, kN and kip" '[ "$(grep -cE "^  cable [01] +peak [0-9.]+ kN \([0-9.]+ kip\) at [0-9.]+ s; work on the vehicle -?[0-9.]+ kJ \(-?[0-9]+ ft-kip\), -?[0-9.]+% of its kinetic energy taken$" "$tmp/stdout")" -eq 2 ]'
check "--set reached the run" 'grep -q "\"speed\":15.6464" "$out/summary.json"'
check "no NaN or infinity in outputs" '! grep -qiE "(^|[,:[])-?(nan|inf)" "$out/timeseries.csv" "$out/summary.json" "$out/events.csv"'

cp "$out/summary.json" "$tmp/before.json"
"$cs" run examples/aps3.yaml -o "$out" --set scenario.speed="35 kg" >/dev/null 2>"$tmp/stderr"
check "a refused model is status 2" '[ $? -eq 2 ]'
check "the refusal names the place" 'grep -q "^--set scenario.speed=35 kg: .*not of speed" "$tmp/stderr"'
check "a refused run leaves earlier outputs alone" 'cmp -s "$tmp/before.json" "$out/summary.json"'
# --dt and --t-end stand for --set scenario.dt= and scenario.t_end=, but a problem with one names it as
# the user typed it
"$cs" run examples/aps3.yaml -o "$tmp/dt" --dt "2 ft" >/dev/null 2>"$tmp/stderr"
check "a refused --dt is status 2, named as given" '[ $? -eq 2 ] && grep -qxF -- "--dt 2 ft: '"'"'ft'"'"' is a unit of length, not of time (expected a time, e.g. \"0.5 ms\")" "$tmp/stderr" && ! grep -q "scenario.dt" "$tmp/stderr"'
"$cs" check examples/aps3.yaml --t-end "-1 s" >/dev/null 2>"$tmp/stderr"
check "a refused --t-end is named as given" '[ $? -eq 2 ] && grep -qe "^--t-end -1 s: '"'"'-1 s'"'"' must be above zero" "$tmp/stderr" && ! grep -qe "--set\|scenario.t_end" "$tmp/stderr"'
# Determinism: the same input twice gives byte-identical outputs (a run through the barrier's failures,
# 0.3 s of APS1: ropes or their anchors giving way and the end posts failing, exercises every stage of the
# step).
for k in 1 2; do
    "$cs" run examples/aps1.yaml -o "$tmp/twice$k" --t-end "300 ms" >/dev/null 2>&1
done
for f in timeseries.csv events.csv; do
    check "$f byte-identical on a second run" 'cmp -s "$tmp/twice1/$f" "$tmp/twice2/$f"'
done
# summary.json's first line records the command line, whose -o differs
check "summary.json byte-identical on a second run, but for its command line" \
    'cmp -s <(tail -n +2 "$tmp/twice1/summary.json") <(tail -n +2 "$tmp/twice2/summary.json") && ! cmp -s "$tmp/twice1/summary.json" "$tmp/twice2/summary.json"'
check "the twice-run passed a rope or anchor failure" \
    'grep -qE "cable_break|termination_break|anchor_yield|anchor_pullout" "$tmp/twice1/events.csv"'
"$cs" run tests/bad/zero_spacing.yaml -o "$tmp/never" >/dev/null 2>&1
check "a bad model writes nothing" '[ $? -eq 2 ] && [ ! -e "$tmp/never" ]'

# One folder, one run: a run without --plots and --report into the folder of a run with them leaves no
# figures and no report beside its files (its manifest names them), nor a temporary a killed run left;
# with --force, the files cablesim did not write stay (tests/cli_outdir.sh: the rest of the rule).
dir="$tmp/one"
"$cs" run examples/aps3.yaml -o "$dir" --t-end "20 ms" --plots --report >/dev/null 2>&1
check "a run with --plots and --report writes them" '[ -s "$dir/plots/speed.png" ] && [ -s "$dir/plots/speed.svg" ] && [ -s "$dir/report.html" ]'
echo partial >"$dir/.cablesim-tmp.events.csv.a1B2c3"
"$cs" run examples/aps3.yaml -o "$dir" --t-end "10 ms" >"$tmp/one.out" 2>&1
check "the rerun exits 0" '[ $? -eq 0 ] || { cat "$tmp/one.out"; false; }'
check "the rerun left no figures and no report" '[ ! -e "$dir/plots" ] && [ ! -e "$dir/report.html" ]'
check "the rerun removed a stale temporary" '[ ! -e "$dir/.cablesim-tmp.events.csv.a1B2c3" ]'
check "the folder holds the rerun's outputs" 'grep -qF "\"overrides\":[\"--t-end 10 ms\"]" "$dir/summary.json" && [ "$(ls "$dir" | tr "\n" " ")" = "events.csv summary.json timeseries.csv " ]'
"$cs" run examples/aps3.yaml -o "$dir" --t-end "20 ms" --plots --report >/dev/null 2>&1
echo notes >"$dir/notes.txt"
echo mine >"$dir/plots/mine.txt"
"$cs" run examples/aps3.yaml -o "$dir" --t-end "10 ms" --force >"$tmp/one.out" 2>&1
check "the forced rerun exits 0" '[ $? -eq 0 ] || { cat "$tmp/one.out"; false; }'
check "the forced rerun left no figures and no report" '[ -z "$(ls "$dir/plots" | grep -E "\.(png|svg)$")" ] && [ ! -e "$dir/report.html" ]'
check "the forced rerun left the files cablesim did not write" '[ "$(cat "$dir/notes.txt")" = notes ] && [ "$(cat "$dir/plots/mine.txt")" = mine ]'

# Where a result comes from: summary.json's first line holds the version, the command line (shell-quoted),
# the overrides as given and the model's hash, which the terminal summary gives too; the same numbers give
# the same hash, another value another.
json=$(head -1 "$out/summary.json")
check "summary.json: the version" 'grep -qF "{\"cablesim\":{\"version\":\"$("$cs" --version | cut -d" " -f2)\"," <<<"$json"'
check "summary.json: the command line, quoted" 'grep -qF "\"command\":\"$cs run examples/aps3.yaml -o $out --t-end '"'"'20 ms'"'"' --set '"'"'scenario.speed=35 mph'"'"'\"" <<<"$json"'
check "summary.json: the overrides as given" 'grep -qF "\"overrides\":[\"--t-end 20 ms\",\"--set scenario.speed=35 mph\"]" <<<"$json"'
hash=$(grep -oE "\"model_hash\":\"[0-9a-f]{16}\"" <<<"$json" | cut -d'"' -f4)
check "summary.json: the model's hash" '[ ${#hash} -eq 16 ]'
check "the terminal gives the same hash on its second line" '[ "$(sed -n 2p "$tmp/stdout")" = "  model hash           $hash (cablesim $("$cs" --version | cut -d" " -f2))" ]'
same=$("$cs" run examples/aps3.yaml -o "$tmp/same" --t-end "0.02 s" --set scenario.speed="15.6464 m/s" 2>&1 | sed -n 2p)
other=$("$cs" run examples/aps3.yaml -o "$tmp/other" --t-end "20 ms" --set scenario.speed="36 mph" 2>&1 | sed -n 2p)
check "the same numbers, given otherwise: the same hash" 'grep -q " $hash " <<<"$same"'
check "another speed: another hash" 'grep -qE " [0-9a-f]{16} " <<<"$other" && ! grep -q " $hash " <<<"$other"'

# Outcomes that say what happened: APS3's truck breaks through where the ropes' end fittings hold a quarter
# of their strength, so its penetration is not given, only how far it had got (beyond), with its exit
# speed; the library's PU at 40 mph stops, and its penetration is given. The failure events are listed;
# the posts' hinges are counted, not listed. The truck strikes the middle of a symmetric barrier, so which
# end's fitting lets go first is round-off's choice.
"$cs" run examples/aps3.yaml -o "$tmp/through" --set "barrier.cables[0].termination_efficiency=0.25" \
    --set "barrier.cables[1].termination_efficiency=0.25" >"$tmp/through.out" 2>&1
j="$tmp/through/summary.json"
check "breakthrough: no penetration as such in summary.json" 'grep -q "\"outcome\":\"breakthrough\"" "$j" && grep -q "\"max_dynamic_penetration_m\":null," "$j" && grep -qE "\"penetration_beyond_m\":[0-9]" "$j" && grep -qE "\"exit_speed_mps\":[0-9]" "$j"'
check "breakthrough: the terminal says beyond" 'grep -qE "^  penetration          beyond [0-9.]+ m \([0-9.]+ ft\): the vehicle got through$" "$tmp/through.out" && ! grep -q "max penetration" "$tmp/through.out"'
check "breakthrough: the failure events, the breakthrough among them" 'grep -qE "^  failure events       [0-9]+, in order" "$tmp/through.out" && grep -qE "^ +[0-9.]+ s  termination_break +cable [01] at the (start|end) anchor$" "$tmp/through.out" && grep -qE "^ +[0-9.]+ s  breakthrough$" "$tmp/through.out"'
hinges=$(grep -c ",post_hinge," "$tmp/through/events.csv")
check "breakthrough: the $hinges post hinges counted, not listed" '[ "$hinges" -gt 0 ] && grep -q "^  posts yielding       $hinges plastic hinges at the base" "$tmp/through.out" && ! grep -q " post_hinge " "$tmp/through.out"'
"$cs" run examples/aps3.yaml -o "$tmp/stops" --set vehicle=PU --set "scenario.speed=40 mph" >"$tmp/stops.out" 2>&1
j="$tmp/stops/summary.json"
check "stopped: its penetration given" 'grep -q "\"outcome\":\"stopped\"" "$j" && grep -qE "\"max_dynamic_penetration_m\":[0-9]" "$j" && grep -q "\"penetration_beyond_m\":null," "$j" && grep -qE "^  max penetration      [0-9.]+ m" "$tmp/stops.out"'

# A roadside run (RS1, NCHRP 350 test 3-11's pickup at 25.7 deg): its occupant risk with units, its roll
# and pitch peaks, and the criteria of the test it stands for, in summary.json and the terminal.
out=$("$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1" 2>&1)
j="$tmp/rs1/summary.json"
check "rs1: summary.json's occupant risk with units" 'grep -qE "\"occupant_risk\":\{\"basis\":\"[^\"]*CFC 180[^\"]*\",\"point_m\":\[0,0,0\],\"occupant_impact\":\"in_run\",\"occupant_impact_time_s\":[0-9.e-]+,\"oiv_longitudinal_mps\":[0-9.e-]+,\"oiv_lateral_mps\":[0-9.e-]+,\"ora_longitudinal_g\":[0-9.e-]+,\"ora_lateral_g\":[0-9.e-]+,\"head_impact\":\"in_run\",\"thiv_time_s\":[0-9.e-]+,\"thiv_mps\":[0-9.e-]+,\"thiv_kmh\":[0-9.e-]+,\"phd_g\":[0-9.e-]+,\"asi\":[0-9.e-]+,\"asi_time_s\":[0-9.e-]+\},\"max_roll_deg\":[0-9.e-]+,\"max_pitch_deg\":[0-9.e-]+" "$j"'
check "rs1: the criteria of NCHRP 350 3-11 as run" 'grep -qE "\"roadside_criteria\":\{\"standard\":\"nchrp-350\",\"test\":\"3-11\",\"vehicle\":\"2000P\",\"criteria\":\[\{\"id\":\"A\"" "$j" && grep -qE "\"id\":\"D\",[^}]*\"verdict\":\"not judged\"" "$j"'
# A vehicle that has left the barrier is redirected whatever stops the run on its way out: the design's
# pickup leaves the ropes at 1.495 s and the run would end a vehicle's length later (1.83275 s); 6,000
# steps (1.5 s at 0.25 ms) stop it first, with the exit already taken.
left=$("$cs" run examples/roadside/design.yaml --set scenario.max_steps=6000 -o "$tmp/left" 2>&1)
check "a run stopped by its step limit after the exit: redirected, with its exit" '[ $? -eq 0 ] && head -1 <<<"$left" | grep -qE "^design: the vehicle was redirected, exit speed [0-9.]+ m/s .* leaving contact at t = 1.495 s$" || { head -3 <<<"$left"; false; }'
# A's detail names each cable the pickup rode over or went under (events.csv's override and underride
# rows: RS5 with its lowest rope lowered to 0.30 m, under the bumper and the front axle, is ridden over),
# and says the other cables held it, as the verdict pass says.
"$cs" run examples/roadside/rs5.yaml --set "barrier.cables[0].height=300 mm" -o "$tmp/rs5" >/dev/null 2>&1
slipped=$(awk -F, '$2 == "override" { printf "rode over cable %d at %s s\n", $4, $1 } $2 == "underride" { printf "went under cable %d at %s s\n", $4, $1 }' "$tmp/rs5/events.csv")
check "rs5: criterion A names every cable the vehicle rode over or went under" '[ -n "$slipped" ] && a=$(grep -oE "\"id\":\"A\",[^}]*" "$tmp/rs5/summary.json") && grep -q "\"verdict\":\"pass\"" <<<"$a" && grep -q "and the other cables held it (no override or underride of the barrier)" <<<"$a" && [ "$(grep -oE "(rode over|went under) cable [0-9]+ at [0-9.e-]+ s" <<<"$a")" = "$slipped" ]'
# the exit criteria of NCHRP 350 (M: the exit angle, judged; K: the path after, not judged)
check "rs1: its exit criteria, M judged and K not" 'grep -qE "\"id\":\"M\",[^}]*\"verdict\":\"(pass|FAIL)\"" "$j" && grep -qE "\"id\":\"K\",[^}]*\"verdict\":\"not judged\"" "$j"'
# MASH's exit box of the 2000P (A = 2 m + 1.95 m wide + 0.16 x 5.35 m long = 4.806 m), beside the criteria
check "rs1: the exit box with the criteria" 'grep -qE "\],\"exit_box\":\{\"a_m\":4\.806,\"b_m\":10,\"start_x_m\":[0-9.e-]+,\"direction\":1,\"cross_along_m\":[0-9.e-]+,\"crossed_in_run\":(true|false),\"heading_back\":false\}\}" "$j"'
# A pickup that leaves the ropes and, a vehicle's length on, moves back toward the barrier with no wheel past
# the box's far side (the design at 8 deg, its tyres gripping at a friction of 1.0) has no exit to judge:
# its box is not judged, not passed
back=$("$cs" run examples/roadside/design.yaml --set "scenario.angle=8 deg" --set vehicle.tyre_friction=1.0 \
    -o "$tmp/back" 2>&1)
check "a vehicle moving back toward the barrier: its exit box not judged" 'grep -qE "^  criteria \(as run\)    mash 3-11: .*exit box not judged" <<<"$back" && grep -qE "\"cross_along_m\":null,\"crossed_in_run\":false,\"heading_back\":true\}" "$tmp/back/summary.json" && grep -qF "at its end the vehicle moves back toward the barrier" "$tmp/back/summary.json"'
check "rs1: the terminal's occupant risk and criteria" 'grep -qE "^  occupant impact      [0-9.]+ s after first contact: OIV [0-9.]+ m/s \([0-9.]+ ft/s\) longitudinal" <<<"$out" && grep -qE "^  EN 1317-1            THIV [0-9.]+ km/h \([0-9.]+ m/s\), PHD [0-9.]+ g, ASI [0-9.]+$" <<<"$out" && grep -qE "^  criteria \(as run\)    nchrp-350 3-11: A (pass|FAIL), D not judged," <<<"$out"'
# --occupant-at: the CG named as a point gives the CG's numbers; another point is written with them; a
# bad point is refused with the reason
"$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1cg" --occupant-at "0 m,0 m,0 m" >/dev/null 2>&1
oiv() { grep -oE "\"oiv_longitudinal_mps\":[0-9.e-]+,\"oiv_lateral_mps\":[0-9.e-]+,\"ora_longitudinal_g\":[0-9.e-]+" "$1"; }
check "--occupant-at the CG: the CG's occupant risk" '[ -n "$(oiv "$j")" ] && [ "$(oiv "$j")" = "$(oiv "$tmp/rs1cg/summary.json")" ] && grep -qF "\"point_m\":[0,0,0]" "$tmp/rs1cg/summary.json"'
out=$("$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1p" --occupant-at "30 cm,0.4 m,0.2 m" 2>&1)
check "--occupant-at a point: written with its place" 'grep -qF "\"point_m\":[0.3,0.4,0.2]" "$tmp/rs1p/summary.json" && grep -qE "^  occupant risk at     x 0.300 m, y 0.400 m, z 0.200 m from the CG" <<<"$out"'
# the criteria judge the CG's occupant risk, as the standards take it, whatever point the run reports
crit_l() { grep -oE "\"id\":\"L\",[^}]*" "$1"; }
check "--occupant-at a point: its own numbers written, L judged on the CG's" '[ "$(oiv "$tmp/rs1p/summary.json")" != "$(oiv "$j")" ] && [ -n "$(crit_l "$j")" ] && [ "$(crit_l "$tmp/rs1p/summary.json")" = "$(crit_l "$j")" ]'
out=$("$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1bad" --occupant-at "0.3 m,1 kg,0" 2>&1)
check "--occupant-at with a mass: exit 2, the reason" '[ $? -eq 2 ] && grep -qF "cablesim run: --occupant-at 0.3 m,1 kg,0: " <<<"$out" && grep -q "not of length" <<<"$out" && [ ! -e "$tmp/rs1bad" ]'
out=$("$cs" run examples/roadside/rs1.yaml -o "$tmp/rs1bad" --occupant-at "0.3 m,1 m" 2>&1)
check "--occupant-at with two lengths: exit 2, the reason" '[ $? -eq 2 ] && grep -qF "three lengths are needed" <<<"$out"'
check "aps3 (head-on, the 15,000-lb truck): no roadside criteria" 'grep -q "\"roadside_criteria\":null" "$tmp/aps3/summary.json"'

# Runs that end: an output interval below the step (1e-30 s never moved the next frame on) or past a
# million frames is refused at its place; scenario.max_steps ends a run "step_limit" (tests/test_crash.c:
# the engine's side).
out=$(timeout 60 "$cs" run examples/aps3.yaml -o "$tmp/tiny" --set 'scenario.output_interval=1e-30 s' 2>&1)
check "an output interval below the step is refused at its place" '[ $? -eq 2 ] && grep -q "scenario.output_interval=1e-30 s: .1e-30 s. is too small for output_interval" <<<"$out" && [ ! -e "$tmp/tiny" ]'
out=$("$cs" run examples/aps3.yaml -o "$tmp/dt2" --dt "2 ms" --t-end "0.1 s" 2>&1)
check "a step above the default 1-ms interval: a frame every step" '[ $? -eq 0 ] && [ "$(wc -l <"$tmp/dt2/timeseries.csv")" -eq 52 ] || { echo "$out"; false; }'
out=$(timeout 60 "$cs" run examples/aps3.yaml -o "$tmp/tiny" --dt "0.1 us" --set 'scenario.output_interval=0.1 us' 2>&1)
check "past a million frames is refused at its place" '[ $? -eq 2 ] && grep -qF "scenario.output_interval=0.1 us: 3e+07 frames to the end time (t_end / output_interval, or / dt for 0) exceed the limit of 1e+06" <<<"$out"'
out=$("$cs" run examples/aps3.yaml -o "$tmp/steps" --set scenario.max_steps=100 2>&1)
check "scenario.max_steps ends the run: step_limit" '[ $? -eq 0 ] && grep -q "^aps3: the run took its 100 steps (scenario.max_steps) at t = 0.050 s" <<<"$out" && grep -q "\"outcome\":\"step_limit\"" "$tmp/steps/summary.json"'
# no -o: results/NAME, and a run with overrides a folder of its own named from them, leaving the first
mkdir -p "$tmp/cwd"
(cd "$tmp/cwd" && "$cs" run "$OLDPWD/examples/aps3.yaml" >/dev/null 2>&1 &&
    "$cs" run "$OLDPWD/examples/aps3.yaml" --set scenario.speed="35 mph" --set 'barrier.cables[0].pretension=8 kip' --t-end "10 ms" >"$tmp/cwd.out" 2>&1)
check "no -o: results/aps3, and the run with overrides in results/aps3_speed-35mph_cables0.pretension-8kip_t-end-10ms" \
    '[ "$(ls "$tmp/cwd/results" | tr "\n" " ")" = "aps3 aps3_speed-35mph_cables0.pretension-8kip_t-end-10ms " ] && grep -q "\"overrides\":\[\]" "$tmp/cwd/results/aps3/summary.json" && grep -qF "outputs              results/aps3_speed-35mph_cables0.pretension-8kip_t-end-10ms/{" "$tmp/cwd.out"'
finish
