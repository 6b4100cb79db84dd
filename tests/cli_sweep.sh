#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cablesim sweep end to end: the same runs.csv (byte for byte), summaries and plots on 1 and 2 threads, a
# grid, a Monte Carlo, a Latin hypercube, the outputs' shape, runs.nc (--netcdf or `netcdf: true`: the same
# bytes on 1 and 2 threads, runs.csv's runs and numbers read back by ncdump, nothing but the runs' journal
# written when it cannot be written), the plots of `plot:` (a grid's lines as PNG and SVG, a Monte Carlo's
# points as PDF, named in summary.md and on the outputs line, nothing but the journal written when one
# cannot be), plain progress lines
# when not on a terminal, `cablesim check` of a spec, and every spec in tests/sweep/bad/ refused with
# status 2 and exactly the problems its "# expect: LINE:COL: text" lines name. The runs are 10 to 20 ms
# long so the suite stays fast.
source "$(dirname "$0")/lib.sh"

check "sweep --help" '"$cs" sweep --help | grep -q "^Usage: cablesim sweep SPEC.yaml"'
"$cs" sweep >/dev/null 2>&1
check "sweep without a spec is status 2" '[ $? -eq 2 ]'

# Each spec on 1 and 2 threads (those in $two); under the sanitizers the Latin hypercube's is the
# representative case of the threads, and the other specs run on 1.
two="lhs grid mc plot"
plain_only "grid, mc and plot on 2 threads" || two=lhs
on_two() { [[ " $two " == *" $1 "* ]]; }
for spec in lhs grid mc plot; do
    threads=1
    on_two "$spec" && threads="1 2"
    for t in $threads; do
        "$cs" sweep --allow-path examples "tests/sweep/$spec.yaml" -o "$tmp/$spec-$t" --threads "$t" >"$tmp/$spec-$t.out" 2>"$tmp/$spec-$t.err"
        check "$spec on $t threads exits 0" '[ $? -eq 0 ] || { cat "$tmp/$spec-$t.err"; false; }'
    done
    if [ "$threads" = "1 2" ]; then
        check "$spec: runs.csv the same on 1 and 2 threads" 'cmp "$tmp/$spec-1/runs.csv" "$tmp/$spec-2/runs.csv"'
        # the summaries record the command line (its -o and --threads differ): the same but for that line
        check "$spec: summary.md the same on 1 and 2 threads, but for its command line" \
            'cmp <(grep -v "^Written by cablesim " "$tmp/$spec-1/summary.md") <(grep -v "^Written by cablesim " "$tmp/$spec-2/summary.md")'
        check "$spec: summary.json the same on 1 and 2 threads, but for its first line" \
            'cmp <(tail -n +2 "$tmp/$spec-1/summary.json") <(tail -n +2 "$tmp/$spec-2/summary.json")'
    fi
    check "$spec: the summaries give the command line" 'grep -qF "\"command\":\"$cs sweep --allow-path examples tests/sweep/$spec.yaml -o $tmp/$spec-1 --threads 1\"" "$tmp/$spec-1/summary.json" && grep -qF "Written by cablesim $("$cs" --version | cut -d" " -f2): \`$cs sweep --allow-path examples tests/sweep/$spec.yaml -o $tmp/$spec-1 --threads 1\`; the base model'"'"'s hash " "$tmp/$spec-1/summary.md"'
    check "$spec: no run failed" 'grep -q "; 0 did not run to the end" "$tmp/$spec-1.out"'
    check "$spec: progress as plain lines" 'grep -q "^sweep: [0-9]*/[0-9]* runs (100%)" "$tmp/$spec-1.err"'
done

