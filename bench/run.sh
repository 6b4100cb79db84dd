#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The benchmarks of docs/performance.md (make bench; not part of make test):
#   1. one APS3 run: engine time (cs_run alone, best of BENCH_REPEAT), steps per second, peak memory, and
#      the whole `cablesim run` as a user pays it (load, settle, run, files; no plots), best of BENCH_REPEAT;
#   2. a Monte Carlo (examples/aps3-uncertain.yaml, BENCH_N runs) on 1 and 2 threads and on 2 MPI ranks;
#   3. cost against barrier length: generated models of 10 to 1,000 posts (bench/gen_posts.sh), each run
#      to BENCH_POSTS_T_END;
#   4. peak memory of the command (/usr/bin/time -v) for a run and for the sweep;
#   5. loading a model of 10,000 and of 100,000 posts, each a group of its own (`cablesim check`);
#   6. instructions of the engine (cs_run) for APS1, APS3, APS4 and the 1,000-post model, counted by
#      valgrind's callgrind: unlike wall times on a shared machine they do not move with the load, so a
#      change of cost shows between two benches (skipped without valgrind, or with BENCH_ICOUNT=0);
#   7. the designer page's times, as make test's browser test last wrote them (if it has run);
#   8. the speed targets of the issues (whole run against the engine, the settle's share, two threads
#      against one, cost per post), each judged from the figures above.
# Each of 1, 2 and 6 also for the build BENCH_BASE names (another engine's build folder, e.g. the previous
# commit's built in its own worktree), run alternately with this one, side by side in the same tables.
# Settings (environment): BUILD (build), BENCH_BASE (empty: none), BENCH_N (1000, the issue's Monte Carlo),
# BENCH_T_END (empty: the model's own, 3 s, or until the truck stops or breaks through), BENCH_POSTS
# ("10 30 100 300 1000"), BENCH_POSTS_T_END (20 ms), BENCH_REPEAT (10), BENCH_POSTS_REPEAT (3),
# BENCH_ICOUNT (1). Writes results/bench/bench.md, prints it and copies it to docs/bench.md, the figures
# docs/performance.md and the README give.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
BASE=${BENCH_BASE:-}
N=${BENCH_N:-1000}
T_END=${BENCH_T_END:-}
POSTS=${BENCH_POSTS:-10 30 100 300 1000}
POSTS_T_END=${BENCH_POSTS_T_END:-20 ms}
POSTS_REPEAT=${BENCH_POSTS_REPEAT:-3}
REPEAT=${BENCH_REPEAT:-10}
ICOUNT=${BENCH_ICOUNT:-1}
out=results/bench
# the bench's own folder, made afresh: a run refuses a folder that holds an earlier cablesim's files it
# cannot tell for its own
rm -rf "$out"
mkdir -p "$out"
md="$out/bench.md"
cs="$BUILD/cablesim"
csmpi="$BUILD/cablesim-mpi"
engine="$BUILD/bench_engine"
builds=("$BUILD")
[ -n "$BASE" ] && builds+=("$BASE")
for d in "${builds[@]}"; do
    for b in "$d/cablesim" "$d/bench_engine"; do
        [ -x "$b" ] || { echo "bench: $b is missing (make build first)"; exit 1; }
    done
done
have_time=0
[ -x /usr/bin/time ] && have_time=1
t_end_args=()
[ -n "$T_END" ] && t_end_args=(--t-end "$T_END")

field() { grep -oE "(^| )$1=[^ ]*" <<<"$2" | head -1 | cut -d= -f2; } # key=value, the key whole
peak_kb() { # peak resident memory of a command, from /usr/bin/time -v
    if [ "$have_time" -eq 1 ]; then
        /usr/bin/time -v "$@" 2>&1 >/dev/null | awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }'
    else
        echo "n/a"
    fi
}

{
    echo "# cablesim benchmarks"
    echo
    echo "$(date -u +%Y-%m-%d), load average before: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')),"
    echo "build \`$BUILD\` ($(grep -m1 CMAKE_BUILD_TYPE "$BUILD/CMakeCache.txt" | cut -d= -f2)), $(gcc --version | head -1)."
    echo
} >"$md"

