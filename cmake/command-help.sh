#!/bin/sh
# SPDX-License-Identifier: MIT
# `cablesim COMMAND ARG...` for help2man, which makes cablesim-COMMAND(1) from its --help: a synopsis line
# continued on the next lines (indented, from "[") is joined into one, as help2man reads a synopsis a line.
# $1 the cablesim binary, $2 the command.
cablesim=$1
cmd=$2
shift 2
"$cablesim" "$cmd" "$@" | awk '
    syn && /^     +[[]/ { sub(/^ +/, ""); line = line " " $0; next }
    NR > 1 { print line }
    { line = $0; syn = /^(Usage:|  or:)/ }
    END { print line }'
