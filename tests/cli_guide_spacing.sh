#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# docs/guide.md's paragraph on the design chart of examples/roadside/spacing-study.yaml says what the
# study's runs give: each number and count it quotes is read from the paragraph itself and checked against
# the study's runs.csv, so the test fails when the prose and the engine part. Each deflection ("2.75 m at
# 3 m", driven or in footings, the mounting told apart by the footing diameters the paragraph names) is the
# run's max_barrier_deflection to the 2 decimals printed; the steps where the deflection falls are those
# the paragraph quotes as falling, and it grows from the smallest spacing quoted to the largest, the
# study's ends; "the footings take off A-B m" is the least and the most of driven minus footings over the
# spacings; "all N runs are redirected", each run to its end; the events it names in italics for a mounting
# happen in every run of it, "several" posts slide in each driven run, in footings "none starts to slide" or
# "up to N", and no post comes out. A number or phrase the test no longer finds in the paragraph fails it: the test is then updated
# with the prose. The guide's numbers are those of musl's maths (the default build, CMakeLists.txt CS_MATH);
# a build with glibc's, which differ in the fourth digit (docs/testing.md), skips (77).
source "$(dirname "$0")/lib.sh"
if [ "${CS_MATH_USED:-musl}" != musl ]; then
    echo "the engine's maths are ${CS_MATH_USED}'s: the guide quotes musl's to the last digit printed: skipped"
    exit 77
fi
"$cs" sweep examples/roadside/spacing-study.yaml -o "$tmp/study" --threads 1 >"$tmp/sweep.out" 2>"$tmp/sweep.err"
check "the study runs (exit 0), each run to its end" '[ $? -eq 0 ] && grep -q "; 0 did not run to the end$" "$tmp/sweep.out" || { cat "$tmp/sweep.err"; false; }'
# the paragraph, one line: from its first words to the blank line after it
awk '/^The design chart of `spacing-study.yaml`/ { on = 1 } on && /^$/ { exit } on' docs/guide.md | tr '\n' ' ' >"$tmp/para.txt"
check "the paragraph is in docs/guide.md" '[ -s "$tmp/para.txt" ]'

