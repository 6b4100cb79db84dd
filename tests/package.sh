#!/usr/bin/env bash
# The Debian package: `cpack -G DEB` in the build tree makes cablesim_VERSION_ARCH.deb holding, under /usr,
# the library (with its soname link), its headers, pkg-config and CMake files, the command with its manual
# page and bash completion, and the parts library; it depends on the Debian packages of the libraries it
# is linked with. $1 the build tree. Skipped (77) without dpkg-deb.
set -u
build=${1:?usage: bash tests/package.sh BUILD}
for tool in dpkg-deb cpack; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed (bash scripts/install-deps.sh)"; exit 77; }
done
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi; }

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$tmp" >"$tmp/cpack.log" 2>&1
check "cpack -G DEB" '[ $? -eq 0 ] || { cat "$tmp/cpack.log"; false; }'
version=$("$build/cablesim" --version | awk '{print $2}')
deb=$(ls "$tmp"/cablesim_"$version"_*.deb 2>/dev/null | head -1)
check "it made cablesim_${version}_ARCH.deb" '[ -n "$deb" ] && [ -s "$deb" ]'
dpkg-deb -c "$deb" | awk '{print $6 ($7 == "->" ? " -> " $8 : "")}' | sed 's|^\./|/|' >"$tmp/contents"
for f in /usr/include/cablesim/cablesim.h /usr/include/cablesim/def.h /usr/include/cablesim/sim.h \
    /usr/include/cablesim/loader.h /usr/include/cablesim/output.h /usr/include/cablesim/units.h \
    "/usr/lib/.*libcablesim.so.$version" \
    "/usr/lib/.*libcablesim.so.0 -> libcablesim.so.$version" "/usr/lib/.*libcablesim.so -> libcablesim.so.0" \
    /usr/lib/.*libcablesim.a /usr/lib/.*pkgconfig/cablesim.pc /usr/lib/.*cmake/cablesim/cablesimConfig.cmake \
    /usr/lib/.*cmake/cablesim/cablesimTargets.cmake /usr/bin/cablesim /usr/share/man/man1/cablesim.1 \
    /usr/share/bash-completion/completions/cablesim /usr/share/cablesim/vehicles.yaml /usr/share/cablesim/ropes.yaml \
    /usr/share/cablesim/sections.yaml /usr/share/cablesim/rails.yaml /usr/share/cablesim/validation/eq21-table4.csv \
    /usr/share/cablesim/examples/aps3.yaml /usr/share/cablesim/examples/api/post_spacing.c; do
    check "the package holds $f" 'grep -qx "$f" "$tmp/contents"'
done
check "nothing outside /usr" '! grep -v "^/usr" "$tmp/contents" | grep -qv "^/$"'
depends=$(dpkg-deb -f "$deb" Depends)
# The library's own; OpenMP's runtime when the command was linked with gcc's (libgomp).
want=(libc6 libyaml-0-2 libudunits2-0 libcairo2 libnetcdf19)
readelf -d "$build/cablesim" | grep -q "NEEDED.*\[libgomp\.so\.1\]" && want+=(libgomp1)
for p in "${want[@]}"; do
    check "it depends on $p" 'grep -qE "(^|, )$p( |,|$)" <<<"$depends"'
done
check "its name, version and section" \
    '[ "$(dpkg-deb -f "$deb" Package)" = cablesim ] && [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] && [ "$(dpkg-deb -f "$deb" Section)" = science ]'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
