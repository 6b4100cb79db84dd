/* SPDX-License-Identifier: MIT */
/* Files a model names are untrusted input: they are read only from the folders allowed (the folder of the
 * file named on the command line and its subfolders, the parts library's, and each `--allow-path DIR`),
 * only when they are regular files, and only up to CS_INPUT_MAX bytes. Model files, the parts library and
 * sweep specs are all read through cs_input_load; the loader and the sweep spec check their references with
 * cs_allow_has. */
#ifndef CS_CONFINE_H
#define CS_CONFINE_H

#include <stddef.h>

#include "cablesim/sim.h"

/* The largest input file read: far above a 100,000-post model (about 10 MB). */
#define CS_INPUT_MAX ((size_t)64 << 20)

/* The folders a model's references may be in, each by its canonical path. */
typedef struct cs_allow {
    char **dirs;
    int count, capacity;
} cs_allow;

/* Add a folder (made canonical; it must exist and be a folder). CS_OK, or with err filled CS_ERR_INVALID
 * (no such folder, not a folder) or CS_ERR_MEMORY. */
cs_status cs_allow_add(cs_allow *a, const char *dir, cs_error *err);
/* Add the folder of a file (made canonical). As cs_allow_add. */
cs_status cs_allow_add_folder_of(cs_allow *a, const char *file, cs_error *err);
/* Copy every folder of from into to. 0, or -1 when memory is short. */
int cs_allow_copy(cs_allow *to, const cs_allow *from);
/* Is the canonical path real in one of the folders (or one of them)? */
int cs_allow_has(const cs_allow *a, const char *real);
/* The folders as "A, B or C" into buf. */
void cs_allow_list(const cs_allow *a, char *buf, size_t size);
void cs_allow_free(cs_allow *a);

/* Read a whole file into *data (malloc'ed, NUL-terminated; *size its length): opened without waiting (a
 * FIFO or a device is refused at once, not read), a regular file only, at most limit bytes. CS_OK, or with
 * err filled saying why ("a FIFO, not a regular file", "... larger than the 64 MB ...", the system's
 * reason) CS_ERR_IO (the system refused it; *errnum its errno), CS_ERR_INVALID (no regular file, too
 * large; *errnum 0) or CS_ERR_MEMORY. */
cs_status cs_input_load(const char *path, size_t limit, char **data, size_t *size, int *errnum,
                        cs_error *err);

#endif
