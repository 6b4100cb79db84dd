/* SPDX-License-Identifier: MIT */
/* The workspace of a state: what the step needs besides the physical state (the barrier system's
 * unknowns, factors and predictor history, and whole-state copies to go back to), allocated with the
 * state and left out of its hash. It is not without effect: the predictor's history and the kept Jacobian
 * decide where each solve starts, and so where, within the solver's tolerance, it ends. A run starts it
 * afresh (cs_state_reset), so a run's result is the same every time; a state copied into another workspace
 * mid-run goes on to the same results only within that tolerance. */
#ifndef CS_WORK_H
#define CS_WORK_H

#include "solver/system.h"

enum { CS_PATH_LEVELS = 2 }; /* how many times a step may be cut into pieces (step.c) */

struct cs_work {
    cs_system sys;
    /* the state at the start of the stretch followed at each level, to take it again (step.c) */
    cs_state *step_start[CS_PATH_LEVELS];
    cs_state *trial;         /* a trial commit (barrier.c) */
    double stored_committed; /* cs_barrier_stored_energy where the stretch being followed started or last
                              * committed at the last level, J (step.c) */
    double solver_residual;  /* largest residual of the solves the step committed */
    int struck;              /* a pose taken up since the stretch's gap was last booked struck a post
                              * before its solve (step.c) */
    int rode;                /* ... or rode slotted cables up their slots before its solve (step.c) */
    struct {
        long solves;     /* barrier solves at a pose */
        long fallback;   /* of them, those that needed the fallback's sweeps (relax.c) */
        long fall_tries; /* of them, those that tried letting a post fall (relax.c) */
        long falls;      /* of those, the falls kept (barrier.c) */
        long pieces;     /* steps the path following cut into pieces (step.c) */
        long sweeps;     /* the fallback's Gauss-Seidel sweeps (relax.c) */
        long newton; /* Newton's residuals and Jacobians evaluated (newton.c), each a pass over the rows */
        double work; /* the solver's work, in rows evaluated: each of Newton's passes its n rows, each
                      * sweep CS_SWEEP_ROW_COST a local problem it solves (relax.c, system.c) */
    } count;         /* since the state was reset */
};

/* The run's work is bounded by what it costs, not by its count of solves (docs/theory.md, The barrier
 * solve, "Bounded work"): once count.work passes the model's work_budget, every solve ends with the
 * Newton solve or sweep under way (barrier.c, relax.c) and the step under way is not taken (step.c). */
static inline int cs_work_spent(const cs_model *model, const cs_work *w) {
    return w->count.work > model->work_budget;
}

#endif
