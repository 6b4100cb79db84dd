/* SPDX-License-Identifier: MIT */
/* Response parameters, updated every step: the 50-ms moving-average deceleration, penetration of the
 * front face past the attack face (y = 0), barrier deflection and working width, failed posts on each
 * side, each cable's peak tension and work on the vehicle, and the end of the run (stopped, broke through,
 * redirected, time limit), with the sudden-loss check of the barrier's force on the vehicle. */
#include "core/vec3.h"
#include "run/run.h"
#include "run/sized.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 50-ms average of the deceleration along the initial travel direction: the change of forward speed
 * over the window, (u(t - W) - u(t)) / W, from a ring of the last window_steps + 1 speeds (the first
 * of them the speed at t = 0, put there at reset). */
static void update_decel(const cs_model *model, cs_state *s, double u) {
    int n = model->window_steps + 1;
    s->speed_ring[s->step % n] = u;
    if (s->ring_fill < n) s->ring_fill++;
    if (s->ring_fill < n) return;
    double old = s->speed_ring[(s->step + 1) % n];
    double w = model->window_steps * model->scenario.dt;
    s->decel_50ms_g = (old - u) / w / CS_G0;
    if (s->decel_50ms_g > s->summary.max_50ms_decel_g) {
        s->summary.max_50ms_decel_g = s->decel_50ms_g;
        s->summary.t_max_50ms_decel_s = s->t;
    }
}

/* Furthest y of the face's four corners (crushed face). */
static double face_penetration(const cs_model *model, const cs_state *s) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double best = -HUGE_VAL, p[3];
    for (int k = 0; k < 4; k++) {
        double y = (k % 2 ? 0.5 : -0.5) * v->front_width,
               z = (k < 2 ? v->face_bottom : v->face_top) - v->cg_height;
        cs_vehicle_face_point(model, s, s->crush, y, z, p);
        if (p[1] > best) best = p[1];
    }
    return best;
}

/* A run that ends before its first window is full has no 50-ms average from the ring: its one window
 * starts with the run and holds the last speed from the end on (the vehicle has stopped, or goes on
 * unhindered). */
static void close_decel_window(const cs_model *model, cs_state *s) {
    int n = model->window_steps + 1;
    if (s->ring_fill >= n) return; /* with the speed at t = 0 alone, first == last: 0 g */
    double first = s->speed_ring[(s->step + 1 - s->ring_fill) % n], last = s->speed_ring[s->step % n];
    double w = model->window_steps * model->scenario.dt, g = (first - last) / w / CS_G0;
    if (g > s->summary.max_50ms_decel_g) {
        s->summary.max_50ms_decel_g = g;
        s->summary.t_max_50ms_decel_s =
            s->t - (s->ring_fill - 1) * model->scenario.dt + w; /* the window's end */
    }
}

/* Furthest y of the outline's corners, each at the bottom and top of its band (a rolled body leans its
 * top over). */
static double vehicle_reach(const cs_model *model, const cs_state *s) {
    double best = -HUGE_VAL, p[3];
    for (int k = 0; k < CS_OUTLINE_CORNERS; k++) {
        double z[2];
        cs_vehicle_corner_band(model, k, &z[0], &z[1]);
        for (int e = 0; e < 2; e++) {
            cs_vehicle_corner_point(model, s, s->crush, k, z[e], p);
            if (p[1] > best) best = p[1];
        }
    }
    return best;
}

/* ---- the sudden-loss check ----
 * A window is a pair of samples at most CS_SUDDEN_LOSS_WINDOW apart; the force falls over it from the
 * earlier to the later. Each sample ends the window of the largest fall to it (from the largest force within
 * the window before it, the latest of equals); that fall is flagged if it passes CS_SUDDEN_LOSS_FRACTION of
 * the largest force so far and no excusing event (a rope breaking, an end fitting letting go, an attachment
 * letting a cable go, an anchor pulling out with its ropes, a rope's contact sliding past the face's edge as
 * the vehicle rides over or runs under it) falls within the window or a sample step of it.
 * It is judged at the next sample, whose events are then known. Falls flagged at successive samples make one
 * stretch, kept by its largest fall; at the end a stretch stays flagged if that fall passes the fraction of
 * the run's largest force (a fall that does passed it of the largest so far, so none is missed). */