cmd_ms() { # the best wall and the best CPU time (user + sys), ms, of `BUILD/cablesim run examples/aps3.yaml`
    # over REPEAT runs: what a user pays, the process from its start to its end (load, settle, run,
    # files; no plots)
    local best="" cpu="" t
    for _ in $(seq "$REPEAT"); do
        rm -rf "$out/cmd-run"
        t=$({ TIMEFORMAT="%3R %3U %3S"; time "$1/cablesim" run examples/aps3.yaml -o "$out/cmd-run" \
            "${t_end_args[@]}" >/dev/null; } 2>&1)
        read -r best cpu < <(awk -v t="$t" -v b="$best" -v c="$cpu" 'BEGIN { split(t, x, " ")
            w = 1000 * x[1]; u = 1000 * (x[2] + x[3])
            print (b == "" || w < b) ? w : b, (c == "" || u < c) ? u : c }')
    done
    echo "$best $cpu"
}
echo "bench: one APS3 run (best of $REPEAT, each build alternately)..."
declare -A one cmd
for d in "${builds[@]}"; do # warm each build's files first: the first run pays the disk
    "$d/bench_engine" examples/aps3.yaml --repeat 1 "${t_end_args[@]}" >/dev/null
done
for d in "${builds[@]}"; do
    one[$d]=$("$d/bench_engine" examples/aps3.yaml --repeat "$REPEAT" "${t_end_args[@]}")
    cmd[$d]=$(cmd_ms "$d")
done
rss_run=$(peak_kb "$cs" run examples/aps3.yaml -o "$out/aps3" "${t_end_args[@]}")
{
    echo "## One APS3 run"
    echo
    echo "\`BUILD/bench_engine examples/aps3.yaml --repeat $REPEAT${T_END:+ --t-end \"$T_END\"}\` (the engine: \`cs_run\` alone)"
    echo "and \`BUILD/cablesim run examples/aps3.yaml -o DIR${T_END:+ --t-end \"$T_END\"}\` (what a user pays: the process from"
    echo "its start to its end, loading the model, settling the barrier, running and writing the files; no"
    echo "plots), each best of $REPEAT; with two builds, each measured in turn. The settle is the barrier's"
    echo "equilibrium under its pretension before the crash (\`cs_state_create\`, made $REPEAT times by bench_engine)."
    echo
    echo "| build | \`cablesim run\` (best) | its CPU time (best) | engine time (best) | median | CPU time (best) | whole run over the engine (wall, best against best) | whole run over the engine (CPU) | settle (CPU, best) | settle over the engine (CPU) | simulated | steps | steps/s | per step | outcome | load | peak memory (engine / \`cablesim run\`) |"
    echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    for d in "${builds[@]}"; do
        o=${one[$d]}
        rss="n/a"
        [ "$d" = "$BUILD" ] && rss=$rss_run
        read -r wall cpu <<<"${cmd[$d]}"
        ratio=$(awk -v a="$cpu" -v b="$(field cpu_ms_best "$o")" 'BEGIN { printf (b > 0 ? "%.2f" : "n/a"), a / b }')
        wratio=$(awk -v a="$wall" -v b="$(field engine_ms_best "$o")" 'BEGIN { printf (b > 0 ? "%.2f" : "n/a"), a / b }')
        settle=$(field settle_cpu_ms_best "$o")
        share=$(awk -v a="$settle" -v b="$(field cpu_ms_best "$o")" 'BEGIN { printf (a != "" && b > 0 ? "%.1f%%" : "n/a"), 100 * a / b }')
        [ "$d" = "$BUILD" ] && { mine_wratio=$wratio mine_ratio=$ratio mine_share=$share; }
        echo "| \`$d\` | **$wall ms** | $cpu ms | **$(field engine_ms_best "$o") ms** | $(field engine_ms_median "$o") ms | $(field cpu_ms_best "$o") ms | **$wratio** | **$ratio** | ${settle:-n/a} ms | **$share** | $(field t_reached_s "$o") s | $(field steps "$o") | $(field steps_per_s "$o") | $(field us_per_step "$o") us | $(field outcome "$o") | $(field load_ms "$o") ms | $(field peak_rss_kb "$o") kB / $rss kB |"
    done
    echo
} >>"$md"

