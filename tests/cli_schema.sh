#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# docs/file-format.md is exactly what `cablesim schema` prints from the schema tables.
set -u
cs=${1:?usage: bash tests/cli_schema.sh path/to/cablesim}
if diff -u docs/file-format.md <("$cs" schema); then
    echo "1 passed, 0 failed"
else
    echo "docs/file-format.md is stale: run '$cs schema > docs/file-format.md'"
    echo "0 passed, 1 failed"
    exit 1
fi
