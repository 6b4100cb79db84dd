#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# designer.html in headless chromium against the command's own runs (report/test/designer.mjs, or the
# script CS_DESIGNER_TEST names: report/test/designer_truth.mjs, the page's numbers against the run's
# other outputs). Skipped (exit 77) in a build without the designer page: emscripten, node or npm missing
# (scripts/install-deps.sh installs them).
#   bash tests/designer_browser.sh CABLESIM REPORT_BUILD_DIR OUT MATH
# (CS_DESIGNER_BUILT=1 when the page is built; MATH: the engine's maths, musl or glibc, as CMake resolved CS_MATH)
set -euo pipefail
if [ "${CS_DESIGNER_BUILT:-0}" != 1 ]; then
  echo "skipped: this cablesim was built without the designer page (emscripten, node or npm not found)"
  exit 77
fi
exec node "${CS_DESIGNER_TEST:-report/test/designer.mjs}" --cablesim "$1" --modules "$2/node_modules" --out "$3" --math "${4:-glibc}"