static int excuses(cs_event_type type) {
    return type == CS_EVENT_CABLE_BREAK || type == CS_EVENT_TERMINATION_BREAK ||
           type == CS_EVENT_CABLE_RELEASE || type == CS_EVENT_CABLE_PULLED_OFF ||
           type == CS_EVENT_ANCHOR_PULLOUT || type == CS_EVENT_OVERRIDE || type == CS_EVENT_UNDERRIDE;
}

void cs_loss_scan_start(cs_loss_scan *scan, double *t, double *f, int size, double step) {
    *scan = (cs_loss_scan){.t = t, .f = f, .size = size, .step = step};
}

static void judge_fall(cs_loss_scan *scan, const cs_event *events, int event_count) {
    const cs_sudden_loss *w = &scan->fall;
    double slack = scan->step * (1.0 + 1e-6);
    scan->pending = 0;
    for (int i = 0; i < event_count; i++) {
        if (excuses(events[i].type) && events[i].t >= w->t_start_s - slack &&
            events[i].t <= w->t_end_s + slack) {
            scan->open = 0;
            return;
        }
    }
    if (scan->open == 1) { /* the stretch goes on: kept by its largest fall */
        cs_sudden_loss *last = &scan->found[scan->kept - 1];
        if (w->force_before_n - w->force_after_n > last->force_before_n - last->force_after_n) *last = *w;
    } else if (scan->open == 0) {
        if (scan->kept < CS_SUDDEN_LOSS_KEPT)
            scan->found[scan->kept++] = *w, scan->open = 1;
        else
            scan->missed++, scan->open = 2;
    }
}

/* Feed the sample (t, force) with the events up to its time. */
static void loss_scan_feed(cs_loss_scan *scan, double t, double force, const cs_event *events,
                           int event_count) {
    if (scan->pending)
        judge_fall(scan, events, event_count);
    else
        scan->open = 0;
    scan->t[scan->fed % scan->size] = t;
    scan->f[scan->fed % scan->size] = force;
    scan->fed++;
    if (force > scan->peak) scan->peak = force;
    double before = force, t_before = t, reach = CS_SUDDEN_LOSS_WINDOW + 1e-6 * scan->step;
    for (long k = scan->fed - 2; k >= 0 && k >= scan->fed - scan->size; k--) {
        int i = (int)(k % scan->size);
        if (t - scan->t[i] > reach) break;
        if (scan->f[i] > before) before = scan->f[i], t_before = scan->t[i];
    }
    scan->pending = before - force > CS_SUDDEN_LOSS_FRACTION * scan->peak;
    if (scan->pending) scan->fall = (cs_sudden_loss){sizeof(cs_sudden_loss), t_before, t, before, force};
}

/* The windows flagged, with all the run's events: the kept ones in found[0 .. kept), the rest counted in
 * missed; returns kept + missed. */
static int loss_scan_finish(cs_loss_scan *scan, const cs_event *events, int event_count) {
    if (scan->pending) judge_fall(scan, events, event_count);
    scan->open = 0;
    int kept = 0;
    for (int k = 0; k < scan->kept; k++)
        if (scan->found[k].force_before_n - scan->found[k].force_after_n >
            CS_SUDDEN_LOSS_FRACTION * scan->peak)
            scan->found[kept++] = scan->found[k];
    scan->kept = kept;
    return kept + scan->missed;
}

/* The caller's events, an array of the first one's size (an event of another size is refused: it would
 * be read past its place), as this library's (count of them, or 1 for none): NULL with err filled. */
