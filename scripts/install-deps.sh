#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install the Debian packages cablesim needs, only those missing. Safe to run again.
# `--demo`: only what the command and its report page need (make demo); none: everything the tests,
# sanitizers, fuzzers, MPI, the designer page and the package need too (make test).
set -euo pipefail
# The command: the compiler and CMake; libyaml (models), udunits2 (units), cairo (plots), netCDF (a
# sweep's runs.nc), json-c (the JSON files, written and read); help2man: the manual page, made from --help at
# build time. report.html (report/): node and npm build its page (Debian's only where none is installed:
# a newer one may be).
pkgs=(build-essential cmake pkg-config libyaml-dev libudunits2-dev libcairo2-dev libnetcdf-dev libjson-c-dev
  help2man)
{ command -v node && command -v npm; } >/dev/null 2>&1 || pkgs+=(nodejs npm)
if [ "${1:-}" != "--demo" ]; then
  # libcmocka-dev: the unit tests. clang + libclang-rt-14-dev: the sanitizer and libFuzzer runtimes (make
  # sanitize, make fuzz); llvm-14: llvm-symbolizer, so their reports name functions and lines.
  pkgs+=(libcmocka-dev clang libclang-rt-14-dev llvm-14)
  # libopenmpi-dev + openmpi-bin: cablesim-mpi and mpirun (sweeps shared among processes; tests/sweep_mpi.sh).
  pkgs+=(libopenmpi-dev openmpi-bin)
  # netcdf-bin: ncdump, which the sweep's shell test reads runs.nc with.
  pkgs+=(netcdf-bin)
  # gdb: stops the command between the renames of its commit (tests/cli_commit.sh).
  pkgs+=(gdb)
  # doxygen: the API reference (make docs) and its test (tests/api_docs.sh); dpkg-dev, debhelper and
  # lintian: the Debian packages (make package, debian/) and their test (tests/package.sh).
  pkgs+=(doxygen dpkg-dev debhelper lintian)
  # Debian's chromium and chromium-driver run the pages' browser tests; poppler-utils' pdfinfo counts the
  # pages of report.html printed (tests/cli_report_print.sh).
  pkgs+=(chromium chromium-driver poppler-utils)
  # emscripten: designer.html's engine as WebAssembly (web/build.sh); dpkg-dev (above) unpacks the Debian
  # sources of libyaml and json-c it compiles for it (scripts/wasm-libyaml.sh, wasm-jsonc.sh, at build time).
  pkgs+=(emscripten)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