echo "bench: Monte Carlo of $N runs..."
declare -A mc_wall # each Monte Carlo's wall time, s, by its key
mc_line() { # key, label, command...
    local key=$1 label=$2
    shift 2
    local timed=()
    [ "$have_time" -eq 1 ] && timed=(/usr/bin/time -f "%U %S %M" -o "$out/time.txt")
    echo "n/a n/a n/a" >"$out/time.txt"
    local a b wall rate u s m
    a=$(date +%s%N)
    "${timed[@]}" "$@" >"$out/mc.log" 2>&1 || { echo "| $label | failed | | | | |"; return; }
    b=$(date +%s%N)
    wall=$(awk -v t=$((b - a)) 'BEGIN { printf "%.2f", t / 1e9 }')
    mc_wall[$key]=$wall
    rate=$(awk -v w="$wall" -v n="$N" 'BEGIN { printf "%.1f", n / w }')
    read -r u s m <"$out/time.txt"
    echo "| $label | $wall s | $rate | $(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.1f", u + s }') s | $m kB | $(awk -v w="$wall" -v n="$N" 'BEGIN { printf "%.0f", w / n * 10000 }') s |"
}
spec=examples/aps3-uncertain.yaml
sweep_args=(sweep "$spec" --runs "$N" --quiet "${t_end_args[@]}")
{
    echo "## Monte Carlo: $N runs of examples/aps3-uncertain.yaml${T_END:+ to $T_END}"
    echo
    echo "| how | wall time | runs/s | CPU time (user + sys) | peak memory | 10,000 runs at this rate |"
    echo "| --- | --- | --- | --- | --- | --- |"
    mc_line one "1 thread (\`$cs ${sweep_args[*]} -o $out/mc1 --threads 1\`)" "$cs" "${sweep_args[@]}" -o "$out/mc1" --threads 1
    [ -n "$BASE" ] && mc_line base "1 thread, \`$BASE\` (\`$BASE/cablesim ... --threads 1\`)" "$BASE/cablesim" \
        "${sweep_args[@]}" -o "$out/mc1-base" --threads 1
    mc_line two "2 threads (\`... --threads 2\`)" "$cs" "${sweep_args[@]}" -o "$out/mc2" --threads 2
    if [ -x "$csmpi" ] && command -v mpirun >/dev/null; then
        flags=(--oversubscribe)
        [ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
        mc_line mpi "2 MPI ranks x 1 thread (\`mpirun -n 2 $csmpi ... --threads 1\`)" mpirun "${flags[@]}" -n 2 "$csmpi" \
            "${sweep_args[@]}" -o "$out/mpi2" --threads 1
    else
        echo "| 2 MPI ranks | not run: no cablesim-mpi or mpirun | | | | |"
    fi
    same="identical"
    for d in mc2 mpi2; do
        [ -f "$out/$d/runs.csv" ] && ! cmp -s "$out/mc1/runs.csv" "$out/$d/runs.csv" && same="DIFFERENT ($d)"
    done
    echo
    echo "runs.csv of the three: $same."
    echo
} >>"$md"

echo "bench: cost against barrier length..."
{
    echo "## Cost against barrier length (to $POSTS_T_END)"
    echo
    echo "Generated models (\`bash bench/gen_posts.sh N\`: APS3's line posts at 8 ft, truck at the middle),"
    echo "\`$engine posts-N.yaml --repeat $POSTS_REPEAT --t-end \"$POSTS_T_END\"\`."
    echo
    echo "| posts | engine time (best) | CPU time (best) | steps | per step | per post and step | outcome | load | peak memory |"
    echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    declare -A per_post # ns per post and step, by the number of posts
    for n in $POSTS; do
        bash bench/gen_posts.sh "$n" >"$out/posts-$n.yaml"
        # a run the engine stops (numerical guard) is a result too: its row says so, and the rest go on
        if r=$("$engine" "$out/posts-$n.yaml" --repeat "$POSTS_REPEAT" --t-end "$POSTS_T_END" 2>"$out/posts-$n.err"); then
            per_post[$n]=$(field ns_per_post_step "$r")
            echo "| $n | $(field engine_ms_best "$r") ms | $(field cpu_ms_best "$r") ms | $(field steps "$r") | $(field us_per_step "$r") us | $(field ns_per_post_step "$r") ns | $(field outcome "$r") | $(field load_ms "$r") ms | $(field peak_rss_kb "$r") kB |"
        else
            echo "| $n | failed | | | | | $(tr '\n|' '  ' <"$out/posts-$n.err") | | |"
        fi
    done
    echo
} >>"$md"

echo "bench: loading 10,000 and 100,000 posts..."
{
    echo "## Loading a model of many posts"
    echo
    echo "\`$cs check posts-one-N.yaml\`: bench/gen_posts.sh's model with each post a group of its own (\`x: [...]\`),"
    echo "N lines of YAML; 100,000 posts are past the loader's 10,000 and refused, after the whole file is read"
    echo "and checked. The loader's work is linear in N (tests/test_io_loader_work.c counts it)."
    echo
    echo "| posts | wall time | CPU time (user + sys) | status |"
    echo "| --- | --- | --- | --- |"
    for n in 10000 100000; do
        f="$out/posts-one-$n.yaml"
        bash bench/gen_posts.sh "$n" | awk -v n="$n" -v g="section: CF-I4x1.75, height: 7 ft, attachment: through, \
footing: {diameter: 9 in, depth: 3 ft, rotation_limit: 45 deg, pullout_capacity: 20 kip}" '/^  posts:/ { print
            for (i = 1; i <= n; i++) printf "    - {x: [%d in], %s}\n", 96 + (i - 1) * 3, g
            skip = 1; next } skip && /^  anchors:/ { skip = 0 } !skip' |
            sed -e "s/end: {x: [0-9]* ft/end: {x: $((96 + n * 3)) in/" -e "s/impact_x: [0-9]* ft/impact_x: 100 ft/" >"$f"
        t=$({ TIMEFORMAT="%3R %3U %3S"; time "$cs" check "$f" >/dev/null 2>"$out/posts-one-$n.err" || true; } 2>&1 | tail -1)
        rc=$(grep -q "valid model" "$out/posts-one-$n.err" && echo loaded || echo refused)
        "$cs" check "$f" >/dev/null 2>&1 && rc=loaded
        read -r w u s <<<"$t"
        echo "| $n | $w s | $(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.2f", u + s }') s | $rc |"
    done
    echo
} >>"$md"