runs="$tmp/lhs-1/runs.csv"
check "runs.csv: 4 runs and a header" '[ "$(wc -l <"$runs")" -eq 5 ]'
check "runs.csv: inputs in SI with units" 'head -1 "$runs" | grep -q "^run,barrier.soil.soil_pressure \[Pa\],barrier.posts\[0\].yield_stress \[Pa\],scenario.speed \[m/s\],outcome,astm_f2656_as_run,astm_f2656_penetration \[m\],sd_std_02_01_as_run,"'
check "runs.csv: responses" 'head -1 "$runs" | grep -q "max_dynamic_penetration \[m\].*events_cable_break.*,error$"'
check "runs.csv: rows in run order" '[ "$(cut -d, -f1 "$runs" | tail -n +2 | tr "\n" " ")" = "0 1 2 3 " ]'
check "runs.csv: speeds within 38-42 mph" 'awk -F, "NR > 1 && (\$4 < 38 * 0.44704 || \$4 > 42 * 0.44704) { bad = 1 } END { exit bad }" "$runs"'
check "runs.csv: soil pressure above its 4000-psf minimum" 'awk -F, "NR > 1 && \$2 < 4000 * 47.880258 { bad = 1 } END { exit bad }" "$runs"'
check "runs.csv: an ASTM label per run" '[ "$(cut -d, -f6 "$runs" | tail -n +2 | grep -cE "^(none|not rated|(C|PU|M|H)[0-9]+/P[1-4])$")" -eq 4 ]'
check "runs.csv: the ASTM penetration, a number or empty" '[ "$(cut -d, -f7 "$runs" | tail -n +2 | grep -cE "^([0-9.e+-]+)?$")" -eq 4 ]'
check "runs.csv: an SD-STD-02.01 label per run" '[ "$(cut -d, -f8 "$runs" | tail -n +2 | grep -cE "^(none|not rated|K(4|8|12)/L[1-3])$")" -eq 4 ]'
check "summary.json: Wilson intervals and Spearman" 'grep -q "\"breakthrough\":{\"count\":0,\"p\":0,\"ci95\":\[0,0.48" "$tmp/lhs-1/summary.json" && grep -q "\"spearman\":{\"max_50ms_decel_g\":{\"barrier.soil.soil_pressure\":" "$tmp/lhs-1/summary.json"'
check "summary.md: outcome table" 'grep -q "^| max dynamic penetration > 1 m past the attack face (or the vehicle got through) | " "$tmp/lhs-1/summary.md" && grep -q "^## Input importance" "$tmp/lhs-1/summary.md"'
check "grid: 3 x 2 runs, last variable fastest" '[ "$(cut -d, -f3 "$tmp/grid-1/runs.csv" | tail -n +2 | tr "\n" " ")" = "SD-STD-02.01 PU SD-STD-02.01 PU SD-STD-02.01 PU " ]'
check "grid: a run cut at its time limit is not rated, with no penetration" '[ "$(grep -c ",time_limit,not rated,,not rated," "$tmp/grid-1/runs.csv")" -eq 6 ]'
check "grid: a text input has no Spearman" 'grep -q "\"vehicle\":null" "$tmp/grid-1/summary.json"'

# plots: tests/sweep/plot.yaml's grid draws deflection (PNG) and exit speed (SVG) against the post spacing,
# a line per vehicle; a Monte Carlo's plot shows each run as a point (PDF)
png="$tmp/plot-1/plots/max_barrier_deflection-vs-spacing.png"
svg="$tmp/plot-1/plots/exit_speed-vs-spacing.svg"
check "plot: a PNG named y-vs-x" '[ "$(head -c 8 "$png" | od -An -tx1 | tr -d " \n")" = 89504e470d0a1a0a ]'
check "plot: the PNG is 1200 x 760 and not empty" '[ "$(head -c 24 "$png" | tail -c 8 | od -An -tx1 | tr -d " \n")" = 000004b0000002f8 ] && [ "$(stat -c %s "$png")" -gt 20000 ]'
check "plot: format svg gives an SVG" 'head -c 200 "$svg" | grep -q "<svg" && tail -c 20 "$svg" | grep -q "</svg>"'
on_two plot &&
    check "plot: the same plots on 1 and 2 threads" 'cmp "$png" "$tmp/plot-2/plots/max_barrier_deflection-vs-spacing.png" && cmp "$svg" "$tmp/plot-2/plots/exit_speed-vs-spacing.svg"'
