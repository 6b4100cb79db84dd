#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The source tree's layers (docs/guide.md, "Layout"): every #include under src/ goes down or stays in
# its layer, never up. The engine's layers, bottom up: src/core, src/elements, src/solver, src/run (the
# order of CMakeLists.txt's CS_ENGINE_LAYERS); the loaders and writers (src/io) sit above them all but
# reach the engine only through its public headers (include/cablesim), never into a layer's internal
# ones, but for src/run/sized.h, the one check of the structs filled or read at their caller's size, that
# src/io/status.h shares. A quoted include is resolved as the compiler does (the including file's folder,
# then src/ for the engine and src/io/ for the loaders and writers, then include/); one that resolves
# nowhere fails too.
# The check is also run on a small tree with an include up a layer, one from src/io into an engine layer,
# one that resolves nowhere and a file in no layer, and must find each of them and nothing else.
source "$(dirname "$0")/lib.sh"

layers=(core elements solver run)

# rank ROOT PATH: the layer rank of a file under ROOT into $r: 0 core .. 3 run, 4 io, -1 the public
# headers, empty for a file in no layer
rank() {
    local rel=${2#"$1"/} k
    r=""
    case $rel in
    include/cablesim/*) r=-1 && return ;;
    src/io/*) r=4 && return ;;
    esac
    for k in "${!layers[@]}"; do
        [[ $rel == src/${layers[$k]}/* ]] && r=$k && return
    done
    return 0
}

# violations ROOT: one line for each include under ROOT/src that goes up a layer, from src/io into an
# engine layer's headers, or resolves nowhere; and for each file under ROOT/src in no layer
violations() {
    local root=$1 f from line text name to target d r
    while IFS= read -r f; do
        rank "$root" "$f"
        [ -n "$r" ] || echo "${f#"$root"/}: in no layer"
    done < <(find "$root/src" -type f -name '*.[ch]' | sort)
    while IFS=: read -r f line text; do
        rank "$root" "$f"
        from=$r
        [ -n "$from" ] || continue
        [[ $text =~ \"([^\"]+)\" ]] && name=${BASH_REMATCH[1]}
        target=""
        for d in "${f%/*}" "$root/src" "$root/src/io" "$root/include"; do
            [ -f "$d/$name" ] && target=$d/$name && break
        done
        if [ -z "$target" ]; then
            echo "${f#"$root"/}:$line: \"$name\" is no file of the tree"
            continue
        fi
        target=$(realpath -m "$target")
        rank "$(realpath -m "$root")" "$target"
        to=$r
        if [ "$from" -eq 4 ] && [ "${target#"$(realpath -m "$root")"/}" = src/run/sized.h ]; then
            continue # the one size check of the structs filled at their caller's size (src/io/status.h)
        fi
        if [ -z "$to" ]; then
            echo "${f#"$root"/}:$line: \"$name\" is in no layer"
        elif [ "$from" -eq 4 ] && [ "$to" -ge 0 ] && [ "$to" -lt 4 ]; then
            echo "${f#"$root"/}:$line: \"$name\": src/io reaches the engine only through include/cablesim"
        elif [ "$to" -gt "$from" ]; then
            echo "${f#"$root"/}:$line: \"$name\" is a layer up"
        fi
    done < <(grep -rnE --include='*.[ch]' '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$root/src" | sort)
}

here=$(cd "$(dirname "$0")/.." && pwd)
found=$(violations "$here")
check "every include under src/ goes down a layer or stays in its own" '[ -z "$found" ] || { echo "$found"; false; }'
cmake_layers=$(grep -oE '^set\(CS_ENGINE_LAYERS [a-z ]+\)' "$here/CMakeLists.txt" | sed -E 's/^set\(CS_ENGINE_LAYERS (.*)\)/\1/')
check "the layers are CMakeLists.txt's CS_ENGINE_LAYERS, in its order" '[ "$cmake_layers" = "${layers[*]}" ]'
check "every layer has its header" 'for l in "${layers[@]}"; do [ -f "$here/src/$l/$l.h" ] || exit 1; done'

# the check itself: a tree with three wrong includes among right ones, and a file in no layer
mkdir -p "$tmp/t/include/cablesim" "$tmp/t/src/core" "$tmp/t/src/elements" "$tmp/t/src/solver" "$tmp/t/src/io/out"
touch "$tmp/t/include/cablesim/cablesim.h" "$tmp/t/src/core/core.h" "$tmp/t/src/solver/work.h" "$tmp/t/src/io/out/csv.h"
printf '#include "cablesim/cablesim.h"\n#include "core/core.h"\n#include "solver/work.h"\n' >"$tmp/t/src/elements/rail.c"
printf '#include "csv.h"\n #  include "core/core.h"\n' >"$tmp/t/src/io/out/csv.c"
printf '#include "work.h"\n' >"$tmp/t/src/core/state.c"
touch "$tmp/t/src/stray.c"
bad=$(violations "$tmp/t")
check "the check finds an include up a layer" 'grep -qxF "src/elements/rail.c:3: \"solver/work.h\" is a layer up" <<<"$bad"'
check "the check finds src/io reaching into an engine layer" 'grep -qF "src/io/out/csv.c:2: \"core/core.h\": src/io reaches" <<<"$bad"'
check "the check finds an include that resolves nowhere" 'grep -qxF "src/core/state.c:1: \"work.h\" is no file of the tree" <<<"$bad"'
check "the check finds a file in no layer" 'grep -q "^src/stray.c: in no layer" <<<"$bad"'
check "and nothing else" '[ "$(wc -l <<<"$bad")" -eq 4 ] || { echo "$bad"; false; }'
finish
