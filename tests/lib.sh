# SPDX-License-Identifier: MIT
# Shared by the command's shell tests (tests/cli_*.sh), sourced after their own comment: $1 is the
# cablesim binary; `check NAME EXPR` counts a pass or prints FAIL; `finish` prints the closing
# "N passed, N failed" line and returns the status. $tmp is a scratch directory removed at exit.
set -u
cs=${1:?usage: bash tests/cli_NAME.sh path/to/cablesim}
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi; }
finish() {
    echo "$pass passed, $fail failed"
    [ "$fail" -eq 0 ]
}
# Under the sanitizers (CS_TEST_SANITIZED=1, which CMake sets on the shell tests of a CS_SANITIZE build) a
# script runs its representative case of each kind, not every repeat of it (docs/testing.md), and says in
# its log what it leaves to the plain suite. `plain_only WHAT` is true in the plain suite, false there.
plain_only() {
    [ -z "${CS_TEST_SANITIZED:-}" ] && return 0
    echo "sanitized build: left to the plain suite: $1"
    return 1
}
# `repeats N FEW WHAT` prints N in the plain suite, FEW under the sanitizers: the number of like runs (WHAT)
# a case makes.
repeats() {
    if [ -z "${CS_TEST_SANITIZED:-}" ]; then
        echo "$1"
    else
        echo "sanitized build: $2 $3, not the plain suite's $1" >&2
        echo "$2"
    fi
}

# expect_problems FILE OUTPUT STATUS: the command refused FILE (status 2) and reported exactly the
# problems its "# expect: LINE:COL: text" lines name, at those places; counts a pass or a failure.
expect_problems() {
    local f=$1 out=$2 rc=$3 good=1 expected=0 line spec pos text got
    if [ "$rc" -ne 2 ]; then
        echo "FAIL $f: exit status $rc (expected 2)"
        good=0
    fi
    while IFS= read -r line; do
        spec=${line#"# expect: "}
        pos=${spec%%: *}
        text=${spec#*: }
        expected=$((expected + 1))
        if ! grep -F -- "$f:$pos: " <<<"$out" | grep -qF -- "$text"; then
            echo "FAIL $f: no problem '$text' at $pos"
            good=0
        fi
    done < <(grep '^# expect: ' "$f")
    got=$(grep -c "^$f:[0-9]*:[0-9]*: " <<<"$out")
    if [ "$expected" -eq 0 ] || [ "$got" -ne "$expected" ]; then
        echo "FAIL $f: $got problems reported, $expected expected"
        good=0
    fi
    if [ "$good" -eq 1 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "$out"; fi
}