# Each claim of the paragraph against the runs: a line "ok<TAB>what" or "FAIL<TAB>what (why)" per claim.
awk -F, '
function say(good, what) { printf "%s\t%s\n", good ? "ok" : "FAIL", what }
function need(pattern, what) {
    if (match(P, pattern)) return substr(P, RSTART, RLENGTH)
    say(0, "the paragraph no longer says " what ": update this test with it")
    return ""
}
function r2(x) { return sprintf("%.2f", x) }
FILENAME ~ /para.txt$/ { P = $0; next }
FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    mm = int($col["barrier.posts[0].footing.diameter [m]"] * 1000 + 0.5)
    s = $col["barrier.posts[0].spacing [m]"] + 0
    runs++
    run_mm[runs] = mm; run_row[runs] = $0
    defl[mm, s] = $col["max_barrier_deflection [m]"]
    if ($col["outcome"] == "redirected") redirected++
    if ($col["error"] != "") errors++
    if (!(s in seen)) { seen[s] = 1; ns++; sp[ns] = s }
}
function ev(r, name, f) { split(run_row[r], f, ","); return f[col["events_" name]] + 0 }
END {
    # the mountings by the footing diameters the paragraph names
    d = need("[0-9]+-mm flange", "the driven posts\047 \"N-mm flange\""); mount_mm["driven"] = d + 0
    d = need("[0-9]+-mm concrete footings", "\"N-mm concrete footings\""); mount_mm["footings"] = d + 0
    bad = 0
    for (r = 1; r <= runs; r++)
        if (run_mm[r] != mount_mm["driven"] && run_mm[r] != mount_mm["footings"]) bad++
    say(runs > 0 && bad == 0, "every run is driven (" mount_mm["driven"] " mm) or in footings (" mount_mm["footings"] " mm): " bad " of " runs " neither")
    # the spacings in order
    for (i = 2; i <= ns; i++) for (j = i; j > 1 && sp[j - 1] > sp[j]; j--) { swap = sp[j]; sp[j] = sp[j - 1]; sp[j - 1] = swap }

    # "all N runs are redirected", and none failed
    c = need("all [0-9]+ runs are redirected", "\"all N runs are redirected\"")
    if (c != "") { split(c, w, " "); say(w[2] == runs && w[2] == redirected && errors == 0, c ": " runs " runs, " redirected " redirected, " errors + 0 " with an error") }

    # each "X m at S m" (the mounting the last "driven" or "in footings" before it), and each "X m driven" or
    # "X m in footings" followed by "at S m"
    n = split(P, t, " ")
    for (i = 1; i <= n; i++) { x = t[i]; gsub(/^[(*`]+|[,;:.)*`]+$/, "", x); t[i] = x }
    mode = ""; np = 0; nc = 0; decimals = 0
    for (i = 1; i <= n; i++) {
        x = t[i]
        if (x == "driven") mode = "driven"
        if (x == "footings" && t[i - 1] == "in") mode = "footings"
        if (x == "at" && np > 0 && t[i + 1] ~ /^[0-9.]+$/ && t[i + 2] == "m") {
            for (k = 1; k <= np; k++) { nc++; cm[nc] = pm[k]; cv[nc] = pv[k]; cs[nc] = t[i + 1] + 0 }
            np = 0
        }
        if (x !~ /^[0-9]+\.[0-9]+$/) continue
        decimals++
        if (t[i + 1] != "m") continue
        if (t[i + 2] == "at" && t[i + 3] ~ /^[0-9.]+$/ && t[i + 4] == "m") { nc++; cm[nc] = mode; cv[nc] = x; cs[nc] = t[i + 3] + 0 }
        else if (t[i + 2] == "driven") { np++; pm[np] = "driven"; pv[np] = x }
        else if (t[i + 2] == "in" && t[i + 3] == "footings") { np++; pm[np] = "footings"; pv[np] = x }
    }
    say(nc > 0 && nc == decimals, "every decimal number of the paragraph is read as a deflection: " nc " of " decimals)
    lo = ""; hi = ""
    for (k = 1; k <= nc; k++) {
        key = mount_mm[cm[k]] SUBSEP cs[k]
        got = (key in defl) ? r2(defl[key]) : "no such run"
        say(cm[k] != "" && got == cv[k], cm[k] " at " cs[k] " m: " cv[k] " m (the run: " got ")")
        quoted[cm[k], cs[k]] = cv[k]
        if (lo == "" || cs[k] < lo) lo = cs[k]
        if (hi == "" || cs[k] > hi) hi = cs[k]
    }
    # the ends quoted are those of the study, the deflection grows between them, and it falls at the steps quoted
    # as falling (two neighbouring spacings quoted, the larger lower) and at no other
    say(lo == sp[1] && hi == sp[ns], "the spacings quoted run from " lo " to " hi " m, the study\047s " sp[1] " to " sp[ns] " m")
    for (m in mount_mm) {
        a = mount_mm[m]
        say(defl[a, sp[ns]] > defl[a, sp[1]], m ": the deflection grows from " sp[1] " to " sp[ns] " m")
        runs_fall = ""; quoted_fall = ""
        for (i = 1; i < ns; i++) {
            if (defl[a, sp[i + 1]] < defl[a, sp[i]]) runs_fall = runs_fall " " sp[i] "-" sp[i + 1]
            if (((m, sp[i]) in quoted) && ((m, sp[i + 1]) in quoted) && quoted[m, sp[i + 1]] < quoted[m, sp[i]])
                quoted_fall = quoted_fall " " sp[i] "-" sp[i + 1]
        }
        say(runs_fall == quoted_fall, m ": it falls at the steps quoted, (" quoted_fall " ) m; the runs: (" runs_fall " ) m")
    }

    # "the footings take off A-B m": the least and the most of driven minus footings
    c = need("take off [0-9.]+-[0-9.]+ m", "\"the footings take off A-B m\"")
    if (c != "") {
        split(c, w, /[ -]/)
        dlo = ""; dhi = ""
        for (i = 1; i <= ns; i++) {
            dd = defl[mount_mm["driven"], sp[i]] - defl[mount_mm["footings"], sp[i]]
            if (dlo == "" || dd < dlo) dlo = dd
            if (dhi == "" || dd > dhi) dhi = dd
        }
        say(w[3] == r2(dlo) && w[4] == r2(dhi), "the footings take off " w[3] "-" w[4] " m (the runs: " r2(dlo) "-" r2(dhi) " m)")
    }

    # the mechanisms: the driven clause (after the range, to "; in its footing") and the footings clause
    split_at = index(P, "; in its footing")
    if (split_at == 0 || c == "") { say(0, "the paragraph no longer has its driven and footings clauses: update this test with it"); exit }
    clause["driven"] = substr(P, index(P, c) + length(c), split_at - index(P, c) - length(c))
    clause["footings"] = substr(P, split_at)
    for (m in clause) {
        rest = clause[m]; named = 0
        while (match(rest, /\*[a-z_]+\*/)) {
            name = substr(rest, RSTART + 1, RLENGTH - 2); rest = substr(rest, RSTART + RLENGTH); named++
            bad = (("events_" name) in col) ? 0 : -1
            for (r = 1; r <= runs && bad == 0; r++) if (run_mm[r] == mount_mm[m] && ev(r, name) == 0) bad = 1
            say(bad == 0, m ": *" name "* in every run" (bad < 0 ? " (no such event)" : ""))
        }
        say(named > 0, m ": the paragraph names its events in italics")
    }
    most = 0; least = ""; out = 0
    for (r = 1; r <= runs; r++) {
        out += ev(r, "post_pullout")
        if (run_mm[r] == mount_mm["footings"] && ev(r, "post_withdrawal") > most) most = ev(r, "post_withdrawal")
        if (run_mm[r] == mount_mm["driven"] && (least == "" || ev(r, "post_withdrawal") < least)) least = ev(r, "post_withdrawal")
    }
    if (need("several posts by the impact start to slide", "that several driven posts start to slide") != "")
        say(least >= 2, "driven: several posts start to slide in every run (the least: " least ")")
    # in footings either "none starts to slide" (no run has a *post_withdrawal*) or "up to N start to slide"
    if (match(P, /none starts to slide/)) say(most == 0, "footings: none starts to slide (the runs: up to " most ")")
    else {
        c = need("up to [0-9]+ start to slide", "\"none starts to slide\" or \"up to N start to slide\" in footings")
        if (c != "") { split(c, w, " "); say(w[3] == most, "footings: up to " w[3] " start to slide (the runs: up to " most ")") }
    }
    if (need("none all the way", "that no driven post slides all the way out") != "" &&
        need("none comes out", "that no post in a footing comes out") != "")
        say(out == 0, "no post comes out (*post_pullout*): " out " in all")
}' "$tmp/para.txt" "$tmp/study/runs.csv" >"$tmp/claims.txt"
check "the claims are read (awk exit 0)" '[ $? -eq 0 ]'
while IFS=$'\t' read -r verdict what; do
    check "guide: $what" '[ "$verdict" = ok ]'
    [ "$verdict" = ok ] && echo "ok: $what"
done <"$tmp/claims.txt"
finish
