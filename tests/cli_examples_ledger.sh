#!/usr/bin/env bash
# Every crash-tested example balances its energy ledger within 1% of the initial kinetic energy over the
# whole run (the largest imbalance at any step, summary.json's energy_balance_error).
set -u
cs="$1"
fail=0
for f in examples/aps1.yaml examples/aps3.yaml examples/aps4.yaml; do
  dir=$(mktemp -d)
  if ! "$cs" run "$f" -o "$dir" >/dev/null 2>&1; then echo "FAIL: $f did not run"; fail=1; continue; fi
  err=$(grep -oE '"energy_balance_error":[^,}]*' "$dir/summary.json" | cut -d: -f2)
  if awk -v e="$err" 'BEGIN { exit !(e <= 0.01 && e >= -0.01) }'; then
    echo "ok: $f ledger $err"
  else
    echo "FAIL: $f ledger $err beyond 1%"; fail=1
  fi
  rm -rf "$dir"
done
[ $fail -eq 0 ] && echo "3 passed, 0 failed" || { echo "failures above"; exit 1; }
