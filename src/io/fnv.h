/* SPDX-License-Identifier: MIT */
/* 64-bit FNV-1a for the loaders' and writers' own keys: a model's hash (cs_model_input_hash) and a
 * sweep's key. The engine hashes its state with its own (core/fnv.h): src/io reaches the engine only
 * through the public API, and a hash primitive is not part of it. */
#ifndef CS_IO_FNV_H
#define CS_IO_FNV_H

#include <stddef.h>

/* The offset basis of 64-bit FNV-1a, where a hash starts. */
#define CS_IO_FNV_BASIS 14695981039346656037ULL

/* 64-bit FNV-1a of n bytes, continuing from h. */
static inline unsigned long long cs_io_fnv(unsigned long long h, const void *data, size_t n) {
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}

#endif
