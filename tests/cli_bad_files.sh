#!/usr/bin/env bash
# Every model in tests/bad/ is refused by `cablesim check` with exit status 2, and the problems it reports
# are exactly those its "# expect: LINE:COL: text" lines name, at those places.
set -u
cs=${1:?usage: bash tests/cli_bad_files.sh path/to/cablesim}
pass=0
fail=0
files=0
for f in tests/bad/*.yaml; do
    files=$((files + 1))
    out=$("$cs" check "$f" 2>&1)
    rc=$?
    ok=1
    if [ "$rc" -ne 2 ]; then echo "FAIL $f: exit status $rc (expected 2)"; ok=0; fi
    expected=0
    while IFS= read -r line; do
        spec=${line#"# expect: "}
        pos=${spec%%: *}
        text=${spec#*: }
        expected=$((expected + 1))
        if ! grep -F -- "$f:$pos: " <<<"$out" | grep -qF -- "$text"; then
            echo "FAIL $f: no problem '$text' at $pos"
            ok=0
        fi
    done < <(grep '^# expect: ' "$f")
    got=$(grep -c "^$f:[0-9]*:[0-9]*: " <<<"$out")
    if [ "$expected" -eq 0 ] || [ "$got" -ne "$expected" ]; then
        echo "FAIL $f: $got problems reported, $expected expected"
        ok=0
    fi
    if [ "$ok" -eq 1 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "$out"; fi
done
if [ "$files" -lt 25 ]; then echo "FAIL: only $files bad files (expected at least 25)"; fail=$((fail + 1)); fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
