#!/usr/bin/env bash
# cablesim validate: the fast parts of the suite (verification, bogie tests) write a report whose
# numbers are the engine's, and the files appear whole (no temporaries left).
source "$(dirname "$0")/lib.sh"
dir="$tmp"
"$cs" validate -o "$dir" --only verification,bogie >/dev/null 2>&1
check "validate exits 0" '[ $? -eq 0 ]'
md="$dir/validation.md"
check "Eq. 21 reproduces Table 4 (B 3 ft, D 6 ft: 39024 lb)" 'grep -q "| 3.00 ft | 6 ft | 39024 lb | 39024 lb |" "$md"'
check "ten bogie rows" '[ "$(grep -c "^| NPGB-" "$md")" -eq 10 ]'
check "the bogie target is judged" 'grep -qE "at least 8 of 10: [0-9]+ of 10, (met|NOT met)" "$md"'
check "csv has a header and ten bogie rows" '[ "$(grep -c "^bogie," "$dir/validation.csv")" -eq 10 ]'
check "no temporaries left" '[ -z "$(ls "$dir" | grep tmp)" ]'
check "no NaN or Inf in the csv" '! grep -qiE "nan|inf" "$dir/validation.csv"'
"$cs" validate --bogus >/dev/null 2>&1
check "unknown option exits 2" '[ $? -eq 2 ]'
finish