check "plot: the plots asked for, and the study's own" '[ "$(ls "$tmp/plot-1/plots" | grep -v "^study-" | tr "\n" " ")" = "exit_speed-vs-spacing.svg max_barrier_deflection-vs-spacing.png " ] && [ "$(ls "$tmp/grid-1/plots" | grep -vc "^study-")" -eq 0 ]'
# the study's own figures and page: the outcomes, and a histogram, a tornado chart and a scatter of each of
# the five responses its runs have a value of (none stops within its 10 ms, none leaves the barrier: no
# max dynamic penetration, no exit speed, and no empty figure of them); report.html holds them all, says
# which it leaves out, and its outcome table agrees with runs.csv
check "study: 16 PNG figures" '[ "$(ls "$tmp/lhs-1/plots" | grep -c "^study-.*\.png$")" -eq 16 ] && [ ! -e "$tmp/lhs-1/plots/study-histogram-exit-speed.png" ]'
check "study: report.html has the 16 figures inline" '[ "$(grep -o "<svg" "$tmp/lhs-1/report.html" | wc -l)" -eq 16 ]'
check "study: the penetration beyond is one of its responses" '[ -s "$tmp/lhs-1/plots/study-histogram-penetration-beyond.png" ] && grep -q "<tr><td>penetration beyond (m)</td><td>4</td>" "$tmp/lhs-1/report.html"'
# a tornado chart's y axis names its inputs, an input a bar, and has no numbered ticks
tornado=$(awk -v RS='</svg>' '/Spearman rank correlation of each input/ {print; exit}' "$tmp/lhs-1/report.html")
check "study: a tornado chart's y axis names the inputs, no numbers" 'grep -q ">scenario.speed</text>" <<<"$tornado" && ! grep -qE ">-?[0-9]+</text>" <<<"$tornado"'
check "study: report.html says which responses have no figures" 'grep -qF "No run has a value of max dynamic penetration, exit speed (runs that left the barrier): their figures are left out." "$tmp/lhs-1/report.html"'
stopped=$(awk -F, 'NR > 1 && $5 == "stopped"' "$runs" | wc -l)
check "study: report.html counts the stopped runs as runs.csv does" 'grep -q "<tr><td>stopped</td><td>$stopped</td>" "$tmp/lhs-1/report.html"'
check "study: the same figures on 1 and 2 threads" 'cmp "$tmp/lhs-1/plots/study-outcomes.png" "$tmp/lhs-2/plots/study-outcomes.png" && cmp "$tmp/lhs-1/report.html" "$tmp/lhs-2/report.html"'
# the study's page gives the inputs in the spec's units: the soil pressure in psf (at least its 4000-psf
# minimum), the speed in mph (38-42), the rope tension in kN
page="$tmp/lhs-1/report.html"
check "study: the inputs' table in the spec's units" 'grep -qE "<tr><td>barrier.soil.soil_pressure</td><td>normal: mean 8000 psf, sd 1000 psf, min 4000 psf</td><td>psf</td><td>[0-9.]+</td>" "$page" && grep -qE "<tr><td>scenario.speed</td><td>[^<]*</td><td>mph</td>" "$page"'
check "study: the inputs' values in those units" 'grep -oE "<tr><td>(barrier.soil.soil_pressure|scenario.speed)</td><td>[^<]*</td><td>[a-z]+</td><td>[0-9.e+]+</td><td>[0-9.e+]+</td><td>[0-9.e+]+</td>" "$page" | sed -E "s/<\/?t[dr]>/ /g" | awk "\$3 == \"psf\" && (\$4 < 4000 || \$6 > 12000) { bad = 1 } \$3 == \"mph\" && (\$4 < 38 || \$6 > 42) { bad = 1 } END { exit bad || NR != 2 }"'
check "study: the cable tension in kN" 'grep -q "<tr><td>max cable tension (kN)</td>" "$page"'
# --dt and --t-end stand for sets of scenario.dt and scenario.t_end; a problem with one names it as given
"$cs" sweep --allow-path examples tests/sweep/through.yaml -o "$tmp/dt" --dt "2 ft" --quiet >/dev/null 2>"$tmp/dt.err"
check "a refused --dt is status 2, named as given" '[ $? -eq 2 ] && grep -qxF -- "--dt 2 ft: '"'"'ft'"'"' is a unit of length, not of time (expected a time, e.g. \"0.5 ms\")" "$tmp/dt.err" && ! grep -q "scenario.dt" "$tmp/dt.err"'
# a run that breaks through: runs.csv gives no penetration, only how far it got, as summary.json does
"$cs" sweep --allow-path examples tests/sweep/through.yaml -o "$tmp/through" --quiet >"$tmp/through.out" 2>&1
check "through: exits 0" '[ $? -eq 0 ] || { cat "$tmp/through.out"; false; }'
col() { head -1 "$1" | tr , "\n" | grep -nxF -- "$2" | cut -d: -f1; }
pen=$(col "$tmp/through/runs.csv" "max_dynamic_penetration [m]")
beyond=$(col "$tmp/through/runs.csv" "penetration_beyond [m]")
check "through: both runs broke through" '[ "$(grep -c ",breakthrough," "$tmp/through/runs.csv")" -eq 2 ]'
check "through: no penetration, how far it got beyond" '[ "$(cut -d, -f"$pen" "$tmp/through/runs.csv" | tail -n +2 | tr "\n" " ")" = "  " ] && cut -d, -f"$beyond" "$tmp/through/runs.csv" | tail -n +2 | awk "!(\$1 > 2) { bad = 1 } END { exit bad || NR != 2 }"'
"$cs" run examples/aps3.yaml --set "scenario.speed=40 mph" --set "barrier.cables[0].pretension=22241.1 N" \
    --set "barrier.cables[0].termination_efficiency=0.25" --set "barrier.cables[1].termination_efficiency=0.25" -o "$tmp/through-run" >/dev/null 2>&1
