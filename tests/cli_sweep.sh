#!/usr/bin/env bash
# cablesim sweep end to end: the same runs.csv (byte for byte) and summaries on 1 and 2 threads, a grid,
# a Monte Carlo, a Latin hypercube, the outputs' shape, runs.nc (--netcdf or `netcdf: true`: the same bytes
# on 1 and 2 threads, runs.csv's runs and numbers read back by ncdump, nothing written when it cannot be
# written), plain progress lines when not on a terminal, `cablesim check` of a spec, and every spec in
# tests/sweep/bad/ refused with status 2 and exactly the problems its "# expect: LINE:COL: text" lines
# name. The runs are 10 ms long so the suite stays fast.
source "$(dirname "$0")/lib.sh"

check "sweep --help" '"$cs" sweep --help | grep -q "usage: cablesim sweep SPEC.yaml"'
"$cs" sweep >/dev/null 2>&1
check "sweep without a spec is status 2" '[ $? -eq 2 ]'

for spec in lhs grid mc; do
    for t in 1 2; do
        "$cs" sweep "tests/sweep/$spec.yaml" -o "$tmp/$spec-$t" --threads "$t" >"$tmp/$spec-$t.out" 2>"$tmp/$spec-$t.err"
        check "$spec on $t threads exits 0" '[ $? -eq 0 ] || { cat "$tmp/$spec-$t.err"; false; }'
    done
    for f in runs.csv summary.md summary.json; do
        check "$spec: $f the same on 1 and 2 threads" 'cmp "$tmp/$spec-1/$f" "$tmp/$spec-2/$f"'
    done
    check "$spec: no run failed" 'grep -q "; 0 did not run to the end" "$tmp/$spec-1.out"'
    check "$spec: progress as plain lines" 'grep -q "^sweep: [0-9]*/[0-9]* runs (100%)" "$tmp/$spec-1.err"'
done

runs="$tmp/lhs-1/runs.csv"
check "runs.csv: 4 runs and a header" '[ "$(wc -l <"$runs")" -eq 5 ]'
check "runs.csv: inputs in SI with units" 'head -1 "$runs" | grep -q "^run,barrier.soil.soil_pressure \[Pa\],barrier.posts\[0\].yield_stress \[Pa\],scenario.speed \[m/s\],outcome,astm_f2656,"'
check "runs.csv: responses" 'head -1 "$runs" | grep -q "max_dynamic_penetration \[m\].*events_cable_break.*,error$"'
check "runs.csv: rows in run order" '[ "$(cut -d, -f1 "$runs" | tail -n +2 | tr "\n" " ")" = "0 1 2 3 " ]'
check "runs.csv: speeds within 38-42 mph" 'awk -F, "NR > 1 && (\$4 < 38 * 0.44704 || \$4 > 42 * 0.44704) { bad = 1 } END { exit bad }" "$runs"'
check "runs.csv: soil pressure above its 4000-psf minimum" 'awk -F, "NR > 1 && \$2 < 4000 * 47.880258 { bad = 1 } END { exit bad }" "$runs"'
check "runs.csv: an ASTM label per run" '[ "$(cut -d, -f6 "$runs" | tail -n +2 | grep -cE "^(none|(C|PU|M|H)[0-9]+/P[1-4])$")" -eq 4 ]'
check "summary.json: Wilson intervals and Spearman" 'grep -q "\"breakthrough\":{\"count\":0,\"p\":0,\"ci95\":\[0,0.48" "$tmp/lhs-1/summary.json" && grep -q "\"spearman\":{\"max_50ms_decel_g\":{\"barrier.soil.soil_pressure\":" "$tmp/lhs-1/summary.json"'
check "summary.md: outcome table" 'grep -q "^| penetration > 1 m (or breakthrough) | " "$tmp/lhs-1/summary.md" && grep -q "^## Input importance" "$tmp/lhs-1/summary.md"'
check "grid: 3 x 2 runs, last variable fastest" '[ "$(cut -d, -f3 "$tmp/grid-1/runs.csv" | tail -n +2 | tr "\n" " ")" = "SD-STD-02.01 PU SD-STD-02.01 PU SD-STD-02.01 PU " ]'
check "grid: the PU run is rated as a PU" 'grep -q ",PU,time_limit,PU40/P1," "$tmp/grid-1/runs.csv"'
check "grid: a text input has no Spearman" 'grep -q "\"vehicle\":null" "$tmp/grid-1/summary.json"'

# runs.nc: one variable of it, a value a line, at full precision
nc_column() { ncdump -p 9,17 -v "$2" "$1" | sed -n "/^ $2 = /,/;/p" | sed "s/^ $2 = //; s/;//" | tr ',' '\n' | tr -d ' ' | grep -v '^$'; }
for t in 1 2; do
    "$cs" sweep tests/sweep/lhs.yaml -o "$tmp/nc-$t" --threads "$t" --netcdf --quiet >"$tmp/nc-$t.out" 2>&1
    check "lhs --netcdf on $t threads exits 0" '[ $? -eq 0 ] || { cat "$tmp/nc-$t.out"; false; }'
