/* SPDX-License-Identifier: MIT */
/* A banded matrix and its LU factors with partial pivoting: linear algebra only, no physics.
 * Row i keeps columns i - kl .. i + ku + kl (the extra kl for the fill-in of the row exchanges). */
#ifndef CS_BAND_H
#define CS_BAND_H

#include <stddef.h>

typedef struct cs_band {
    double *a;       /* n rows of `width` entries */
    int *pivot;      /* [n] the row exchanged with row k at step k */
    size_t capacity; /* entries allocated */
    int n, kl, ku, width;
} cs_band;

/* Storage for up to `entries` entries and `rows` rows; -1 out of memory. */
int cs_band_init(cs_band *b, size_t entries, int rows);
void cs_band_free(cs_band *b);
/* Set the size and bandwidths and zero the entries; -1 if they do not fit the storage. */
int cs_band_shape(cs_band *b, int n, int kl, int ku);

static inline double *cs_band_entry(cs_band *b, int i, int j) {
    return b->a + (size_t)i * (size_t)b->width + (size_t)(j - i + b->kl);
}
/* Whether (i, j) lies in the band of an n x n matrix. */
static inline int cs_band_holds(const cs_band *b, int i, int j) {
    return i >= 0 && i < b->n && j >= 0 && j < b->n && i >= j - b->ku && i <= j + b->kl;
}
/* A(i, j) += v where (i, j) lies in the band; elsewhere nothing. */
static inline void cs_band_add(cs_band *b, int i, int j, double v) {
    if (cs_band_holds(b, i, j)) *cs_band_entry(b, i, j) += v;
}

/* LU with partial pivoting in place; -1 if a pivot is zero. */
int cs_band_factor(cs_band *b);
/* x = A^-1 x with the factors. */
void cs_band_solve(const cs_band *b, double *x);

#endif
