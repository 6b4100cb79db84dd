#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every crash-tested example balances its energy ledger within 1% of the initial kinetic energy over the
# whole run (the largest imbalance at any step, summary.json's energy_balance_error).
source "$(dirname "$0")/lib.sh"
for f in examples/aps1.yaml examples/aps3.yaml examples/aps4.yaml; do
  dir="$tmp/$(basename "$f" .yaml)"
  "$cs" run "$f" -o "$dir" >/dev/null 2>&1
  err=$(grep -oE '"energy_balance_error":[^,}]*' "$dir/summary.json" 2>/dev/null | cut -d: -f2)
  echo "$f: ledger ${err:-missing}"
  check "$f balances within 1%" '[ -n "$err" ] && awk -v e="$err" "BEGIN { exit !(e <= 0.01 && e >= -0.01) }"'
done
finish
