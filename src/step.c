/* One time step, as named stages, and the run loop. */
#include "internal.h"
#include "vec3.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Breaks, post failures, anchor pullouts and posts struck by the face, found after a commit, change the
 * barrier's topology with no work done on it: re-solve at the same vehicle pose until nothing more
 * changes, and book the stored energy that vanished (massless cable snapping, posts letting go, a
 * struck post leaving the ropes' paths) as released. */
static void resolve_failures(const cs_model *model, cs_state *s) {
    /* what is released is the whole drop across the failures; a cable slipping off the face inside
     * the loop books its own share too (contact.c), so restart from the total before the loop */
    double before = cs_barrier_stored_energy(model, s), released = s->e_released;
    int changed = 0;
    for (int round = 0; round <= model->cable_count + model->post_count + 2; round++) {
        int any = 0;
        for (int c = 0; c < model->cable_count; c++)
            any |= cs_cable_check_break(model, c, s);
        for (int p = 0; p < model->post_count; p++)
            any |= cs_post_check_failure(model, s, p);
        any |= cs_anchor_check(model, s);
        any |= cs_post_capture(model, s);
        any |= cs_contact_check_slip(model, s);
        if (!any) break;
        changed = 1;
        cs_contact_drop_failed(model, s);
        cs_contact_update(model, s);
        cs_barrier_solve(model, s);
        cs_barrier_commit(model, s);
    }
    if (changed) s->e_released = released + before - cs_barrier_stored_energy(model, s);
}

static cs_status unstable(const cs_model *model, cs_state *s, cs_error *err, const char *what, int element) {
    s->frozen = 1;
    if (err) {
        char name[64];
        if (element >= 0)
            snprintf(name, sizeof name, "%s %d", what, element);
        else
            snprintf(name, sizeof name, "%s", what);
        err->status = CS_ERR_UNSTABLE;
        snprintf(err->message, sizeof err->message,
                 "t = %.4f s: %s went unstable (a value became NaN or infinite); reduce the time step (now "
                 "%.3g ms)",
                 s->t, name, model->scenario.dt * 1e3);
    }
    return CS_ERR_UNSTABLE;
}

/* Guards: no NaN or Inf anywhere, and no energy created. */
static cs_status check_numbers(const cs_model *model, cs_state *s, cs_error *err) {
    for (int i = 0; i < 3; i++)
        if (!isfinite(s->pos[i]) || !isfinite(s->vel[i]) || !isfinite(s->omega[i]) || !isfinite(s->force[i]))
            return unstable(model, s, err, "the vehicle", -1);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        for (int i = 0; i + 1 < cs->node_count; i++)
            if (!isfinite(cs->tension[i]) || !isfinite(cs->m[i])) return unstable(model, s, err, "cable", c);
    }
    for (int p = 0; p < model->post_count; p++)
        if (!isfinite(s->posts[p].tilt[0]) || !isfinite(s->posts[p].tilt[1]))
            return unstable(model, s, err, "post", p);
    if (!isfinite(s->energy.balance_error) || s->energy.balance_error > 0.25) {
        s->frozen = 1;
        if (err) {
            err->status = CS_ERR_UNSTABLE;
            snprintf(
                err->message, sizeof err->message,
                "t = %.4f s: the energy ledger grew by %.1f%% of the initial kinetic energy; reduce the time "
                "step (now %.3g ms)",
                s->t, 100.0 * s->energy.balance_error, model->scenario.dt * 1e3);
        }
        return CS_ERR_UNSTABLE;
    }
    return CS_OK;
}

cs_status cs_step(const cs_model *model, cs_state *s, cs_error *err) {
    if (err) err->status = CS_OK, err->message[0] = '\0';
    if (s->frozen || s->outcome != CS_RUNNING) return CS_OK;
    v3_copy(s->step_start_pos, s->pos);
    memcpy(s->step_start_quat, s->quat, sizeof s->quat);
    cs_vehicle_integrate(model, s); /* 1. the vehicle moves: half a kick and a drift */
    s->t += model->scenario.dt;
    s->step++;
    cs_contact_update(model, s);  /* 2. cables wrap onto or leave the face */
    cs_barrier_solve(model, s);   /* 3. posts, sliding and crush in equilibrium */
    cs_barrier_commit(model, s);  /* 4. plastic flow, friction and crush work */
    resolve_failures(model, s);   /* 5. breaks, failures, posts struck by the face */
    cs_barrier_force(model, s);   /* 6. the barrier's push, */
    cs_vehicle_finish(model, s);  /*    the second half kick */
    cs_energy_update(model, s);   /* 7. the ledger */
    cs_response_update(model, s); /* 8. response parameters, end of the run */
    return check_numbers(model, s, err);
}

cs_status cs_run(const cs_model *model, cs_state *s, cs_output_fn on_output, void *user, cs_error *err) {
    double interval = model->scenario.output_interval, next = s->t + interval;
    if (on_output) on_output(model, s, user);
    int last_out = 1;
    while (s->outcome == CS_RUNNING) {
        cs_status st = cs_step(model, s, err);
        if (st != CS_OK) return st;
        last_out = 0;
        if (on_output && (interval <= 0.0 || s->t >= next - 1e-9 * model->scenario.dt)) {
            on_output(model, s, user);
            last_out = 1;
            while (next <= s->t + 1e-9 * model->scenario.dt)
                next += interval > 0.0 ? interval : model->scenario.dt;
        }
    }
    if (on_output && !last_out) on_output(model, s, user);
    return CS_OK;
}