single=$(grep -o '"penetration_beyond_m":[0-9.e+-]*' "$tmp/through-run/summary.json" | cut -d: -f2)
check "through: beyond as the single run's summary.json has it" 'grep -q "\"max_dynamic_penetration_m\":null" "$tmp/through-run/summary.json" && awk -F, -v s="$single" -v c="$beyond" "NR == 3 { d = \$c - s; exit !(s > 2 && d * d < 1e-12) }" "$tmp/through/runs.csv"'
# the summaries as runs.csv: no penetration of a run the barrier did not hold, the beyond of each, the rope
# tension in kN, the exit speeds
jstat() { grep -o "\"$2\":{\"runs\":[0-9]*,\"over\":\"[^\"]*\",\"mean\":[^,]*,\"sd\":[^,]*,\"min\":[^,]*,\"p05\":[^,]*,\"median\":[^,]*,\"p95\":[^,]*,\"max\":[^}]*}" "$1"; }
colmax() { cut -d, -f"$(col "$1" "$2")" "$1" | tail -n +2 | sort -g | tail -1; }
sj="$tmp/through/summary.json"
check "through: summary.json's penetration over no run, beyond over both" 'jstat "$sj" max_dynamic_penetration_m | grep -q "\"runs\":0,\"over\":\"the runs the barrier held .*\"mean\":null," && jstat "$sj" penetration_beyond_m | grep -q "^\"penetration_beyond_m\":{\"runs\":2,\"over\":\"the runs it did not hold"'
check "through: summary.json's largest beyond is runs.csv's" 'awk -v j="$(jstat "$sj" penetration_beyond_m | grep -o "\"max\":[0-9.e+-]*" | cut -d: -f2)" -v c="$(colmax "$tmp/through/runs.csv" "penetration_beyond [m]")" "BEGIN { exit !(c > 2 && (j - c) ^ 2 < 1e-16) }"'
check "through: summary.json's rope tension in kN, runs.csv's in N" '! grep -q max_cable_tension_n "$sj" && awk -v j="$(jstat "$sj" max_cable_tension_kn | grep -o "\"max\":[0-9.e+-]*" | cut -d: -f2)" -v c="$(colmax "$tmp/through/runs.csv" "max_cable_tension [N]")" "BEGIN { exit !(j > 100 && (j - c / 1000) ^ 2 < 1e-12) }"'
check "through: summary.json's exit speeds over both runs" 'awk -v j="$(jstat "$sj" exit_speed_mps | grep -o "\"max\":[0-9.e+-]*" | cut -d: -f2)" -v c="$(colmax "$tmp/through/runs.csv" "exit_speed [m/s]")" "BEGIN { exit !(j > 1 && (j - c) ^ 2 < 1e-16) }" && jstat "$sj" exit_speed_mps | grep -q "\"runs\":2,"'
check "through: summary.md says so, with the counts and units" 'grep -q "^| max dynamic penetration (m) | 0 | n/a |" "$tmp/through/summary.md" && grep -q "^| penetration beyond (m) | 2 | [0-9]" "$tmp/through/summary.md" && grep -q "^| max cable tension (kN) | 2 | [0-9.]* |" "$tmp/through/summary.md" && grep -q "^| exit speed (m/s) | 2 | [0-9]" "$tmp/through/summary.md" && grep -q "max dynamic penetration (m) only over the runs the barrier held" "$tmp/through/summary.md"'
check "through: a force given in N is shown in N" 'grep -q "<tr><td>barrier.cables\[0\].pretension</td><td>levels: 22241.1 N</td><td>N</td><td>22241.1</td>" "$tmp/through/report.html"'
check "plot: summary.md names each plot, what it shows and what it leaves out" 'grep -qxF -- "- \`plots/max_barrier_deflection-vs-spacing.png\`: max_barrier_deflection against barrier.posts[0].spacing, a line per vehicle: 6 of 6 runs shown, 0 broke through (marked with a cross); none left out." "$tmp/plot-1/summary.md" && grep -qxF -- "- \`plots/exit_speed-vs-spacing.svg\`: exit_speed against barrier.posts[0].spacing, a line per vehicle: 0 of 6 runs shown, 0 broke through (marked with a cross); left out: 6 runs with no exit_speed." "$tmp/plot-1/summary.md"'
check "plot: the outputs line names the plots" 'grep -qxF "outputs: $tmp/plot-1/{runs.csv,summary.md,summary.json,report.html,plots/study-*.png,plots/max_barrier_deflection-vs-spacing.png,plots/exit_speed-vs-spacing.svg}" "$tmp/plot-1.out"'
check "plot: the runs are the grid's, spacing slowest" '[ "$(cut -d, -f2,3 "$tmp/plot-1/runs.csv" | tail -n +2 | tr "\n" " ")" = "4,2270P 4,1100C 2,2270P 2,1100C 6,2270P 6,1100C " ]'
sed "s|^model: .*|model: $PWD/examples/aps3.yaml|" tests/sweep/mc.yaml >"$tmp/mc-plot.yaml"
printf 'plot:\n  x: scenario.impact_x\n  y: max_cable_tension\n  format: pdf\n' >>"$tmp/mc-plot.yaml"
"$cs" sweep --allow-path examples "$tmp/mc-plot.yaml" -o "$tmp/mc-plot" --quiet >"$tmp/mc-plot.out" 2>&1
check "plot: a Monte Carlo's plot exits 0" '[ $? -eq 0 ] || { cat "$tmp/mc-plot.out"; false; }'
check "plot: a Monte Carlo's runs as points, in a PDF" '[ "$(head -c 5 "$tmp/mc-plot/plots/max_cable_tension-vs-impact_x.pdf")" = "%PDF-" ] && grep -qF "max_cable_tension against scenario.impact_x, each run a point: 6 of 6 runs shown" "$tmp/mc-plot/summary.md"'
check "plot: the runs are the same with a plot" 'cmp "$tmp/mc-plot/runs.csv" "$tmp/mc-1/runs.csv"'
mkdir -p "$tmp/plot-fail/plots/max_barrier_deflection-vs-spacing.png"
out=$("$cs" sweep --allow-path examples tests/sweep/plot.yaml -o "$tmp/plot-fail" --quiet 2>&1)
check "a plot that cannot be written: status 1, why, nothing written" '[ $? -eq 1 ] && grep -q "nothing written: .*/plots/max_barrier_deflection-vs-spacing.png: Is a directory" <<<"$out" && [ "$(ls -A "$tmp/plot-fail")" = "$(printf ".cablesim-journal\nplots")" ] && [ "$(ls -A "$tmp/plot-fail/plots")" = max_barrier_deflection-vs-spacing.png ]'