static cs_event *take_events(const cs_event *given, int count, cs_error *err) {
    cs_event *all = calloc(count > 0 ? (size_t)count : 1, sizeof *all);
    if (!all) return cs_out_of_memory(err), NULL;
    size_t stride = 0;
    if (count > 0 && given) memcpy(&stride, given, sizeof stride);
    for (int i = 0; i < count && given; i++) {
        const char *at = (const char *)given + (size_t)i * stride;
        size_t size;
        memcpy(&size, at, sizeof size);
        if (size != stride)
            return cs_sized_refuse(err, "cs_event", "an array's events must all have the first one's size"),
                   free(all), NULL;
        all[i] = (cs_event){.size = sizeof *all, .cable_end = -1, .cable = -1, .post = -1};
        if (cs_sized_take(&all[i], sizeof *all, at, "cs_event", err)) return free(all), NULL;
    }
    return all;
}

int cs_sudden_losses(const double *t, const double *force, int n, double step, const cs_event *given,
                     int event_count, cs_sudden_loss *out, int capacity, cs_error *err) {
    if (n <= 0) return 0;
    cs_event *events = take_events(given, given ? event_count : 0, err);
    if (!events) return -1;
    double *ring = malloc(2 * (size_t)n * sizeof *ring);
    cs_loss_scan *scan = malloc(sizeof *scan);
    if (!ring || !scan) return free(events), free(ring), free(scan), cs_out_of_memory(err), -1;
    if (!given) event_count = 0;
    cs_loss_scan_start(scan, ring, ring + n, n, step);
    int seen = 0; /* the events up to each sample's time */
    for (int j = 0; j < n; j++) {
        while (seen < event_count && events[seen].t <= t[j] + 1e-6 * step)
            seen++;
        loss_scan_feed(scan, t[j], force[j], events, seen);
    }
    int count = loss_scan_finish(scan, events, event_count);
    int kept = scan->kept < capacity ? scan->kept : capacity;
    if (capacity > 0 &&
        cs_sized_put_array(out, scan->found, sizeof *scan->found, kept, "cs_sudden_loss", err))
        count = -1;
    free(events), free(ring), free(scan);
    return count;
}

int cs_state_sudden_losses(const cs_state *s, cs_sudden_loss *out, int capacity, cs_error *err) {
    int n = s->outcome == CS_RUNNING ? 0 : s->loss.kept < capacity ? s->loss.kept : capacity;
    if (capacity > 0 &&
        cs_sized_put_array(out, s->loss.found, sizeof *s->loss.found, n, "cs_sudden_loss", err))
        return -1;
    if (err) err->status = CS_OK, err->message[0] = '\0';
    return n;
}

/* Cable c's record over the run so far, at this library's size. */
static cs_cable_summary cable_summary(const cs_state *s, int c) {
    const cs_cable_state *cs = &s->cables[c];
    return (cs_cable_summary){
        .size = sizeof(cs_cable_summary),
        .peak_tension_n = cs->max_tension_seen,
        .peak_tension_time_s = cs->max_tension_time,
        .work_on_vehicle_j = cs->work_on_vehicle,
        .energy_share = s->e_initial_kinetic > 0.0 ? -cs->work_on_vehicle / s->e_initial_kinetic : 0.0};
}

cs_status cs_state_cable_summary(const cs_state *s, int c, cs_cable_summary *out, cs_error *err) {
    if (c < 0 || c >= s->cable_count_alloc) {
        char why[64];
        snprintf(why, sizeof why, "no cable %d (the run has %d)", c, s->cable_count_alloc);
        return cs_sized_refuse(err, "cs_cable_summary", why);
    }
    cs_cable_summary full = cable_summary(s, c);
    return cs_sized_put(out, &full, sizeof full, "cs_cable_summary", err);
}

void cs_summary_cables(const cs_model *model, const cs_state *s, cs_summary *sm) {
    for (int c = 0; c < model->cable_count && c < CS_SUMMARY_CABLES; c++) {
        cs_cable_summary cb = cable_summary(s, c);
        sm->cables[c] = (cs_summary_cable){cb.peak_tension_n, cb.peak_tension_time_s, cb.work_on_vehicle_j,
                                           cb.energy_share};
    }
}

