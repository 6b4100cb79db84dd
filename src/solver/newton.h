/* SPDX-License-Identifier: MIT */
/* A Newton solver for F(x) = 0 with a banded Jacobian: line search on |F|^2, Broyden's updates between
 * rebuilds of the factored Jacobian. It knows nothing of what x means: the problem places x, evaluates
 * F and its Jacobian, and says how far a step may go. */
#ifndef CS_NEWTON_H
#define CS_NEWTON_H

#include "core/band.h"

/* Its limits: at most CS_NEWTON_ITERATIONS iterations, each forming and factoring a Jacobian (counted as
 * CS_JACOBIAN_EVALUATIONS residuals: its rows' gradients, the crush's column by differences, the banded LU)
 * and trying up to CS_NEWTON_TRIALS steps; so one solve makes at most CS_NEWTON_MOST_PASSES passes over
 * its rows (nw->evaluations). */
#define CS_NEWTON_ITERATIONS 40
#define CS_NEWTON_TRIALS 30
#define CS_JACOBIAN_EVALUATIONS 2
#define CS_NEWTON_MOST_PASSES (1 + CS_NEWTON_ITERATIONS * (CS_JACOBIAN_EVALUATIONS + CS_NEWTON_TRIALS))

typedef struct cs_newton_problem {
    void *ctx;
    int n;
    /* Bring the problem to x (everything F depends on). */
    void (*place)(void *ctx, const double *x);
    /* F at the x last placed. */
    void (*residual)(void *ctx, double *r);
    /* The Jacobian at x with residual r, the problem at x, into J (the problem sets J's shape); -1 if it
     * cannot (the band does not fit). */
    int (*jacobian)(void *ctx, const double *x, const double *r, cs_band *J);
    /* The largest fraction (<= 1) of the step dx from the x last accepted that the problem allows. */
    double (*step_limit)(void *ctx, const double *dx);
} cs_newton_problem;

typedef struct cs_newton {
    int capacity;    /* unknowns the buffers hold */
    double *x, *r;   /* the iterate and its residual */
    double *dx;      /* the step */
    double *xt, *rt; /* a trial and its residual */
    double *updates; /* Broyden's pairs (s, u), CS_BROYDEN_MAX of them */
    int update_count;
    int factored; /* `band` holds the factors of a Jacobian of the problem's current unknowns */
    cs_band band;
    long evaluations; /* residuals and Jacobians evaluated since cs_newton_init (each a pass over the rows) */
} cs_newton;

int cs_newton_init(cs_newton *nw, int capacity, size_t band_entries);
void cs_newton_free(cs_newton *nw);
/* Forget the factored Jacobian (the unknowns changed, or the band was used for something else). */
void cs_newton_forget(cs_newton *nw);

/* Solve from nw->x (n = p->n values set by the caller) until max |F| <= tol or 40 iterations; the
 * problem is left at the last accepted x (in nw->x, its residual in nw->r). Returns max |F| there, or -1
 * if the Jacobian could not be formed. */
double cs_newton_solve(cs_newton *nw, const cs_newton_problem *p, double tol);

#endif
