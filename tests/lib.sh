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
