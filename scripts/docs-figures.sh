#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The figures of docs/guide.md that a run draws (make figures): `bash scripts/docs-figures.sh [BUILD]` runs
# BUILD/cablesim (BUILD: build) into a scratch folder, removed at exit, and
# - copies the spacing study's chart to docs/roadside-spacing.png (tests/cli_guide_spacing.sh checks the
#   guide's numbers beside it against the same study);
# - with chromium, shoots the top of the 64-run study's page (examples/aps3-uncertain.yaml) to
#   docs/study-page.png, as the guide says.
# The other figures in docs/ are made as the docs that show them say.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/cablesim" sweep examples/roadside/spacing-study.yaml -o "$out/spacing-study"
cp "$out/spacing-study/plots/max_barrier_deflection-vs-spacing.png" docs/roadside-spacing.png
echo "docs-figures: wrote docs/roadside-spacing.png"
"$build/cablesim" sweep examples/aps3-uncertain.yaml --threads 2 -o "$out/aps3-uncertain" >/dev/null
if command -v chromium >/dev/null; then
    chromium --headless --no-sandbox --hide-scrollbars --window-size=1000,1350 \
        --screenshot="$PWD/docs/study-page.png" "file://$out/aps3-uncertain/report.html" 2>/dev/null
    echo "docs-figures: wrote docs/study-page.png"
else
    echo "docs-figures: no chromium: docs/study-page.png not drawn"
fi