# runs.nc: one variable of it, a value a line, at full precision
nc_column() { ncdump -p 9,17 -v "$2" "$1" | sed -n "/^ $2 = /,/;/p" | sed "s/^ $2 = //; s/;//" | tr ',' '\n' | tr -d ' ' | grep -v '^$'; }
threads="1 2"
plain_only "lhs --netcdf on 2 threads" || threads=1
for t in $threads; do
    "$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/nc-$t" --threads "$t" --netcdf --quiet >"$tmp/nc-$t.out" 2>&1
    check "lhs --netcdf on $t threads exits 0" '[ $? -eq 0 ] || { cat "$tmp/nc-$t.out"; false; }'
done
nc="$tmp/nc-1/runs.nc"
[ "$threads" = "1 2" ] && check "runs.nc the same on 1 and 2 threads" 'cmp "$tmp/nc-1/runs.nc" "$tmp/nc-2/runs.nc"'
check "runs.csv the same with --netcdf" 'cmp "$tmp/nc-1/runs.csv" "$runs"'
check "runs.nc: as many runs as runs.csv" '[ "$(ncdump -h "$nc" | grep -oE "^\s*run = [0-9]+" | grep -oE "[0-9]+")" -eq "$(($(wc -l <"$runs") - 1))" ]'
check "runs.nc: runs.csv's speeds, within 38-42 mph" 'paste -d, <(nc_column "$nc" scenario_speed) <(cut -d, -f4 "$runs" | tail -n +2) | awk -F, "\$1 < 38 * 0.44704 || \$1 > 42 * 0.44704 || \$1 != \$2 { bad = 1 } END { exit bad || NR != 4 }"'
check "runs.nc: runs.csv's penetrations in full (the CSV's 10 digits)" 'paste -d, <(nc_column "$nc" penetration_beyond) <(cut -d, -f13 "$runs" | tail -n +2) | awk -F, "!(\$1 > 0.05) || (\$1 - \$2) ^ 2 > (5e-10 * \$2) ^ 2 { bad = 1 } END { exit bad || NR != 4 }"'
check "runs.nc: units and CF" 'ncdump -h "$nc" | grep -q "scenario_speed:units = \"m/s\"" && ncdump -h "$nc" | grep -q ":Conventions = \"CF-1.8\""'
sed "s|^model: .*|model: $PWD/examples/aps3.yaml|; s|^seed: 7|&\nnetcdf: true|" tests/sweep/lhs.yaml >"$tmp/lhs-nc.yaml"
"$cs" sweep --allow-path examples "$tmp/lhs-nc.yaml" -o "$tmp/nc-spec" --quiet >/dev/null 2>&1
check "netcdf: true in the spec writes runs.nc, the same runs" '[ "$(nc_column "$tmp/nc-spec/runs.nc" scenario_speed | tr "\n" " ")" = "$(nc_column "$nc" scenario_speed | tr "\n" " ")" ]'
check "no runs.nc unless asked" '[ ! -e "$tmp/lhs-1/runs.nc" ]'
mkdir -p "$tmp/nc-fail/runs.nc"
out=$("$cs" sweep --allow-path examples tests/sweep/lhs.yaml -o "$tmp/nc-fail" --netcdf --quiet 2>&1)
check "a runs.nc that cannot be written: status 1, why, nothing written" '[ $? -eq 1 ] && grep -q "nothing written: .*/runs.nc: Is a directory" <<<"$out" && [ "$(ls -A "$tmp/nc-fail")" = "$(printf ".cablesim-journal\nruns.nc")" ]'

