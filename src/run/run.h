/* SPDX-License-Identifier: MIT */
/* The run (src/run), the engine's top layer: the model built from the definitions (model.c), the state
 * created with its workspace and read through views (state.c), a step and the run loop (step.c), and the
 * response parameters (response.c). */
#ifndef CS_RUN_H
#define CS_RUN_H

#include "solver/solver.h"

/* Barrier solves a run may make per step to t_end on average, by default: a step takes about one (1.01 to
 * 1.04 over the crash tests), a step cut into its finest pieces some 70; a run that needs 20 a step over
 * its whole length is not following its path (docs/robustness.md). */
#define CS_SOLVE_BUDGET 20.0
/* What one solve of that budget may cost on average, in passes over the barrier's unknowns as installed
 * (model->work_rows): the run's work budget is CS_SOLVE_WORK x work_rows rows a solve of the budget, 2,000
 * passes a step at the default (solver/work.h). The costliest of 11,037 stress runs that follow their
 * path make 869 passes a step (median 2); a fuzzed design that did not made 43,000 (docs/theory.md, The
 * barrier solve, "Bounded work"). */
#define CS_SOLVE_WORK 100.0

/* ---- response parameters (response.c) ---- */
void cs_response_update(const cs_model *model, cs_state *s);
/* The summary's records of the model's first CS_SUMMARY_CABLES cables (cs_summary_cable), from the state. */
void cs_summary_cables(const cs_model *model, const cs_state *s, cs_summary *sm);
/* Start the sudden-loss check (response.c), fed a sample a step of the run, or each sample
 * cs_sudden_losses is given: a ring of `size` samples (t and f), samples `step` apart. */
void cs_loss_scan_start(cs_loss_scan *scan, double *t, double *f, int size, double step);
/* End the run as "did not converge": its solves have used up the budget. */
void cs_response_give_up(const cs_model *model, cs_state *s, cs_outcome why);

#endif
