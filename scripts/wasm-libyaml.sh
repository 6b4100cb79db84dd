#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# libyaml for the designer page's WebAssembly: Debian's source package of the libyaml the command links
# (libyaml-0-2), fetched with apt-get source into OUT and compiled with emcc into OUT/libyaml.a, its
# header in OUT/include. Nothing is installed and the machine's apt configuration is left as it is: the
# source index is read into OUT/apt from deb-src twins of the machine's own Debian sources. Runs once per
# build tree (OUT/libyaml.a kept).
#   bash scripts/wasm-libyaml.sh OUT [EMCC]
set -euo pipefail
out=$(mkdir -p "$1" && cd "$1" && pwd)
emcc=${2:-emcc}
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs:/usr/lib/nodejs # see web/build.sh
[ -f "$out/libyaml.a" ] && exit 0
apt="$out/apt"
rm -rf "$apt" "$out/src"
mkdir -p "$apt/parts" "$apt/lists/partial" "$apt/cache/archives/partial" "$out/src"
# The machine's Debian sources, as deb-src (deb822 files and one-line lists alike).
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && grep -q '^URIs:.*debian' "$f" && sed 's/^Types:.*/Types: deb-src/' "$f" >"$apt/parts/$(basename "$f")"
done
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] && grep -E '^deb .*debian' "$f" | sed 's/^deb /deb-src /' >>"$apt/parts/debian-src.list" || true
done
opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt/parts" -o "Dir::State::Lists=$apt/lists"
  -o "Dir::Cache=$apt/cache" -o "APT::Sandbox::User=root" -o "Debug::NoLocking=1" -qq)
apt-get "${opts[@]}" update
version=$(dpkg-query -W -f '${source:Version}' libyaml-0-2 2>/dev/null || true)
# the command's version, else the index's own (a point release the mirror has moved past)
(cd "$out/src" && { apt-get "${opts[@]}" source "libyaml${version:+=$version}" >/dev/null 2>&1 ||
  apt-get "${opts[@]}" source libyaml >/dev/null; })
src=$(find "$out/src" -maxdepth 1 -mindepth 1 -type d -name 'libyaml-*' | head -1)
[ -n "$src" ] || { echo "wasm-libyaml.sh: no libyaml source in $out/src" >&2; exit 1; }
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
