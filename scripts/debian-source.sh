# SPDX-License-Identifier: MIT
# Sourced by the scripts that compile a Debian library for the designer page's WebAssembly
# (wasm-libyaml.sh, wasm-jsonc.sh): debian_source OUT SOURCE BINARY fetches Debian's source package SOURCE
# of the version the machine's BINARY package was built from (else the index's own, a point release the
# mirror has moved past) with apt-get source into OUT/src, and prints its folder. Nothing is installed
# and the machine's apt configuration is left as it is: the source index is read into OUT/apt from
# deb-src twins of the machine's own Debian sources.
debian_source() {
  local out=$1 package=$2 binary=$3 f
  local apt="$out/apt"
  rm -rf "$apt" "$out/src"
  mkdir -p "$apt/parts" "$apt/lists/partial" "$apt/cache/archives/partial" "$out/src"
  # The machine's Debian sources, as deb-src (deb822 files and one-line lists alike).
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && grep -q '^URIs:.*debian' "$f" && sed 's/^Types:.*/Types: deb-src/' "$f" >"$apt/parts/$(basename "$f")"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] && grep -E '^deb .*debian' "$f" | sed 's/^deb /deb-src /' >>"$apt/parts/debian-src.list" || true
  done
  local opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt/parts" -o "Dir::State::Lists=$apt/lists"
    -o "Dir::Cache=$apt/cache" -o "APT::Sandbox::User=root" -o "Debug::NoLocking=1" -qq)
  apt-get "${opts[@]}" update >&2
  local version
  version=$(dpkg-query -W -f '${source:Version}' "$binary" 2>/dev/null || true)
  (cd "$out/src" && { apt-get "${opts[@]}" source "$package${version:+=$version}" >/dev/null 2>&1 ||
    apt-get "${opts[@]}" source "$package" >/dev/null; })
  local dir
  dir=$(find "$out/src" -maxdepth 1 -mindepth 1 -type d -name "$package-*" | head -1)
  [ -n "$dir" ] || { echo "debian-source.sh: no $package source in $out/src" >&2; return 1; }
  echo "$dir"
}

# wasm_args OUT [EMCC]: the arguments of a wasm-*.sh script into out (made, absolute) and emcc (default
# emcc), and the node modules Debian's emscripten looks for (see web/build.sh).
wasm_args() {
  out=$(mkdir -p "$1" && cd "$1" && pwd)
  emcc=${2:-emcc}
  export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs:/usr/lib/nodejs
}