static void end_run(const cs_model *model, cs_state *s, cs_outcome outcome, double value) {
    s->outcome = outcome;
    close_decel_window(model, s);
    cs_summary *sm = &s->summary;
    sm->sudden_loss_count = loss_scan_finish(&s->loss, s->events, s->event_count);
    for (int k = 0; k < CS_SUMMARY_SUDDEN_LOSSES; k++)
        sm->sudden_losses[k] =
            k < s->loss.kept
                ? (cs_summary_loss){s->loss.found[k].t_start_s, s->loss.found[k].t_end_s,
                                    s->loss.found[k].force_before_n, s->loss.found[k].force_after_n}
                : (cs_summary_loss){0};
    if (outcome == CS_STOPPED) {
        s->summary.stop_time_s = s->t;
        cs_event_add(model, s, CS_EVENT_STOPPED, CS_ELEMENT_VEHICLE, 0, value);
    } else if (cs_outcome_exits(outcome)) {
        const double *v = outcome == CS_REDIRECTED ? s->exit_vel : s->vel; /* at the last loss of contact */
        s->summary.exit_speed_mps = value;
        s->summary.exit_angle_deg = atan2(-v[1], fabs(v[0])) / CS_DEG;
        s->summary.exit_time_s = outcome == CS_REDIRECTED ? s->exit_t : s->t;
        cs_event_add(model, s, outcome == CS_REDIRECTED ? CS_EVENT_REDIRECTED : CS_EVENT_BREAKTHROUGH,
                     CS_ELEMENT_VEHICLE, 0, value);
    }
}

/* How the vehicle got through: over or under every cable, if it passed every cable it left behind that way
 * (none broke or was let go by an anchor before it passed it: one it passed stays in the barrier, out of its
 * way, and breaking there later changes nothing of how the vehicle got past it), by the way it passed most;
 * else it broke through. */
static cs_outcome through_how(const cs_model *model, const cs_state *s) {
    int over = 0, under = 0;
    for (int c = 0; c < model->cable_count; c++)
        if (!s->cables[c].passed &&
            (s->cables[c].status == CS_CABLE_BROKEN || s->cables[c].status == CS_CABLE_RELEASED))
            return CS_BREAKTHROUGH;
    for (int i = 0; i < s->event_count; i++) {
        over += s->events[i].type == CS_EVENT_OVERRIDE;
        under += s->events[i].type == CS_EVENT_UNDERRIDE;
    }
    return over + under == 0 ? CS_BREAKTHROUGH : over >= under ? CS_OVERRIDE : CS_UNDERRIDE;
}

void cs_response_give_up(const cs_model *model, cs_state *s, cs_outcome why) {
    /* a vehicle that has left the barrier has been redirected, whatever stops the run on its way out */
    if (s->exit_pending)
        end_run(model, s, CS_REDIRECTED, v3_norm(s->exit_vel));
    else
        end_run(model, s, why, 0.0);
    s->summary.outcome = s->outcome;
}

