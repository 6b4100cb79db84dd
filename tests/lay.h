/* SPDX-License-Identifier: MIT */
/* Engine-internal test helper: lay cable 0 of a state as anchor - post 0 - anchor through three
 * points, with the two spans at given strains (no plastic set). */
#ifndef CS_TEST_LAY_H
#define CS_TEST_LAY_H

#include "fixture.h"
#include "run/run.h"

/* A model and its state built from a fixture, for tests that reach into the engine. */
typedef struct world {
    fixture fx;
    cs_model *model;
    cs_state *state;
} world;

static inline void world_free(world *w) {
    cs_state_free(w->state);
    cs_model_free(w->model);
}

static inline cs_cable_state *lay_cable(cs_state *s, const double *a, const double *b, const double *c,
                                        double e1, double e2) {
    cs_cable_state *cs = &s->cables[0];
    cs->node_count = 3;
    cs->node[0] = CS_NODE_START, cs->node[1] = 0, cs->node[2] = CS_NODE_END;
    cs->where[0] = 1;
    for (int k = 0; k < 3; k++)
        cs->pos[k] = a[k], cs->pos[3 + k] = b[k], cs->pos[6 + k] = c[k];
    cs->m[0] = 0.0;
    cs->m[1] = cs_span_length(cs, 0) / (1.0 + e1);
    cs->m[2] = cs->m[1] + cs_span_length(cs, 1) / (1.0 + e2);
    for (int k = 0; k < 3; k++)
        cs->m_commit[k] = cs->m[k];
    cs->ep[0] = cs->ep[1] = 0.0;
    return cs;
}

#endif