# --runs, --seed and --t-end from the command line; a different seed gives other inputs
"$cs" sweep --allow-path examples tests/sweep/mc.yaml -o "$tmp/mc-seed" --runs 3 --seed 99 --t-end "5 ms" --quiet >/dev/null 2>&1
check "--runs --seed --t-end" '[ "$(wc -l <"$tmp/mc-seed/runs.csv")" -eq 4 ] && ! cmp -s <(head -2 "$tmp/mc-seed/runs.csv") <(head -2 "$tmp/mc-1/runs.csv") && grep -q "scenario.t_end=5 ms" "$tmp/mc-seed/summary.json"'
check "--set of a varied path is refused, naming it" '! out=$("$cs" sweep --allow-path examples tests/sweep/mc.yaml -o "$tmp/setv" --runs 2 --set "scenario.impact_x=50 ft" 2>&1) && grep -qF -- "--set scenario.impact_x=50 ft: the study varies scenario.impact_x, so a fixed value would not be used" <<<"$out" && [ ! -e "$tmp/setv" ]'
sed "s|^model: .*|model: $PWD/examples/aps3.yaml|; s|^  scenario.impact_x: .*|  scenario.dt: {dist: uniform, min: 0.2 ms, max: 0.5 ms}|" tests/sweep/mc.yaml >"$tmp/mc-dt.yaml"
check "--dt on a study that varies scenario.dt is refused, named as given" '! out=$("$cs" sweep --allow-path examples "$tmp/mc-dt.yaml" -o "$tmp/setdt" --runs 2 --dt "1 ms" 2>&1) && grep -qF -- "--dt 1 ms: the study varies scenario.dt, so a fixed value would not be used (expected no --dt)" <<<"$out" && ! grep -q -- "--set" <<<"$out" && [ ! -e "$tmp/setdt" ]'
check "--runs on a grid is refused" '! "$cs" sweep --allow-path examples tests/sweep/grid.yaml -o "$tmp/x" --runs 3 >/dev/null 2>&1'

