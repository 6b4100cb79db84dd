#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The design chart of docs/guide.md (make figures): `bash scripts/docs-figures.sh [BUILD]` runs
# BUILD/cablesim (BUILD: build) on the guide's spacing study into a scratch folder, removed at exit, and
# copies the study's chart to docs/roadside-spacing.png. tests/cli_guide_spacing.sh checks the guide's
# numbers beside it against the same study. The other figures in docs/ are made as the docs that show them
# say.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/cablesim" sweep examples/roadside/spacing-study.yaml -o "$out/spacing-study"
cp "$out/spacing-study/plots/max_barrier_deflection-vs-spacing.png" docs/roadside-spacing.png
echo "docs-figures: wrote docs/roadside-spacing.png"
