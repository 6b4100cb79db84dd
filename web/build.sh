#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The designer page's engine: the engine (src/core, src/elements, src/solver, src/run) and the model
# loader with the writers it needs (src/io/), compiled by emscripten into one JavaScript module with its
# WebAssembly inlined (OUT/cablesim-wasm.js, a factory createCablesim()). libyaml and json-c are
# Debian's, compiled for it by scripts/wasm-libyaml.sh and scripts/wasm-jsonc.sh; the units come from the
# page's table (no udunits2: load/units_udunits.c is left out, web/designer.c stands in for
# cs_units_open).
#   bash web/build.sh SOURCE_DIR OUT [EMCC]
set -euo pipefail
src=$(cd "$1" && pwd)
out=$(mkdir -p "$2" && cd "$2" && pwd)
emcc=${3:-emcc}
emar=$(dirname "$(command -v "$emcc")")/emar
# Debian's emscripten looks for its node modules (acorn) where Debian's nodejs does; a nodejs from
# elsewhere looks elsewhere.
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs:/usr/lib/nodejs
bash "$src/scripts/wasm-libyaml.sh" "$out/libyaml" "$emcc"
bash "$src/scripts/wasm-jsonc.sh" "$out/jsonc" "$emcc"
# the maths functions called, never folded or merged by the compiler: as the command built with
# CS_MATH=musl calls them (CMakeLists.txt), so that both give the same bits
nobuiltin=(-fno-builtin-sin -fno-builtin-cos -fno-builtin-tan -fno-builtin-asin -fno-builtin-atan2 -fno-builtin-tanh
  -fno-builtin-cbrt -fno-builtin-exp -fno-builtin-pow -fno-builtin-hypot)
flags=("${nobuiltin[@]}" -std=c17 -Wall -Wextra -Wpedantic -Werror -O3 -fno-math-errno -fno-trapping-math -D_POSIX_C_SOURCE=200809L
  -I"$src/include" -I"$src/src" -I"$src/src/io" -I"$out/libyaml/include" -I"$out/jsonc/include" -DYAML_DECLARE_STATIC)
io=(load/confine load/convert load/loader load/lstore load/parts load/modelhash load/schema load/units load/yamlload load/yamltree
  load/yamledit out/json out/jsondoc out/csv out/numtext out/report_html out/record out/htmltext out/runinfo out/report study/rating study/occupant study/criteria)
rm -rf "$out/obj"
mkdir -p "$out/obj"
sources=("$src"/src/{core,elements,solver,run}/*.c)
for c in "${io[@]}"; do sources+=("$src/src/io/$c.c"); done
sources+=("$src/web/designer.c")
objs=()
running=0
for c in "${sources[@]}"; do # two at a time: the machine's cores are shared
  o="$out/obj/$(echo "${c#"$src"/}" | tr / _ | sed 's/\.c$/.o/')"
  objs+=("$o")
  "$emcc" "${flags[@]}" -c "$c" -o "$o" &
  running=$((running + 1))
  if [ $running -ge 2 ]; then wait -n; running=$((running - 1)); fi
done
while [ $running -gt 0 ]; do wait -n; running=$((running - 1)); done
rm -f "$out/libcablesim-web.a"
"$emar" rcs "$out/libcablesim-web.a" "${objs[@]}"
exports=_cs_web_open,_cs_web_run,_cs_web_values,_cs_web_edit,_cs_web_parts
"$emcc" -O2 "$out/obj/web_designer.o" "$out/libcablesim-web.a" "$out/libyaml/libyaml.a" "$out/jsonc/lib/libjson-c.a" -o "$out/cablesim-wasm.js.tmp.js" \
  -sMODULARIZE=1 -sEXPORT_NAME=createCablesim -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sFORCE_FILESYSTEM=1 \
  -sENVIRONMENT=web,node -sEXPORTED_FUNCTIONS="[$exports]" -sEXPORTED_RUNTIME_METHODS='[ccall,FS]'
mv "$out/cablesim-wasm.js.tmp.js" "$out/cablesim-wasm.js"
echo "designer engine: $out/cablesim-wasm.js ($(($(stat -c %s "$out/cablesim-wasm.js") / 1024)) KiB)"
