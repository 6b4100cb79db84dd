#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Debian packages (debian/, built by scripts/build-deb.sh with DEB_BUILD_OPTIONS=nocheck): lintian
# finds no error and no warning in them; libcablesim1 holds the library under its multiarch directory with
# its soname link, libcablesim-dev its headers, static library, pkg-config and CMake files, cablesim the
# command with its manual pages (compressed), the documents they name and bash completion, cablesim-data
# the parts library and examples; the command's package depends on the libraries it is linked with and
# those it loads by dlopen, the library's has a symbols file and nothing runs ldconfig in a maintainer script; a -dbgsym package holds
# the debug symbols.
# $1 the build tree (its cablesim gives the version). Skipped (77) without dpkg-buildpackage, debhelper or
# lintian.
set -u
build=${1:?usage: bash tests/package.sh BUILD}
for tool in dpkg-buildpackage dh lintian; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed (bash scripts/install-deps.sh)"; exit 77; }
done
pass=0
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi; }

DEB_BUILD_OPTIONS="nocheck parallel=2" bash scripts/build-deb.sh "$tmp" >"$tmp/build.log" 2>&1
check "dpkg-buildpackage -us -uc -b" '[ $? -eq 0 ] || { tail -40 "$tmp/build.log"; false; }'
version=$("$build/cablesim" --version | awk '{print $2}')
arch=$(dpkg-architecture -qDEB_HOST_ARCH)
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
deb() { echo "$tmp/${1}_${version}_${2:-$arch}.deb"; }
for p in libcablesim1 libcablesim-dev cablesim libcablesim1-dbgsym cablesim-dbgsym; do
    check "it made ${p}_${version}_$arch.deb" '[ -s "$(deb "$p")" ]'
done
check "it made cablesim-data_${version}_all.deb" '[ -s "$(deb cablesim-data all)" ]'

lintian --fail-on none --tag-display-limit 0 "$tmp"/*.changes >"$tmp/lintian.txt" 2>&1
errors=$(grep -c "^E: " "$tmp/lintian.txt")
warnings=$(grep -c "^W: " "$tmp/lintian.txt")
echo "lintian: $errors errors, $warnings warnings"
check "lintian: 0 errors, 0 warnings" '[ "$errors" -eq 0 ] && [ "$warnings" -eq 0 ] || { grep "^[EW]: " "$tmp/lintian.txt"; false; }'

contents() { dpkg-deb -c "$(deb "$@")" | awk '{print $6 ($7 == "->" ? " -> " $8 : "")}' | sed 's|^\./|/|'; }
has() { # has PACKAGE [ARCH] PATTERN...: each pattern is a whole line of the package's contents
    local p=$1 a=$arch
    shift
    [ "$1" = all ] && a=all && shift
    local list
    list=$(contents "$p" "$a")
    for f in "$@"; do
        check "$p holds $f" 'grep -qx -- "$f" <<<"$list"'
    done
}
lib=/usr/lib/$multiarch
has libcablesim1 "$lib/libcablesim.so.$version" "$lib/libcablesim.so.1 -> libcablesim.so.$version"
has libcablesim-dev /usr/include/cablesim/cablesim.h /usr/include/cablesim/export.h /usr/include/cablesim/def.h \
    /usr/include/cablesim/sim.h /usr/include/cablesim/loader.h /usr/include/cablesim/output.h \
    /usr/include/cablesim/rating.h /usr/include/cablesim/units.h \
    "$lib/libcablesim.so -> libcablesim.so.1" "$lib/libcablesim.a" "$lib/pkgconfig/cablesim.pc" \
    "$lib/cmake/cablesim/cablesimConfig.cmake" "$lib/cmake/cablesim/cablesimTargets.cmake"
has cablesim /usr/bin/cablesim /usr/share/man/man1/cablesim.1.gz /usr/share/man/man1/cablesim-run.1.gz \
    /usr/share/man/man1/cablesim-sweep.1.gz /usr/share/bash-completion/completions/cablesim
has cablesim-data all /usr/share/cablesim/vehicles.yaml /usr/share/cablesim/ropes.yaml \
    /usr/share/cablesim/sections.yaml /usr/share/cablesim/rails.yaml /usr/share/cablesim/validation/eq21-table4.csv \
    /usr/share/cablesim/examples/aps3.yaml /usr/share/cablesim/examples/api/post_spacing.c
# the documents a manual page names are where it says, in the command's package
dpkg-deb -x "$(deb cablesim)" "$tmp/cablesim-root"
named=$(zcat "$tmp"/cablesim-root/usr/share/man/man1/*.1.gz | grep -o '/usr/share/doc/cablesim/[a-z\\-]*\.md' | tr -d '\\' |
    sort -u)
check "the manual pages name the installed documents (ratings.md among them)" 'grep -qx /usr/share/doc/cablesim/ratings.md <<<"$named"'
for f in $named; do
    check "cablesim holds $f, which a manual page names" '[ -s "$tmp/cablesim-root$f" ]'
done
check "no manual page names a docs/ path of the source tree" '! zcat "$tmp"/cablesim-root/usr/share/man/man1/*.1.gz | grep -q "[^/]docs/"'
check "the library's package has a symbols file naming cs_version" \
    'dpkg-deb --ctrl-tarfile "$(deb libcablesim1)" | tar -xOf - ./symbols | grep -q "^ cs_version@Base"'
check "no maintainer script of the library's, ldconfig by debhelper's trigger" \
    '! dpkg-deb --ctrl-tarfile "$(deb libcablesim1)" | tar -tf - | grep -qE "postinst|postrm" && dpkg-deb --ctrl-tarfile "$(deb libcablesim1)" | tar -xOf - ./triggers | grep -qx "activate-noawait ldconfig"'
dpkg-deb --fsys-tarfile "$(deb cablesim)" | tar -xOf - ./usr/bin/cablesim >"$tmp/cablesim"
check "the command is stripped, its debug symbols in cablesim-dbgsym" \
    '! readelf -S "$tmp/cablesim" | grep -q "\.debug_info" && dpkg-deb -c "$(deb cablesim-dbgsym)" | grep -q "/usr/lib/debug/.build-id/.*\.debug$"'
depends=$(dpkg-deb -f "$(deb cablesim)" Depends)
for p in libc6 libyaml-0-2 libudunits2-0 libcairo2 libfontconfig1 libnetcdf19 cablesim-data; do
    check "cablesim depends on $p" 'grep -qE "(^|, )$p( |,|$)" <<<"$depends"'
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
