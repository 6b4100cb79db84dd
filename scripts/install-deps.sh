#!/usr/bin/env bash
# Install the Debian packages cablesim needs, only those missing. Safe to run again.
set -euo pipefail
# clang + libclang-rt-14-dev: the sanitizer and libFuzzer runtimes (make sanitize, make fuzz); llvm-14:
# llvm-symbolizer, so their reports name functions and lines.
pkgs=(build-essential cmake pkg-config clang libclang-rt-14-dev llvm-14 libyaml-dev libudunits2-dev libcmocka-dev
  libcairo2-dev)
# libopenmpi-dev + openmpi-bin: cablesim-mpi and mpirun (sweeps shared among processes; tests/sweep_mpi.sh).
pkgs+=(libopenmpi-dev openmpi-bin)
# libnetcdf-dev: the sweep's runs.nc (netCDF C library); netcdf-bin: ncdump, which its shell test reads it with.
pkgs+=(libnetcdf-dev netcdf-bin)
# libjson-c-dev: cablesim compare reads each run's summary.json.
pkgs+=(libjson-c-dev)
# doxygen: the API reference (make docs) and its test (tests/api_docs.sh); help2man: the command's manual
# page, made from its --help at build time; dpkg-dev: dpkg-shlibdeps, the .deb's dependencies (make package).
pkgs+=(doxygen help2man dpkg-dev)
# report.html (report/): node and npm build its page (Debian's only where none is installed: a newer one
# may be); Debian's chromium and chromium-driver run its browser test.
pkgs+=(chromium chromium-driver)
{ command -v node && command -v npm; } >/dev/null 2>&1 || pkgs+=(nodejs npm)
# emscripten: designer.html's engine as WebAssembly (web/build.sh); dpkg-dev (above) unpacks the Debian
# source of libyaml it compiles for it (scripts/wasm-libyaml.sh, at build time).
pkgs+=(emscripten)
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
