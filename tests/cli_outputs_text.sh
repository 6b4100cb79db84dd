# SPDX-License-Identifier: MIT
# Outputs that cannot run code (src/io/out/htmltext.c): a CSV text cell that a spreadsheet would take
# for a formula (=, +, -, @, a tab or a carriage return first; not a number) gets a leading ', and reads
# back as it was (sweep --resume); a sweep's summary.md escapes HTML; the terminal shows control
# characters of a user's text (a model's name, a value echoed in a problem) as '?'.
# Usage: bash tests/cli_outputs_text.sh path/to/cablesim
source "$(dirname "$0")/lib.sh"
cs=$(cd "$(dirname "$cs")" && pwd)/$(basename "$cs")
src=$(pwd)
cd "$tmp" || exit 1

cp "$src/examples/aps3.yaml" . # beside the spec: a study's model may not leave its folder
cat >"x<b>.yaml" <<SPEC
model: aps3.yaml
method: grid
set:
  scenario.t_end: 5 ms
vary:
  name: ["=1+2", "@SUM(A1)", "-3", "+4e2", "'=x", "<b>bold"]
SPEC
"$cs" sweep "x<b>.yaml" -o whole --quiet >whole.out 2>&1
check "the sweep runs" '[ $? -eq 0 ] || { cat whole.out; false; }'
check "runs.csv: formulas get a leading ', numbers do not" '[ "$(cut -d, -f2 whole/runs.csv | tr "\n" " ")" = "name '"'"'=1+2 '"'"'@SUM(A1) -3 +4e2 '"''"'=x <b>bold " ]'
CABLESIM_SWEEP_STOP_AFTER=2 "$cs" sweep "x<b>.yaml" -o part --threads 1 --quiet >/dev/null 2>&1
"$cs" sweep --resume part >resume.out 2>&1
check "--resume reads the marked cells back as they were" '[ $? -eq 0 ] && grep -q "2 runs read back" resume.out && cmp -s <(cut -d, -f1-3 whole/runs.csv) <(cut -d, -f1-3 part/runs.csv) || { cat resume.out; false; }'
check "summary.md escapes HTML: the spec's name, the levels, a code span holding <" 'grep -qxF "# Sweep x&lt;b&gt;.yaml" whole/summary.md && grep -qF "| \`name\` | - | levels: =1+2, @SUM(A1), -3, +4e2, '"'"'=x, &lt;b&gt;bold |" whole/summary.md && grep -qF "Written by cablesim $("$cs" --version | cut -d" " -f2): <code>$cs sweep '"'"'x&lt;b&gt;.yaml'"'"' -o whole --quiet</code>" whole/summary.md && ! grep -q "<b>" whole/summary.md'

# compare.csv: a run's label (its folder as given) that looks like a formula; compare reads the runs
"$cs" run "$src/examples/aps3.yaml" -o "=1+2" --t-end "20 ms" >/dev/null 2>&1
"$cs" compare "=1+2" -o cmp >cmp.out 2>&1
check "compare reads the run and marks its label in compare.csv" '[ $? -eq 0 ] && head -1 cmp/compare.csv | grep -qF "\"'"'"'=1+2\"" || cat cmp.out'

# the terminal: a value echoed in a problem, with an escape sequence, shows it as '?'
out=$("$cs" check "$src/tests/good/base.yaml" --set "scenario.speed=$(printf '\033[31m')40 mph" 2>&1)
check "a problem's echoed value shows no control character" '[ $? -eq 2 ] && ! grep -q "$(printf "\033")" <<<"$out" && grep -qF "scenario.speed=?[31m40 mph" <<<"$out"'
out=$("$cs" check "$src/tests/bad/name_control.yaml" --allow-path "$src/tests/good" 2>&1)
check "a name with an escape sequence is refused, and not echoed raw" '[ $? -eq 2 ] && ! grep -q "$(printf "\033")" <<<"$out"'

finish
