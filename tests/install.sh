#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The installed tree on its own: `cmake --install` of the build into a temporary prefix, then, from a
# folder outside the source tree with CABLESIM_DATA unset, the library example (examples/api/) built with
# pkg-config and with CMake's find_package(cablesim), run against the installed libcablesim.so, prints
# what the installed `cablesim run` gives for the same model and --set, and writes the same summary.json;
# the installed command finds its parts library under the prefix, also once the prefix has moved; the
# library exports only what its headers declare, and each header compiles on its own; cablesim(1) and a
# manual page per command, cablesim-COMMAND(1), are installed.
# $1 the build tree, $2 its CMAKE_INSTALL_LIBDIR, $3 the C compiler, $4 flags to compile and link with
# (the sanitizers' in a sanitized build).
set -u
build=${1:?usage: bash tests/install.sh BUILD LIBDIR CC [FLAGS]}
libdir=${2:?}
cc=${3:?}
flags=${4:-}
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi; }
unset CABLESIM_DATA

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1
check "cmake --install into $prefix" '[ $? -eq 0 ] || { cat "$tmp/install.log"; false; }'
lib=$prefix/$libdir
version=$("$build/cablesim" --version | awk '{print $2}')
for f in "$lib/libcablesim.so.$version" "$lib/libcablesim.a" "$lib/pkgconfig/cablesim.pc" \
    "$lib/cmake/cablesim/cablesimConfig.cmake" "$lib/cmake/cablesim/cablesimConfigVersion.cmake" \
    "$lib/cmake/cablesim/cablesimTargets.cmake" "$prefix/bin/cablesim" "$prefix/share/man/man1/cablesim.1" \
    "$prefix/share/bash-completion/completions/cablesim" "$prefix/share/cablesim/vehicles.yaml" \
    "$prefix/share/cablesim/validation/eq21-table4.csv" "$prefix/share/cablesim/examples/aps3.yaml" \
    "$prefix/share/cablesim/examples/api/post_spacing.c" "$prefix/share/cablesim/examples/api/CMakeLists.txt"; do
    check "installed: ${f#"$prefix"/}" '[ -s "$f" ]'
done
check "libcablesim.so -> libcablesim.so.1 -> libcablesim.so.$version" \
    '[ "$(readlink "$lib/libcablesim.so")" = libcablesim.so.1 ] && [ "$(readlink "$lib/libcablesim.so.1")" = "libcablesim.so.$version" ]'
check "its soname is libcablesim.so.1" 'readelf -d "$lib/libcablesim.so.$version" | grep -q "SONAME.*\[libcablesim.so.1\]"'
for h in cablesim def sim loader output units sweep compare rating export; do
    check "installed header cablesim/$h.h" '[ -s "$prefix/include/cablesim/$h.h" ]'
    printf '#include <cablesim/%s.h>\nint cs_test_unit;\n' "$h" >"$tmp/h-$h.c"
    check "cablesim/$h.h compiles on its own (C17, pedantic)" \
        '"$cc" -std=c17 -Wall -Wextra -Wpedantic -Werror -I"$prefix/include" -c "$tmp/h-$h.c" -o "$tmp/h-$h.o"'
done
# The headers declare extern "C" and hold inline defaults: a C++ program includes them as well.
if command -v c++ >/dev/null; then
    printf '#include <cablesim/cablesim.h>\nint cs_test_unit() { return (int)cs_default_post_def().size; }\n' \
        >"$tmp/h.cc"
    check "cablesim/cablesim.h compiles as C++ (C++11, pedantic)" \
        'c++ -std=c++11 -Wall -Wextra -Wpedantic -Werror -I"$prefix/include" -c "$tmp/h.cc" -o "$tmp/h-cc.o"'
fi

