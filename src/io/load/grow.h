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

/* Make *items hold count + 1 elements of size bytes, for arrays whose capacity follows from their count
 * (parallel arrays that share one count, each grown in turn, all only by this): 16 up to 16 elements, then
 * the power of two at or above the count, so n appends reallocate about log2(n) times, not n (a realloc
 * that moves copies the array: n of them would be quadratic). 0, or -1 if memory is short (the array is
 * then unchanged). */
static inline int cs_grow_one(void *items, int count, size_t size) {
    if (count > 0 && (count < 16 || (count & (count - 1)) != 0)) return 0; /* room left */
    void **p = items;
    void *q = realloc(*p, (count < 16 ? 16 : 2 * (size_t)count) * size);
    if (!q) return -1;
    *p = q;
    return 0;
}

#endif