done
nc="$tmp/nc-1/runs.nc"
check "runs.nc the same on 1 and 2 threads" 'cmp "$tmp/nc-1/runs.nc" "$tmp/nc-2/runs.nc"'
check "runs.csv the same with --netcdf" 'cmp "$tmp/nc-1/runs.csv" "$runs"'
check "runs.nc: as many runs as runs.csv" '[ "$(ncdump -h "$nc" | grep -oE "^\s*run = [0-9]+" | grep -oE "[0-9]+")" -eq "$(($(wc -l <"$runs") - 1))" ]'
check "runs.nc: runs.csv's speeds, within 38-42 mph" 'paste -d, <(nc_column "$nc" scenario_speed) <(cut -d, -f4 "$runs" | tail -n +2) | awk -F, "\$1 < 38 * 0.44704 || \$1 > 42 * 0.44704 || \$1 != \$2 { bad = 1 } END { exit bad || NR != 4 }"'
check "runs.nc: runs.csv's penetrations in full (the CSV's 10 digits)" 'paste -d, <(nc_column "$nc" max_dynamic_penetration) <(cut -d, -f10 "$runs" | tail -n +2) | awk -F, "!(\$1 > 0.05) || (\$1 - \$2) ^ 2 > (5e-10 * \$2) ^ 2 { bad = 1 } END { exit bad || NR != 4 }"'
check "runs.nc: units and CF" 'ncdump -h "$nc" | grep -q "scenario_speed:units = \"m/s\"" && ncdump -h "$nc" | grep -q ":Conventions = \"CF-1.8\""'
sed "s|^model: .*|model: $PWD/examples/aps3.yaml|; s|^seed: 7|&\nnetcdf: true|" tests/sweep/lhs.yaml >"$tmp/lhs-nc.yaml"
"$cs" sweep "$tmp/lhs-nc.yaml" -o "$tmp/nc-spec" --quiet >/dev/null 2>&1
check "netcdf: true in the spec writes runs.nc, the same runs" '[ "$(nc_column "$tmp/nc-spec/runs.nc" scenario_speed | tr "\n" " ")" = "$(nc_column "$nc" scenario_speed | tr "\n" " ")" ]'
check "no runs.nc unless asked" '[ ! -e "$tmp/lhs-1/runs.nc" ]'
mkdir -p "$tmp/nc-fail/runs.nc.tmp"
out=$("$cs" sweep tests/sweep/lhs.yaml -o "$tmp/nc-fail" --netcdf --quiet 2>&1)
check "a runs.nc that cannot be written: status 1, why, nothing written" '[ $? -eq 1 ] && grep -q "nothing written: .*/runs.nc: creating the file: Is a directory" <<<"$out" && [ "$(ls -A "$tmp/nc-fail")" = runs.nc.tmp ]'

# --runs, --seed and --t-end from the command line; a different seed gives other inputs
"$cs" sweep tests/sweep/mc.yaml -o "$tmp/mc-seed" --runs 3 --seed 99 --t-end "5 ms" --quiet >/dev/null 2>&1
check "--runs --seed --t-end" '[ "$(wc -l <"$tmp/mc-seed/runs.csv")" -eq 4 ] && ! cmp -s <(head -2 "$tmp/mc-seed/runs.csv") <(head -2 "$tmp/mc-1/runs.csv") && grep -q "scenario.t_end=5 ms" "$tmp/mc-seed/summary.json"'
check "--runs on a grid is refused" '! "$cs" sweep tests/sweep/grid.yaml -o "$tmp/x" --runs 3 >/dev/null 2>&1'

# `cablesim check` knows a spec from a model, and checks the spec's model with its values
check "check a spec" '"$cs" check tests/sweep/lhs.yaml | grep -q "tests/sweep/lhs.yaml: a valid sweep spec: Latin hypercube of 4 runs over 3 values"'
check "check the example spec" '"$cs" check examples/aps3-uncertain.yaml >/dev/null'
check "check a bad spec" '"$cs" check tests/sweep/bad/bad_level.yaml 2>&1 | grep -q "^tests/sweep/bad/bad_level.yaml:6:42: "'

files=0
for f in tests/sweep/bad/*.yaml; do
    files=$((files + 1))
    out=$("$cs" sweep "$f" -o "$tmp/bad" 2>&1)
    expect_problems "$f" "$out" $?
done
check "bad specs wrote nothing" '[ ! -e "$tmp/bad" ]'
check "at least 15 bad specs" '[ "$files" -ge 15 ]'
finish
