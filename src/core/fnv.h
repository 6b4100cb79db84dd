/* SPDX-License-Identifier: MIT */
/* 64-bit FNV-1a, the engine's hash of a state (cs_state_hash), defined in state.c; the loaders and writers
 * keep their own (io/fnv.h). */
#ifndef CS_FNV_H
#define CS_FNV_H

#include <stddef.h>

/* The offset basis of 64-bit FNV-1a, where a hash by cs_fnv1a64 starts. */
#define CS_FNV1A64_BASIS 14695981039346656037ULL
/* 64-bit FNV-1a of n bytes, continuing from h (start from CS_FNV1A64_BASIS). */
unsigned long long cs_fnv1a64(unsigned long long h, const void *data, size_t n);

#endif
