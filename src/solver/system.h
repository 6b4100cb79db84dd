/* SPDX-License-Identifier: MIT */
/* The barrier's equilibrium as one nonlinear system F(x) = 0 at a vehicle pose (system.c): its unknowns
 * gathered from the state in order along the barrier, each element's rows (rows.h), and Newton's method
 * on them (newton.c). */
#ifndef CS_SYSTEM_H
#define CS_SYSTEM_H

#include "elements/rows.h"
#include "solver/newton.h"

typedef struct cs_system {
    cs_rows rows;      /* the unknowns, their columns, the placement's chords, axes and spans */
    cs_slot *gathered; /* the unknowns in the order they are gathered in, before their sort */
    int *order;        /* [n] the sort's order of them at the last assembly (gathered[order[k]]) */
    int gathered_n, order_valid;
    cs_slot *slots_kept; /* the unknowns saved by cs_system_keep */
    double *kept;        /* and their values */
    int kept_n;
    cs_slot *slots_lu; /* the unknowns of the factored Jacobian */
    int lu_n, lu_kl, lu_ku;
    cs_slot *slots_bw; /* the unknowns the band's width was last found for */
    int *nodes_bw;     /* [cable_count (max_nodes + 1)] each cable's node count (-1: not intact) and ids */
    int bw_valid, bw_n, kl, ku;
    size_t key_count; /* unknowns the predictor remembers, keyed by element */
    double *last;     /* [keys] each unknown's value at the start of the last step's solve */
    long *last_step;  /* [keys] the step that value belongs to */
    long still_step;  /* a step that extrapolates nothing: the one after a jump (cs_system_jumped) */
    double *scratch;  /* [n] residuals of the crush's difference quotient */
    cs_newton newton;
} cs_system;

int cs_system_init(const cs_model *model, cs_system *sys);
void cs_system_free(cs_system *sys);
/* Forget the predictor's history and the factored Jacobian (a new run). */
void cs_system_reset(cs_system *sys);
/* The barrier jumped to a new equilibrium in `step` (a failure, a snap booked as released, a post's fall):
 * the next step's solves start from the state as it stands, not from the last increment (which holds the
 * jump). */
void cs_system_jumped(cs_system *sys, long step);

/* Newton from the state as it stands (its unknowns extrapolated from the last step, unless the barrier
 * jumped in it: cs_system_jumped); the state is left at the last iterate, every node placed and every
 * intact span's tension found there. Returns the largest scaled residual, or -1 if Newton stalled above
 * CS_NEWTON_GIVE_UP or the band did not fit. */
#define CS_NEWTON_GIVE_UP 1e-2
double cs_system_solve(const cs_model *model, cs_state *s, cs_system *sys);

/* Remember the unknowns as they stand, and go back to them (every node placed there). */
void cs_system_keep(const cs_model *model, cs_state *s, cs_system *sys);
void cs_system_go_back(const cs_model *model, cs_state *s, cs_system *sys);

/* For tests: the linearisation at the state as it stands: the unknowns (their count returned, -1 if more
 * than cap or the band does not fit), their kinds (cs_unknown_kind) and values x, the residual r and the
 * Jacobian, dense and row-major; and the residual at other values of the same unknowns. */
int cs_system_linearize(const cs_model *model, cs_state *s, cs_system *sys, int cap, int *kind, double *x,
                        double *r, double *jac);
void cs_system_residual(const cs_model *model, cs_state *s, cs_system *sys, int n, const double *x,
                        double *r);

#endif