# Exported: the functions the headers declare, and nothing else.
nm -D --defined-only "$lib/libcablesim.so" | awk '$2 == "T" {print $3}' | sort >"$tmp/exported"
missing=0
while read -r sym; do
    grep -qE "\b$sym\(" "$prefix"/include/cablesim/*.h || { echo "exported but not declared: $sym"; missing=1; }
done <"$tmp/exported"
check "every exported function is declared in the headers" '[ "$missing" -eq 0 ]'
check "the interface is exported (cs_loader_load, cs_run, cs_write_outputs, cs_version ...)" \
    'for f in cs_loader_create cs_loader_set cs_loader_load cs_loader_build cs_run cs_state_summary cs_record_create cs_record_frame cs_write_outputs cs_version; do grep -qx "$f" "$tmp/exported" || exit 1; done'
check "internals are hidden (cs_arena_alloc, cs_w_num, cs_figures_write)" \
    '! grep -qxE "cs_arena_alloc|cs_w_num|cs_figures_write|cs_data_dir_find" "$tmp/exported"'

# The example, built both ways against the installed tree.
export PKG_CONFIG_PATH=$lib/pkgconfig
check "pkg-config knows cablesim $version" '[ "$(pkg-config --modversion cablesim)" = "$version" ]'
src=$prefix/share/cablesim/examples/api
# shellcheck disable=SC2046,SC2086
"$cc" -std=c17 -Wall -Wextra -Wpedantic -Werror $flags "$src/post_spacing.c" $(pkg-config --cflags --libs cablesim) \
    -o "$tmp/ex-pkgconfig" 2>"$tmp/cc.log"
check "the example builds with pkg-config --cflags --libs cablesim" '[ $? -eq 0 ] || { cat "$tmp/cc.log"; false; }'
cmake -S "$src" -B "$tmp/ex-cmake" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" >"$tmp/cmake.log" 2>&1 && cmake --build "$tmp/ex-cmake" >>"$tmp/cmake.log" 2>&1
check "the example builds with find_package(cablesim) and cablesim::cablesim" '[ $? -eq 0 ] || { cat "$tmp/cmake.log"; false; }'
check "find_package found the installed package" \
    'grep -q "^cablesim_DIR:PATH=$lib/cmake/cablesim$" "$tmp/ex-cmake/CMakeCache.txt"'

mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere" || exit 1
model=$prefix/share/cablesim/examples/aps3.yaml
set=("barrier.posts[0].spacing=6 ft")
"$prefix/bin/cablesim" run "$model" --set "${set[0]}" -o "$tmp/out-cli" >"$tmp/cli.txt" 2>"$tmp/cli.err"
check "the installed cablesim runs the installed example" '[ $? -eq 0 ] || { cat "$tmp/cli.err"; false; }'
outcome=$(grep -o '"outcome":"[a-z_]*"' "$tmp/out-cli/summary.json" | cut -d'"' -f4)
decel=$(sed -n 's/^  max 50-ms deceleration \([0-9.]*\) g at .*/\1/p' "$tmp/cli.txt")
check "cablesim run printed an outcome and a deceleration" '[ -n "$outcome" ] && [ -n "$decel" ]'
for way in pkgconfig cmake; do
    exe=$tmp/ex-$way
    [ "$way" = cmake ] && exe=$tmp/ex-cmake/post_spacing
    LD_LIBRARY_PATH=$lib "$exe" "$model" "6 ft" "$tmp/out-$way" >"$tmp/$way.txt" 2>"$tmp/$way.err"
    check "the example built with $way runs against $lib" '[ $? -eq 0 ] || { cat "$tmp/$way.err"; false; }'
    check "it uses the installed library ($version)" 'grep -q "(libcablesim $version)$" "$tmp/$way.txt"'
    check "its outcome is cablesim run's ($outcome)" 'grep -qx "outcome: $outcome at t = .*" "$tmp/$way.txt"'
    check "its max 50-ms deceleration is cablesim run's ($decel g)" \
        'grep -qx "max 50-ms deceleration: $decel g at t = .*" "$tmp/$way.txt"'
    check "its summary.json is cablesim run's, byte for byte after the first line (the command line)" \
        'cmp -s <(tail -n +2 "$tmp/out-cli/summary.json") <(tail -n +2 "$tmp/out-$way/summary.json")'
    check "and names the same model hash" \
        '[ "$(grep -o "\"model_hash\":\"[0-9a-f]*\"" "$tmp/out-$way/summary.json")" = "$(grep -o "\"model_hash\":\"[0-9a-f]*\"" "$tmp/out-cli/summary.json")" ]'
