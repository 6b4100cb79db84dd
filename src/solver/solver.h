/* SPDX-License-Identifier: MIT */
/* What the solver (src/solver) offers the run above it: the barrier's equilibrium at a vehicle pose
 * (barrier.c, on the system of system.h solved by Newton, newton.h), its Gauss-Seidel fallback (relax.c)
 * and the posts' lean as installed (settle.c). The workspace they keep between steps: work.h. */
#ifndef CS_SOLVER_H
#define CS_SOLVER_H

#include "elements/elements.h"

/* ---- barrier solve (barrier.c), and its fallback (relax.c) ---- */
double cs_barrier_solve(const cs_model *model, cs_state *s);
void cs_barrier_force(const cs_model *model, cs_state *s);
void cs_barrier_commit(const cs_model *model, cs_state *s);
/* The stored and dissipated energy the barrier would hold if committed as it stands (on a trial copy in
 * the workspace). */
double cs_barrier_trial_energy(const cs_model *model, const cs_state *s, cs_work *work);
double cs_barrier_stored_energy(const cs_model *model, const cs_state *s);
/* Gauss-Seidel sweeps of the elements' local problems (may_fall: a post with no equilibrium near falls
 * to the next one), no more once the run's work budget is spent (work.h); the largest relative residual
 * of the last sweep, or CS_RELAX_NOTHING if it swept none. */
#define CS_RELAX_NOTHING 1.0 /* a residual of one unit: far from equilibrium, nothing solved */
double cs_relax(const cs_model *model, cs_state *s, int sweeps, int may_fall);
/* The fallback's local solve of support i of a cable: the rope slides until the capstan condition holds
 * with its neighbours held; the relative violation found on entry. */
double cs_relax_slide_node(const cs_model *model, const cs_cable_model *cm, cs_cable_state *cs, int i,
                           double tol);
/* The fallback's local problem at each end of cable c that can slip: the largest change it made to an end
 * span's tension, over Fu (0 where the ends already kept the law). */
double cs_relax_ends(const cs_model *model, int c, cs_state *s);
/* The fallback's local solve of post p's tilt (its cables sliding through it) with its neighbours held;
 * the relative residual found on entry. */
double cs_relax_post(const cs_model *model, cs_state *s, int p, double tol, int may_fall);
/* The crush alone in balance with the face's load (the paper's crush correction); the residual on entry. */
double cs_relax_crush(const cs_model *model, cs_state *s);

/* The posts' lean under the ropes' tensions as they stand (held, not following the spans' stretch), at
 * rest: one Newton solve over every standing post's tilt (settle.c). Returns the largest scaled residual
 * left (-1 if the band did not fit). */
double cs_settle_posts(const cs_model *model, cs_state *s);

#endif
