#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Debian packages from debian/ (debhelper): `bash scripts/build-deb.sh OUT` copies the files git tracks
# (as they are in the work tree) to OUT/cablesim-VERSION and runs `dpkg-buildpackage -us -uc -b` there, so
# the build writes nothing in the source tree; the .deb files, .buildinfo and .changes land in OUT.
# DEB_BUILD_OPTIONS passes through (nocheck: no tests; parallel=N).
set -euo pipefail
out=${1:?usage: bash scripts/build-deb.sh OUT}
root=$(cd "$(dirname "$0")/.." && pwd)
version=$(sed -n 's/^#define CS_VERSION_STRING "\(.*\)"$/\1/p' "$root/include/cablesim/cablesim.h")
src="$out/cablesim-$version"
rm -rf "$src"
mkdir -p "$src"
git -C "$root" ls-files -z | (cd "$root" && xargs -0 tar -cf - --no-recursion) | tar -xf - -C "$src"
cd "$src"
dpkg-buildpackage -us -uc -b