icount() { # bench_engine, model, extra arguments...: millions of instructions in cs_run (with link-time
    # optimisation its symbol may carry a suffix, cs_run.constprop.0: hence the pattern; none counted: n/a)
    local bench=$1 model=$2
    shift 2
    valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='cs_run*' "$bench" "$model" \
        --repeat 1 "$@" 2>&1 >/dev/null | awk '/Collected/ && $4 > 0 { printf "%.1f M", $4 / 1e6 }'
}
if [ "$ICOUNT" != 0 ] && command -v valgrind >/dev/null; then
    echo "bench: instructions (callgrind)..."
    big=$(for n in $POSTS; do echo "$n"; done | sort -n | tail -1)
    declare -A count
    for d in "${builds[@]}"; do
        tag=$(tr -c 'A-Za-z0-9\n' _ <<<"$d")
        for m in aps1 aps3 aps4; do
            icount "$d/bench_engine" "examples/$m.yaml" >"$out/icount-$tag-$m.txt" &
        done
        icount "$d/bench_engine" "$out/posts-$big.yaml" --t-end "$POSTS_T_END" >"$out/icount-$tag-posts.txt" &
        wait
        for m in aps1 aps3 aps4 posts; do # a run valgrind could not count says so instead of a blank
            count[$d$m]=$(cat "$out/icount-$tag-$m.txt")
            [ -n "${count[$d$m]}" ] || count[$d$m]="n/a"
        done
    done
    {
        echo "## Instructions of the engine"
        echo
        echo "\`valgrind --tool=callgrind --toggle-collect='cs_run*' BUILD/bench_engine MODEL --repeat 1\`, millions (M) of"
        echo "instructions: the same at any load for the same build (they can differ between CPUs only where"
        echo "the C library picks its math routines by the CPU's features)."
        echo
        echo "| build | APS1 | APS3 | APS4 | $big posts to $POSTS_T_END |"
        echo "| --- | --- | --- | --- | --- |"
        for d in "${builds[@]}"; do
            echo "| \`$d\` | ${count[${d}aps1]} | ${count[${d}aps3]} | ${count[${d}aps4]} | ${count[${d}posts]} |"
        done
        echo
    } >>"$md"
    if command -v callgrind_annotate >/dev/null; then
        echo "bench: where APS3's instructions go..."
        valgrind --tool=callgrind --callgrind-out-file="$out/aps3.callgrind" --toggle-collect='cs_run*' \
            "$engine" examples/aps3.yaml --repeat 1 >/dev/null 2>&1
        {
            echo "## Where APS3's instructions go"
            echo
            echo "The same count for \`$BUILD\`, by function, inclusive (a function's share holds what it calls), the 15"
            echo "largest of the engine's own (\`callgrind_annotate --inclusive=yes\`). Link-time optimisation"
            echo "inlines across files, so a function may be named under the file it was inlined into, and shares"
            echo "overlap."
            echo
            echo "| share of \`cs_run\` | instructions | function (file) |"
            echo "| --- | --- | --- |"
            callgrind_annotate --inclusive=yes --threshold=100 "$out/aps3.callgrind" 2>/dev/null |
                awk '/^ *[0-9,]+ +\(/ { w = $3; if (w !~ /:/) w = $4 } /^ *[0-9,]+ +\(/ && w ~ /(^|\/)src\// {
                    n = $1; gsub(/,/, "", n); sub(/^.*\/src\//, "src/", w); split(w, a, ":")
                    f = a[2]; sub(/\..*/, "", f); if ((a[1] f) in seen) next; seen[a[1] f] = 1
                    if (f == "cs_run") total = n; else if (total > 0 && k++ < 15)
                        printf "| %.1f%% | %.1f M | `%s` (%s) |\n", 100 * n / total, n / 1e6, f, a[1] }'
            echo
        } >>"$md"
    fi
