#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# json-c for the designer page's WebAssembly: Debian's source package of the json-c the command links
# (libjson-c5), fetched into OUT (debian-source.sh), configured by its own CMake files under emcmake and
# compiled with emcc into OUT/lib/libjson-c.a, its headers in OUT/include/json-c. Runs once per build tree
# (OUT/lib/libjson-c.a kept).
#   bash scripts/wasm-jsonc.sh OUT [EMCC]
set -euo pipefail
. "$(dirname "$0")/debian-source.sh"
wasm_args "$@"
[ -f "$out/lib/libjson-c.a" ] && exit 0
src=$(debian_source "$out" json-c libjson-c5)
emcmake=$(dirname "$(command -v "$emcc")")/emcmake
rm -rf "$out/build"
# installed into OUT alone (its include folder fixed at configure time, not emscripten's sysroot)
"$emcmake" cmake -S "$src" -B "$out/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$out" \
  -DCMAKE_INSTALL_LIBDIR=lib -DCMAKE_INSTALL_INCLUDEDIR=include -DBUILD_SHARED_LIBS=OFF -DBUILD_STATIC_LIBS=ON \
  -DBUILD_TESTING=OFF -DBUILD_APPS=OFF -DDISABLE_WERROR=ON -DDISABLE_THREAD_LOCAL_STORAGE=ON >"$out/configure.log"
cmake --build "$out/build" -j2 --target json-c >"$out/build.log"
cmake --install "$out/build" >"$out/install.log"
[ -f "$out/include/json-c/json.h" ] && [ -f "$out/lib/libjson-c.a" ] || { echo "wasm-jsonc.sh: json-c not installed into $out" >&2; exit 1; }
echo "json-c $(basename "$src" | sed 's/^json-c-//') for WebAssembly: $out/lib/libjson-c.a"