void cs_response_update(const cs_model *model, cs_state *s) {
    cs_summary *sm = &s->summary;
    double u = v3_dot(s->vel, model->dir);
    update_decel(model, s, u);
    loss_scan_feed(&s->loss, s->t, v3_norm(s->force), s->events, s->event_count);
    sm->cable_count = model->cable_count;
    cs_summary_cables(model, s, sm);
    double pen = face_penetration(model, s);
    if (pen > sm->max_dynamic_penetration_m) sm->max_dynamic_penetration_m = pen;
    sm->working_width_m = fmax(sm->working_width_m, vehicle_reach(model, s));
    for (int p = 0; p < model->post_count; p++) {
        if (!cs_post_in_barrier(&s->posts[p])) continue;
        double top[3];
        cs_post_attachment(model, p, s->posts[p].tilt, s->posts[p].pull, cs_post_upright(&model->posts[p]),
                           model->posts[p].height, top);
        sm->working_width_m = fmax(sm->working_width_m, top[1]);
    }

    int engaged = 0; /* a struck post still standing and bearing holds the vehicle like a cable */
    for (int p = 0; p < model->post_count; p++)
        engaged += s->posts[p].captured && cs_post_in_barrier(&s->posts[p]) && s->posts[p].bearing;
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        engaged += cs->status == CS_CABLE_INTACT && cs->engaged;
        if (cs->max_tension_seen > sm->max_cable_tension_n) sm->max_cable_tension_n = cs->max_tension_seen;
        for (int i = 0; cs->status == CS_CABLE_INTACT && i < cs->node_count; i++)
            if (cs->pos[3 * i + 1] > sm->max_barrier_deflection_m)
                sm->max_barrier_deflection_m = cs->pos[3 * i + 1];
    }
    sm->cables_broken = 0;
    for (int c = 0; c < model->cable_count; c++)
        sm->cables_broken += s->cables[c].status == CS_CABLE_BROKEN;
    sm->posts_failed_left = sm->posts_failed_right = 0;
    sm->posts_failed_rotation_left = sm->posts_failed_rotation_right = 0;
    sm->posts_failed_shear_left = sm->posts_failed_shear_right = 0;
    sm->posts_failed_pullout_left = sm->posts_failed_pullout_right = 0;
    for (int p = 0; p < model->post_count; p++) {
        cs_post_status st = s->posts[p].status; /* a post down on the ground has failed, its ropes kept */
        if (cs_post_in_barrier(&s->posts[p]) && st != CS_POST_DOWN) continue;
        int right = model->posts[p].x >= model->scenario.impact_x;
        if (right)
            sm->posts_failed_right++;
        else
            sm->posts_failed_left++;
        *(right ? &sm->posts_failed_rotation_right : &sm->posts_failed_rotation_left) +=
            st == CS_POST_FAILED_ROTATION || st == CS_POST_DOWN;
        *(right ? &sm->posts_failed_shear_right : &sm->posts_failed_shear_left) += st == CS_POST_FAILED_SHEAR;
        *(right ? &sm->posts_failed_pullout_right : &sm->posts_failed_pullout_left) +=
            st == CS_POST_FAILED_PULLOUT;
    }
    sm->working_width_m = fmax(sm->working_width_m, sm->max_barrier_deflection_m);
    sm->t_end_s = s->t;
    v3_copy(sm->final_position_m, s->pos);

    /* moving back to the traffic side when contact ends, even with a cable slipped under it or its CG
     * still past the line (it straddles the cables on its way out): its exit, unless it comes back */
    if (!s->contact_started || engaged)
        s->exit_pending = 0;
    else if (!s->exit_pending && s->vel[1] < 0.0) {
        s->exit_pending = 1;
        s->exit_t = s->t;
        v3_copy(s->exit_vel, s->vel);
    }
    int end = s->t >= model->scenario.t_end - 0.5 * model->scenario.dt;
    if (s->exit_pending) {
        /* redirected once it has gone its own length at its exit speed without touching the barrier
         * again (a swing of its tail or nose back onto the ropes is part of the same impact, a return
         * later on is another), or has come to rest */
        const cs_vehicle_def *v = &model->vehicle.def;
        double gone = (s->t - s->exit_t) * v3_norm(s->exit_vel);
        if (end || gone >= v->cg_to_front + v->cg_to_rear || v3_norm(s->vel) <= model->scenario.stop_speed)
            end_run(model, s, CS_REDIRECTED, v3_norm(s->exit_vel));
    } else if (s->contact_started && u <= model->scenario.stop_speed) {
        end_run(model, s, CS_STOPPED, sm->max_dynamic_penetration_m);
    } else if (s->contact_started && engaged == 0 && s->pos[1] > 0.0) {
        end_run(model, s, through_how(model, s), v3_norm(s->vel));
    } else if (end) {
        end_run(model, s, s->contact_started ? CS_TIME_LIMIT : CS_NO_CONTACT, 0.0);
    }
    sm->outcome = s->outcome;
}
