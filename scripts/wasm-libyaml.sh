#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# libyaml for the designer page's WebAssembly: Debian's source package of the libyaml the command links
# (libyaml-0-2), fetched into OUT (debian-source.sh) and compiled with emcc into OUT/libyaml.a, its
# header in OUT/include. Runs once per build tree (OUT/libyaml.a kept).
#   bash scripts/wasm-libyaml.sh OUT [EMCC]
set -euo pipefail
. "$(dirname "$0")/debian-source.sh"
wasm_args "$@"
[ -f "$out/libyaml.a" ] && exit 0
src=$(debian_source "$out" libyaml libyaml-0-2)
v=$(basename "$src" | sed 's/^libyaml-//')
IFS=. read -r major minor patch <<<"$v"
mkdir -p "$out/obj" "$out/include"
for c in "$src"/src/*.c; do
  "$emcc" -O2 -w -DYAML_DECLARE_STATIC -DYAML_VERSION_MAJOR="$major" -DYAML_VERSION_MINOR="$minor" \
    -DYAML_VERSION_PATCH="$patch" -DYAML_VERSION_STRING="\"$v\"" -I"$src/include" -c "$c" -o "$out/obj/$(basename "$c" .c).o"
done
cp "$src/include/yaml.h" "$out/include/"
emar rcs "$out/libyaml.a.tmp" "$out"/obj/*.o
mv "$out/libyaml.a.tmp" "$out/libyaml.a"
echo "libyaml $v for WebAssembly: $out/libyaml.a"