done
check "the spacing changed the run (6 ft is not the design's 8 ft)" \
    '"$prefix/bin/cablesim" run "$model" -o "$tmp/out-8ft" >/dev/null 2>&1 && ! cmp -s "$tmp/out-8ft/summary.json" "$tmp/out-cli/summary.json"'

# The parts library is the prefix's, found from where the command or the library is, not from the source
# tree; the tree still works once moved.
real=$(cd "$prefix" && pwd -P)
check "the installed cablesim lists its parts from PREFIX/share/cablesim" \
    '"$prefix/bin/cablesim" list >"$tmp/list.txt" 2>&1 && head -1 "$tmp/list.txt" | grep -qx "Parts library: $real/share/cablesim" && grep -q "^  M " "$tmp/list.txt"'
mv "$prefix" "$tmp/moved"
check "moved, it lists the parts from the new place" \
    '"$tmp/moved/bin/cablesim" list 2>&1 | head -1 | grep -qx "Parts library: $(cd "$tmp/moved" && pwd -P)/share/cablesim"'
check "moved, the example finds the parts beside libcablesim.so" \
    'LD_LIBRARY_PATH=$tmp/moved/$libdir "$tmp/ex-pkgconfig" "$tmp/moved/share/cablesim/examples/aps3.yaml" >/dev/null 2>&1'
check "moved, pkg-config gives the new place (the .pc is relocatable)" \
    '[ "$(PKG_CONFIG_PATH=$tmp/moved/$libdir/pkgconfig pkg-config --variable=includedir cablesim)" -ef "$tmp/moved/include" ]'
mkdir -p "$tmp/copy/bin" && cp "$tmp/moved/bin/cablesim" "$tmp/copy/bin/"
"$tmp/copy/bin/cablesim" list >/dev/null 2>"$tmp/none.err"
check "a command with no share/cablesim beside it says how to point at the library" \
    '[ $? -eq 2 ] && grep -q "cannot find the parts library: CABLESIM_DATA is not set and .* does not exist (set CABLESIM_DATA" "$tmp/none.err"'
check "CABLESIM_DATA points it at one" 'CABLESIM_DATA="$tmp/moved/share/cablesim" "$tmp/copy/bin/cablesim" list | grep -q "^  M "'

# The manual pages and the bash completion.
man1=$tmp/moved/share/man/man1/cablesim.1
check "the manual page is cablesim(1) $version, naming CABLESIM_DATA" \
    'grep -q "^\.TH CABLESIM \"1\".*cablesim $version" "$man1" && grep -q "^\.SH ENVIRONMENT" "$man1" && grep -q "CABLESIM_DATA" "$man1" && grep -q "^\.SH SYNOPSIS" "$man1"'
# a page per command, from its --help: its synopsis, its exit status, and cablesim(1) under SEE ALSO
for cmd in run check sweep rate validate compare designer list schema; do
    page=$tmp/moved/share/man/man1/cablesim-$cmd.1
    check "the manual page cablesim-$cmd(1)" \
        'grep -q "^\.TH CABLESIM-${cmd^^} \"1\"" "$page" && sed -n "/^\.SH SYNOPSIS/,/^\.SH DESCRIPTION/p" "$page" | grep -qw "$cmd" && grep -q "Exit status: 0 " "$page" && sed -n "/^\.SH \"SEE ALSO\"/,\$p" "$page" | grep -qx "\.BR cablesim (1),"'
done
check "cablesim(1) names each command's page" '[ "$(grep -c "^\.BR cablesim\\\\-[a-z]* (1)" "$man1")" -eq 9 ]'
completion() { bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _cablesim; echo "${COMPREPLY[*]}"' _ \
    "$tmp/moved/share/bash-completion/completions/cablesim" "$@"; }
check "completion: the commands" '[ "$(completion cablesim r)" = "run rate" ]'
check "completion: a command's options" '[ "$(completion cablesim run --p)" = "--plots" ]'
check "completion: --standard's values" '[ "$(completion cablesim rate x.yaml --standard m)" = "mash" ]'

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
