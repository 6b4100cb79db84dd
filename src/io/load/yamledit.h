/* SPDX-License-Identifier: MIT */
/* A model file's text with some of its values replaced in place, its comments, order and layout kept:
 * the designer page's "download the edited model" (docs/designer.md). */
#ifndef CS_YAMLEDIT_H
#define CS_YAMLEDIT_H

#include <stddef.h>

#include "cablesim/sim.h"

/* text (size bytes, a YAML file) with the value of each sets[i], "PATH=VALUE" as `cablesim run --set`
 * takes it, replaced by VALUE, written plain where YAML reads it back as the same text, else
 * double-quoted. Each PATH must name a single value written in the file (no alias). The result is read
 * back and each value checked. Returns the new text (malloc'd, NUL-terminated; *out_size its length), or
 * NULL with err filled: CS_ERR_INVALID (text does not read, a set is not PATH=VALUE or names no single
 * value of the file, a value does not read back) or CS_ERR_MEMORY. */
char *cs_yaml_edit(const char *text, size_t size, const char *const *sets, int count, size_t *out_size,
                   cs_error *err);

#endif
