#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `cablesim run FILE --plots`: every figure as PNG and SVG (its texts <text> elements) under DIR/plots,
# committed with the other outputs; without --plots no plots directory appears.
source "$(dirname "$0")/lib.sh"

check "--help names --plots" '"$cs" --help | grep -q -- "--plots"'

"$cs" run examples/aps3.yaml -o "$tmp/none" --t-end "20 ms" >/dev/null 2>"$tmp/stderr"
check "a run without --plots exits 0" '[ $? -eq 0 ] || { cat "$tmp/stderr"; false; }'
check "a run without --plots draws nothing" '[ ! -e "$tmp/none/plots" ]'

out="$tmp/aps3"
"$cs" run examples/aps3.yaml --plots -o "$out" --t-end "20 ms" >"$tmp/stdout" 2>"$tmp/stderr"
check "run --plots exits 0" '[ $? -eq 0 ] || { cat "$tmp/stderr"; false; }'
check "the summary names the plots" 'grep -q "plots/\*.png" "$tmp/stdout"'
for f in timeseries.csv events.csv summary.json; do
    check "$f still written" '[ -s "$out/$f" ]'
done
for name in deceleration speed penetration cables posts energy snapshots angles path; do
    check "$name.png is a PNG" '[ "$(head -c 8 "$out/plots/$name.png" | od -An -tx1 | tr -d " \n")" = 89504e470d0a1a0a ]'
    check "$name.svg is an SVG" 'head -c 200 "$out/plots/$name.svg" | grep -q "<svg" && tail -c 20 "$out/plots/$name.svg" | grep -q "</svg>"'
    check "$name.svg's texts are text, not glyphs" 'grep -q "</text>" "$out/plots/$name.svg" && ! grep -q "glyph" "$out/plots/$name.svg"'
done
check "no temporaries left" '[ -z "$(find "$out" -name "*.tmp")" ]'

finish
