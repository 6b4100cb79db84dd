/* SPDX-License-Identifier: MIT */
/* Room for one more element in a growing array. */
#ifndef CS_GROW_H
#define CS_GROW_H

#include <stdlib.h>

/* Make *items hold at least count + 1 elements of size bytes (doubling *capacity). 0, or -1 if memory
 * is short (the array is then unchanged). */
static inline int cs_grow(void *items, int *capacity, int count, size_t size) {
    void **p = items;
    if (count < *capacity) return 0;
    int cap = *capacity ? 2 * *capacity : 16;
    void *q = realloc(*p, (size_t)cap * size);
    if (!q) return -1;
    *p = q;
    *capacity = cap;
    return 0;
}

/* Make *items hold count + 1 elements of size bytes, for arrays as long as their count (parallel arrays
 * that share one count, each grown in turn). 0, or -1 if memory is short (the array is then unchanged). */
static inline int cs_grow_one(void *items, int count, size_t size) {
    void **p = items;
    void *q = realloc(*p, ((size_t)count + 1) * size);
    if (!q) return -1;
    *p = q;
    return 0;
}

#endif
