#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A fuzzer of --set: `cablesim check MODEL --set PATH=VALUE` for every numeric field of the schema (read
# from `cablesim schema`, placed in MODEL's first cable, post, rail, anchor and the vehicle and scenario)
# at extreme values (0, -1, 1e-30, 1e30, nan, inf, hex, a huge string, a wrong unit, a bare number), then
# random pairs of them until SECONDS have passed. Each run must end within 20 s with exit status 0 or 2
# and every line it prints on stderr must be a problem at a place (FILE:LINE:COL: or --set PATH=VALUE:) or
# the count of problems. Usage: fuzz/fuzz_set.sh CABLESIM SECONDS [MODEL]
cs=$1 seconds=${2:-60} model=${3:-examples/aps3.yaml}
export CABLESIM_DATA=${CABLESIM_DATA:-$PWD/data}
declare -A prefix=([vehicle]=vehicle. [inertia_box]=vehicle.inertia_box. [soil]=barrier.soil.
    [cable]='barrier.cables[0].' [cable_end]='barrier.cables[0].start.' [posts]='barrier.posts[0].'
    [footing]='barrier.posts[0].footing.' [rail]='barrier.rails[0].' [anchor]=barrier.anchors.start.
    [scenario]=scenario.)
paths=()
while IFS=$'\t' read -r table key unit; do
    [ -n "${prefix[$table]}" ] && paths+=("${prefix[$table]}$key"$'\t'"$unit")
done < <("$cs" schema | awk -F'|' '/^## /{t=$0; sub(/^## /,"",t)} /^\| `/{k=$2; gsub(/[ `]/,"",k); ty=$3
    if (ty ~ /^ *(number|[a-z ]+ \()/ && ty !~ /list/) { u=ty; sub(/.*\(/,"",u); sub(/\).*/,"",u); if (ty ~ /^ *number/) u=""; print t "\t" k "\t" u } }')
huge=$(head -c 5000 /dev/zero | tr '\0' 9)
values() { # the extremes of a field whose SI unit is $1
    local u=$1 s=${1:+ $1}
    printf '%s\n' "0$s" "-1$s" "1e-30$s" "1e30$s" "nan$s" "inf$s" "-inf$s" "0x28$s" "$huge$s" "1 furlongz" "7 kg" "35" "1e308$s" "1e-320$s" ""
}
runs=0 fails=0
one() { # run one check with the --set of $@; count a failure
    local out rc
    out=$(timeout 20 "$cs" check "$model" --allow-path examples "${@/#/--set=}" 2>&1 >/dev/null)
    rc=$?
    runs=$((runs + 1))
    local bad
    bad=$(grep -vE '^([^ :]+:[0-9]+:[0-9]+: |--set |cablesim: .*problems?, nothing run$)' <<<"$out" | head -1)
    if { [ $rc -ne 0 ] && [ $rc -ne 2 ]; } || { [ -n "$out" ] && [ -n "$bad" ]; } || { [ $rc -eq 2 ] && [ -z "$out" ]; }; then
        fails=$((fails + 1))
        echo "FAIL (status $rc): ${*:0:200}" >&2
        echo "${bad:0:300}" >&2
    fi
}
end=$((SECONDS + seconds))
for p in "${paths[@]}"; do
    path=${p%%$'\t'*} unit=${p#*$'\t'}
    while IFS= read -r v; do
        [ $SECONDS -ge $end ] && break 2
        one "$path=$v"
    done < <(values "$unit")
done
mapfile -t all < <(for p in "${paths[@]}"; do values "${p#*$'\t'}" | sed "s|^|${p%%$'\t'*}=|"; done)
while [ $SECONDS -lt $end ]; do
    one "${all[RANDOM % ${#all[@]}]}" "${all[RANDOM % ${#all[@]}]}"
done
echo "fuzz_set: ${#paths[@]} fields, $runs runs in $seconds s, $fails failed"
[ $fails -eq 0 ]