fi
timing="$BUILD/designer-test/timing.json" # written by make test's designer_browser (report/test/designer.mjs)
if [ -f "$timing" ]; then
    {
        echo "## The designer page"
        echo
        echo "One run of examples/aps3.yaml in designer.html in headless chromium, 21 times, as \`make test\`'s"
        echo "designer_browser timed it on $(date -u -r "$timing" '+%Y-%m-%d %H:%M UTC') ($timing): the run (\`cs_run\` in"
        echo "the WebAssembly), the model's load from the page's files, and the whole call the page makes for a"
        echo "change (load, settle, run and summaries; no redrawing)."
        echo
        echo "| in the page | fastest | median |"
        echo "| --- | --- | --- |"
        for part in engine load call; do
            f=$(awk -v p="\"$part\"" '$1 == p":" { on = 1 } on && /"fastest_ms"/ { gsub(/[^0-9.]/, "", $2); f = $2 }
                on && /"median_ms"/ { gsub(/[^0-9.]/, "", $2); print f, $2; exit }' "$timing")
            read -r fast med <<<"$f"
            case $part in engine) what="the run (\`cs_run\`)" ;; load) what="the load" ;; *) what="the whole call" ;; esac
            echo "| $what | ${fast:-n/a} ms | ${med:-n/a} ms |"
        done
        echo
    } >>"$md"
fi

{ # the issues' targets for speed, each judged from the figures above
    verdict() { awk -v x="$1" -v lim="$2" -v op="$3" 'BEGIN { if (x == "" || x == "n/a") print "not measured"
        else if ((op == "le" && x + 0 <= lim) || (op == "ge" && x + 0 >= lim)) print "met"; else print "missed" }'; }
    echo "## Against the targets"
    echo
    echo "| target | measured | verdict |"
    echo "| --- | --- | --- |"
    echo "| a whole APS3 \`cablesim run\` at most 2 times the engine's run (wall, best against best) | ${mine_wratio:-n/a} | $(verdict "${mine_wratio:-}" 2 le) |"
    echo "| the same in CPU time | ${mine_ratio:-n/a} | $(verdict "${mine_ratio:-}" 2 le) |"
    echo "| the settle under 2% of a crash run (CPU) | ${mine_share:-n/a} | $(verdict "${mine_share%\%}" 2 le) |"
    speedup=n/a
    [ -n "${mc_wall[one]:-}" ] && [ -n "${mc_wall[two]:-}" ] &&
        speedup=$(awk -v a="${mc_wall[one]}" -v b="${mc_wall[two]}" 'BEGIN { printf "%.2f", a / b }')
    echo "| 2 threads at least 1.8 times one (the Monte Carlo's wall time) | $speedup | $(verdict "$speedup" 1.8 ge) |"
    sorted=$(for n in "${!per_post[@]}"; do echo "$n"; done | sort -n)
    # from 100 posts up (below, the step's fixed cost is most of a post's share)
    lo=$(awk '$1 >= 100' <<<"$sorted" | head -1) hi=$(tail -1 <<<"$sorted") spread=n/a
    [ -n "$lo" ] && [ "$lo" != "$hi" ] &&
        spread=$(awk -v a="${per_post[$lo]}" -v b="${per_post[$hi]}" 'BEGIN { printf "%.2f", b / a }')
    echo "| time linear in the number of posts: the cost per post and step at $hi posts within 2 times that at $lo | $spread | $(verdict "$spread" 2 le) |"
    echo
} >>"$md"
cat "$md"
cp "$md" docs/bench.md
