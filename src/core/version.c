/* SPDX-License-Identifier: MIT */
#include "cablesim/cablesim.h"

const char *cs_version(void) {
    return CS_VERSION_STRING;
}