# `cablesim check` knows a spec from a model, and checks the spec's model with its values
check "check a spec" '"$cs" check --allow-path examples tests/sweep/lhs.yaml | grep -q "tests/sweep/lhs.yaml: a valid sweep spec: Latin hypercube of 4 runs over 3 values"'
check "check the example spec" '"$cs" check examples/aps3-uncertain.yaml >/dev/null'
check "check a bad spec" '"$cs" check --allow-path examples tests/sweep/bad/bad_level.yaml 2>&1 | grep -q "^tests/sweep/bad/bad_level.yaml:6:42: "'
check "check a spec with plots" '"$cs" check --allow-path examples tests/sweep/plot.yaml | grep -q "a valid sweep spec: grid of 6 runs over 2 values"'
check "check a bad plot" '"$cs" check --allow-path examples tests/sweep/bad/plot_unknown_response.yaml 2>&1 | grep -q "^tests/sweep/bad/plot_unknown_response.yaml:9:6: plot: y: unknown response"'

files=0
for f in tests/sweep/bad/*.yaml; do
    files=$((files + 1))
    out=$("$cs" sweep --allow-path examples "$f" -o "$tmp/bad" 2>&1)
    expect_problems "$f" "$out" $?
done
check "bad specs wrote nothing" '[ ! -e "$tmp/bad" ]'
check "at least 15 bad specs" '[ "$files" -ge 15 ]'
finish
