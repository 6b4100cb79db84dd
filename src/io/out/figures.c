/* SPDX-License-Identifier: MIT */
/* The figures of a run (figures.h). Every time series comes from the recorded frames (record.h), every
 * marked failure from the events; nothing here recomputes the physics. */
#include "cablesim/units.h"
#include "figures_int.h"
#include "numtext.h"
#include "status.h"
#include "writers.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* y at time tq, linear between frames. */
static double value_at(const double *t, const double *y, int n, double tq) {
    if (n == 0) return NAN;
    for (int i = 0; i + 1 < n; i++)
        if (tq <= t[i + 1]) {
            double u = t[i + 1] > t[i] ? (tq - t[i]) / (t[i + 1] - t[i]) : 1;
            return y[i] + fmax(0, u) * (y[i + 1] - y[i]);
        }
    return y[n - 1];
}

/* Axes over the run's time, from its start to its end (not rounded out to a tick), y from zero, titled
 * "<model>: what" (d NULL: what alone) in title, which the axes keep; y2label and y2_scale as in cs_axes
 * (NULL, 0: no right axis). */
static void time_axes(cs_axes *a, char *title, const cs_figure_data *d, const char *what, const char *ylabel,
                      const char *y2label, double y2_scale, const double *t, int n) {
    snprintf(title, TITLE_SIZE, "%s%s%s", d ? d->in->name : "", d ? ": " : "", what);
    cs_axes_init(a, title, "time (s)", ylabel);
    a->y2label = y2label;
    a->y2_scale = y2_scale;
    if (n > 0) cs_axes_set_x(a, fmin(0, t[0]), t[n - 1]);
    cs_axes_fit_point(a, NAN, 0);
}

/* A point marker on a curve at time tq, with a legend entry once per kind (*shown). */
static void mark_at(cs_plot *p, cs_axes *a, const double *t, const double *y, int n, double tq,
                    const cs_style *s, const char *legend, int *shown) {
    double x = tq, v = value_at(t, y, n, tq);
    cs_plot_line(p, a, &x, &v, 1, s, *shown ? NULL : legend);
    *shown = 1;
}

/* ---- 1: deceleration ---- */

static void fig_deceleration(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    int n = r->frame_count, imax = -1;
    double *raw = t + n, *avg = t + 2 * n;
    double ux = cos(d->in->scenario.angle), uy = sin(d->in->scenario.angle);
    for (int i = 0; i < n; i++) {
        const cs_vehicle_view *v = &r->vehicle[i];
        raw[i] = -(v->acceleration[0] * ux + v->acceleration[1] * uy) / CS_G0;
        /* the average exists once a whole window has passed */
        avg[i] = v->t > 0.05 + 0.5 * d->in->scenario.dt ? v->decel_50ms_g : NAN;
        if (isfinite(avg[i]) && (imax < 0 || avg[i] > avg[imax])) imax = i;
    }
    char title[TITLE_SIZE], note[96];
    cs_axes a;
    time_axes(&a, title, d, "deceleration of the CG along the initial travel direction", "deceleration (g)",
              NULL, 0, t, n);
    cs_axes_fit(&a, NULL, raw, n);
    cs_axes_layout(p, &a, whole(p));
    cs_style zero = line(GREY, 1);
    cs_plot_hline(p, &a, 0, &zero, NULL);
    cs_style s_raw = line((cs_rgb){0.55, 0.70, 0.90}, 1.2), s_avg = line((cs_rgb){0.05, 0.25, 0.60}, 3);
    cs_plot_line(p, &a, t, raw, n, &s_raw, "raw (every recorded frame)");
    cs_plot_line(p, &a, t, avg, n, &s_avg, "50-ms moving average (defined from t = 50 ms)");
    /* the largest 50-ms average: the run's (every step), as the terminal and summary.json give it, else
     * the frames' */
    double tq = imax >= 0 ? t[imax] : NAN, gq = imax >= 0 ? avg[imax] : NAN;
    if (d->summary && d->summary->max_50ms_decel_g > 0)
        tq = d->summary->t_max_50ms_decel_s, gq = d->summary->max_50ms_decel_g;
    if (isfinite(tq)) {
        char tt[CS_TIME_TEXT_SIZE];
        cs_style m = mark(RED, CS_MARK_CIRCLE, 13);
        cs_plot_line(p, &a, &tq, &gq, 1, &m, "largest 50-ms average");
        snprintf(note, sizeof note, "max %.2f g at t = %s s", gq, cs_time_text(tq, tt));
        cs_plot_label(p, &a, tq, gq, 12, -16, 0, note);
    }
    cs_plot_legend(p, &a, CS_LEGEND_TOP_RIGHT);
}

/* ---- 2: speed ---- */

static void fig_speed(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    int n = r->frame_count;
    double *u = t + n;
    for (int i = 0; i < n; i++)
        u[i] = r->vehicle[i].forward_speed;
    char title[TITLE_SIZE], note[128];
    cs_axes a;
    time_axes(&a, title, d, "speed of the CG along the initial travel direction", "speed (m/s)",
              "speed (mph)", 1 / CS_MPH, t, n);
    cs_axes_fit(&a, NULL, u, n);
    cs_axes_layout(p, &a, whole(p));
    cs_style s = line(cs_plot_palette(0), 3);
    cs_plot_line(p, &a, t, u, n, &s, "forward speed");
    for (int k = 0; k < d->event_count; k++) {
        const cs_event *e = &d->events[k];
        if (e->type != CS_EVENT_STOPPED && e->type != CS_EVENT_BREAKTHROUGH && e->type != CS_EVENT_REDIRECTED)
            continue;
        int shown = 0;
        char tt[CS_TIME_TEXT_SIZE];
        cs_style m = mark(RED, CS_MARK_DIAMOND, 14);
        mark_at(p, &a, t, u, n, e->t, &m, cs_event_type_name(e->type), &shown);
        if (e->type == CS_EVENT_STOPPED)
            snprintf(note, sizeof note, "stopped at t = %s s", cs_time_text(e->t, tt));
        else if (e->type == CS_EVENT_REDIRECTED) /* the run ends a vehicle's length past the exit */
            snprintf(note, sizeof note,
                     "redirected: the run ends at t = %s s, a vehicle's length after it left the ropes at "
                     "%.1f m/s (%.1f mph)",
                     cs_time_text(e->t, tt), e->value, e->value / CS_MPH);
        else
            snprintf(note, sizeof note,
                     "broke through at t = %s s, leaving at %.1f m/s (%.1f mph), its whole speed",
                     cs_time_text(e->t, tt), e->value, e->value / CS_MPH);
        cs_plot_label(p, &a, e->t, value_at(t, u, n, e->t), -12, 22, 1, note);
    }
    cs_plot_legend(p, &a, CS_LEGEND_BOTTOM_LEFT);
}

/* ---- 3: penetration ---- */

static void fig_penetration(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    int n = r->frame_count, nc = r->cable_count, imax = -1;
    double *face = t + n, *pen = t + 2 * n, *cable = t + 3 * n;
    for (int i = 0; i < n; i++) {
        const cs_vehicle_view *v = &r->vehicle[i];
        face[i] = fmax(v->front_corners[0][1], v->front_corners[1][1]);
        pen[i] = v->penetration;
        if (imax < 0 || pen[i] > pen[imax]) imax = i;
        cable[i] = NAN;
        for (int c = 0; c < nc; c++) {
            size_t k = (size_t)i * (size_t)nc + (size_t)c;
            if (!cs_cable_status_holds(r->cables[k].status)) continue;
            for (int j = 0; j < r->path_count[k]; j++) {
                double y = r->path_xyz[(k * (size_t)r->max_nodes + (size_t)j) * 3 + 1];
                if (!(y <= cable[i])) cable[i] = y;
            }
        }
    }
    char title[TITLE_SIZE], note[96];
    cs_axes a;
    time_axes(&a, title, d, "penetration past the attack face (y = 0)", "distance past the attack face (m)",
              "distance past the attack face (ft)", 1 / CS_FT, t, n);
    cs_axes_fit(&a, NULL, face, 3 * n); /* face, pen and cable follow each other */
    cs_axes_layout(p, &a, whole(p));
    /* widest first: where the curves coincide (the face pushing the cables) all three stay visible */
    cs_style zero = line(GREY, 1.5), s_face = line((cs_rgb){0.60, 0.78, 0.95}, 8), s_pen = line(RED, 2.5),
             s_cable = dashed((cs_rgb){0.05, 0.50, 0.10}, 3.5);
    cs_plot_hline(p, &a, 0, &zero, "attack face (cable line before impact)");
    cs_plot_line(p, &a, t, face, n, &s_face, "front face now (mid-height corners)");
    cs_plot_line(p, &a, t, pen, n, &s_pen, "dynamic penetration (largest so far, any face corner)");
    cs_plot_line(p, &a, t, cable, n, &s_cable, "barrier deflection (furthest point of a cable that holds)");
    if (imax >= 0) {
        snprintf(note, sizeof note, "max %.2f m (%.1f ft)", pen[imax], pen[imax] / CS_FT);
        cs_plot_label(p, &a, t[imax], pen[imax], -8, -16, 1, note);
    }
    cs_plot_legend(p, &a, CS_LEGEND_BOTTOM_RIGHT);
}

/* ---- 4: cable tensions ---- */

static void fig_cables(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    const cs_barrier_def *b = &d->in->barrier;
    int n = r->frame_count, nc = r->cable_count;
    for (int c = 0; c < nc; c++)
        for (int i = 0; i < n; i++)
            t[(size_t)(1 + c) * (size_t)n + (size_t)i] =
                r->cables[(size_t)i * (size_t)nc + (size_t)c].max_tension / 1e3;
    char title[TITLE_SIZE], label[CS_LABEL_SIZE];
    cs_axes a;
    time_axes(&a, title, d, "tension of each cable (largest span)", "tension (kN)", "tension (kip)",
              1e3 / CS_KIP, t, n);
    cs_axes_fit(&a, NULL, t + n, n * nc);
    int same = 1;
    for (int c = 0; c < b->cable_count; c++) {
        cs_axes_fit_point(&a, NAN, b->cables[c].rope.nominal_strength / 1e3);
        same &= b->cables[c].rope.nominal_strength == b->cables[0].rope.nominal_strength;
    }
    int kinds[3] = {0, 0, 0}; /* the legend's rows: the strengths, the cables, each kind of event */
    for (int k = 0; k < d->event_count; k++)
        if (d->events[k].element_kind == CS_ELEMENT_CABLE && d->events[k].element >= 0 &&
            d->events[k].element < nc)
            kinds[0] |= d->events[k].type == CS_EVENT_CABLE_BREAK,
                kinds[1] |= d->events[k].type == CS_EVENT_OVERRIDE,
                kinds[2] |= d->events[k].type == CS_EVENT_UNDERRIDE;
    a.legend_rows =
        (same ? 1 : (b->cable_count < nc ? b->cable_count : nc)) + nc + kinds[0] + kinds[1] + kinds[2];
    cs_axes_layout(p, &a, whole(p));
    for (int c = 0; c < b->cable_count && c < nc; c++) {
        double fu = b->cables[c].rope.nominal_strength;
        if (same && c > 0) break;
        snprintf(label, sizeof label, "rope strength Fu%s = %.0f kN (%.0f kip)", same ? "" : " of this cable",
                 fu / 1e3, fu / CS_KIP);
        cs_style s = dashed(same ? BLACK : cs_plot_palette(c), 1.5);
        cs_plot_hline(p, &a, fu / 1e3, &s, label);
    }
    for (int c = 0; c < nc; c++) {
        double h = c < b->cable_count ? b->cables[c].height : NAN;
        snprintf(label, sizeof label, "cable %d at %.2f m (%.2f ft)", c, h, h / CS_FT);
        cs_style s = line(cs_plot_palette(c), 2.5);
        cs_plot_line(p, &a, t, t + (size_t)(1 + c) * (size_t)n, n, &s, label);
    }
    int shown[3] = {0, 0, 0};
    for (int k = 0; k < d->event_count; k++) {
        const cs_event *e = &d->events[k];
        if (e->element_kind != CS_ELEMENT_CABLE || e->element < 0 || e->element >= nc) continue;
        const double *y = t + (size_t)(1 + e->element) * (size_t)n;
        if (e->type == CS_EVENT_CABLE_BREAK) {
            cs_style m = mark(RED, CS_MARK_CROSS, 16);
            double x = e->t, v = e->value / 1e3;
            cs_plot_line(p, &a, &x, &v, 1, &m, shown[0]++ ? NULL : "cable breaks");
            snprintf(label, sizeof label, "cable %d breaks, %.0f kN", e->element, v);
            cs_plot_label(p, &a, x, v, 12, -14, 0, label);
        } else if (e->type == CS_EVENT_OVERRIDE || e->type == CS_EVENT_UNDERRIDE) {
            int over = e->type == CS_EVENT_OVERRIDE;
            cs_style m = mark(cs_plot_palette(e->element), over ? CS_MARK_TRIANGLE : CS_MARK_DIAMOND, 13);
            mark_at(p, &a, t, y, n, e->t, &m,
                    over ? "the vehicle rides over the cable" : "the vehicle runs under the cable",
                    &shown[1 + !over]);
            snprintf(label, sizeof label, "%s cable %d", over ? "over" : "under", e->element);
            cs_plot_label(p, &a, e->t, value_at(t, y, n, e->t), 0, -18, 0.5, label);
        }
    }
    cs_plot_legend(p, &a, CS_LEGEND_TOP_RIGHT);
}

/* ---- 5: the posts nearest the impact ---- */

static int is_failure(cs_event_type type) {
    return type == CS_EVENT_POST_ROTATION_LIMIT || type == CS_EVENT_POST_SHEAR ||
           type == CS_EVENT_POST_PULLOUT;
}

/* Whether post p has a rotation limit to draw: a tilt short of 90 degrees past which a struck post goes
 * (a post hinged at grade has none of its own: it goes when its top comes down to the edge). */
static int has_limit(const cs_record *r, int p) {
    return r->posts[p].rotation_limit < 0.5 * CS_PI - 1e-9;
}

/* The k-th of the nearest posts idx is the mirror image of an earlier one about the impact point: as
 * far from it on the other side, its moment and tilt the same at every frame (within 0.1% of the largest,
 * a curve ending at the same frame). That one's index in idx, or -1. */
static int mirror_of(const cs_figure_data *d, const int *idx, int k, const double *moment, const double *tilt,
                     int n) {
    const cs_post_def *posts = d->in->barrier.posts;
    double xi = d->in->scenario.impact_x, dk = posts[idx[k]].x - xi;
    for (int j = 0; j < k; j++) {
        if (fabs(posts[idx[j]].x - xi + dk) > 1e-6 * fmax(1, fabs(dk)) || fabs(dk) < 1e-9) continue;
        int same = 1;
        for (int m = 0; m < 2 && same; m++) {
            const double *a = (m ? tilt : moment) + (size_t)j * (size_t)n,
                         *b = (m ? tilt : moment) + (size_t)k * (size_t)n;
            double big = 0;
            for (int i = 0; i < n; i++)
                big = fmax(big, fmax(isfinite(a[i]) ? fabs(a[i]) : 0, isfinite(b[i]) ? fabs(b[i]) : 0));
            for (int i = 0; i < n && same; i++)
                same = isfinite(a[i]) == isfinite(b[i]) && !(fabs(a[i] - b[i]) > 1e-3 * big);
        }
        if (same) return j;
    }
    return -1;
}

static void fig_posts(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    const cs_post_def *posts = d->in->barrier.posts;
    int n = r->frame_count, np = r->post_count, idx[NEAR_POSTS];
    int count = cs_nearest_posts(d->in, idx, np < NEAR_POSTS ? np : NEAR_POSTS);
    double *moment = t + n, *tilt = t + (size_t)(1 + NEAR_POSTS) * (size_t)n;
    /* a curve ends where its post fails: a failed post carries nothing */
    for (int k = 0; k < count; k++)
        for (int i = 0, failed = 0; i < n; i++) {
            const cs_post_view *v = &r->posts[(size_t)i * (size_t)np + (size_t)idx[k]];
            moment[(size_t)k * (size_t)n + (size_t)i] = failed ? NAN : v->base_moment / 1e3;
            tilt[(size_t)k * (size_t)n + (size_t)i] = failed ? NAN : v->tilt * 180 / CS_PI;
            failed = cs_fig_post_rank(v->status) == 2;
        }
    char title[TITLE_SIZE], label[CS_LABEL_SIZE], mtitle[TITLE_SIZE], ttitle[TITLE_SIZE];
    snprintf(title, sizeof title, "%s: the %d posts nearest the impact point (x = %.2f m, %.2f ft)",
             d->in->name, count, d->in->scenario.impact_x, d->in->scenario.impact_x / CS_FT);
    cs_plot_text(p, 0.5 * p->width, MARGIN + 14, 18, 1, 0.5, title);
    double half = 0.5 * (p->height - 40 - 2 * MARGIN);
    cs_axes am, at;
    time_axes(&am, mtitle, NULL, "base moment (a curve ends where its post fails)", "base moment (kN·m)",
              NULL, 0, t, n);
    time_axes(&at, ttitle, NULL, "tilt from vertical", "tilt (deg)", NULL, 0, t, n);
    am.legend_width = at.legend_width = 430;
    cs_axes_fit(&am, NULL, moment, n * count);
    cs_axes_fit(&at, NULL, tilt, n * count);
    for (int k = 0; k < count && n > 0; k++) {
        cs_axes_fit_point(&am, NAN, r->posts[idx[k]].moment_capacity / 1e3);
        if (has_limit(r, idx[k])) cs_axes_fit_point(&at, NAN, r->posts[idx[k]].rotation_limit * 180 / CS_PI);
    }
    cs_axes_layout(p, &am, (cs_box){MARGIN, MARGIN + 40, p->width - 2 * MARGIN, half});
    cs_axes_layout(p, &at, (cs_box){MARGIN, MARGIN + 40 + half, p->width - 2 * MARGIN, half});
    /* limits, once per distinct value, naming the posts it is theirs */
    for (int k = 0; k < count && n > 0; k++) {
        double cap = r->posts[idx[k]].moment_capacity, lim = r->posts[idx[k]].rotation_limit;
        int new_cap = 1, new_lim = has_limit(r, idx[k]), len;
        for (int j = 0; j < k; j++) {
            new_cap &= r->posts[idx[j]].moment_capacity != cap;
            new_lim &= r->posts[idx[j]].rotation_limit != lim;
        }
        cs_style s = dashed(BLACK, 1.5);
        if (new_cap) {
            len = snprintf(label, sizeof label, "capacity %.1f kN·m, %.1f kip·ft (post", cap / 1e3,
                           cap / (CS_KIP * CS_FT));
            for (int j = k, m = 0; j < count; j++)
                if (r->posts[idx[j]].moment_capacity == cap && len < (int)sizeof label - 8)
                    len += snprintf(label + len, sizeof label - (size_t)len, "%s %d", m++ ? "," : "", idx[j]);
            snprintf(label + len, sizeof label - (size_t)len, ")");
            cs_plot_hline(p, &am, cap / 1e3, &s, label);
        }
        snprintf(label, sizeof label, "rotation limit %.0f deg", lim * 180 / CS_PI);
        if (new_lim) cs_plot_hline(p, &at, lim * 180 / CS_PI, &s, label);
    }
    /* a wide line under a narrow one: mirror posts of a centred impact coincide and both show */
    for (int k = 0; k < count; k++) {
        cs_style s = line(cs_plot_palette(k), k % 2 ? 2.2 : 6.5);
        int len = snprintf(label, sizeof label, "post %d at x = %.2f m (%.1f ft)", idx[k], posts[idx[k]].x,
                           posts[idx[k]].x / CS_FT);
        int j = mirror_of(d, idx, k, moment, tilt, n);
        if (j >= 0) snprintf(label + len, sizeof label - (size_t)len, ": mirror image of post %d", idx[j]);
        cs_plot_line(p, &am, t, moment + (size_t)k * (size_t)n, n, &s, label);
        cs_plot_line(p, &at, t, tilt + (size_t)k * (size_t)n, n, &s, label);
    }
    int shown[2][2] = {{0, 0}, {0, 0}};
    for (int e = 0; e < d->event_count; e++) {
        const cs_event *ev = &d->events[e];
        int fail = is_failure(ev->type),
            yield = ev->type == CS_EVENT_POST_HINGE || ev->type == CS_EVENT_FOOTING_ROTATION;
        if (ev->element_kind != CS_ELEMENT_POST || (!fail && !yield)) continue;
        for (int k = 0; k < count; k++) {
            if (idx[k] != ev->element) continue;
            cs_style m = fail ? mark(RED, CS_MARK_CROSS, 15) : mark(cs_plot_palette(k), CS_MARK_CIRCLE, 11);
            const char *what = fail ? "post fails" : "post yields (hinge or soil)";
            mark_at(p, &am, t, moment + (size_t)k * (size_t)n, n, ev->t, &m, what, &shown[0][fail]);
            mark_at(p, &at, t, tilt + (size_t)k * (size_t)n, n, ev->t, &m, what, &shown[1][fail]);
        }
    }
    cs_plot_legend(p, &am, CS_LEGEND_OUTSIDE_RIGHT);
    cs_plot_legend(p, &at, CS_LEGEND_OUTSIDE_RIGHT);
}

/* ---- 6: the energy ledger ---- */

static const struct {
    const char *label;
    size_t offset;
    cs_rgb color;
} ledger[] = {
    /* bottom to top: what is gone for good, what is stored, what still moves */
    {"crush of the vehicle", offsetof(cs_energy, crush), {0.80, 0.20, 0.20}},
    {"post plastic (hinges)", offsetof(cs_energy, post_plastic), {0.20, 0.55, 0.25}},
    {"post swing damping", offsetof(cs_energy, post_damping), {0.40, 0.65, 0.45}},
    {"soil (footings, posts, dead-men)", offsetof(cs_energy, soil), {0.55, 0.38, 0.22}},
    {"cable plastic", offsetof(cs_energy, cable_plastic), {0.90, 0.50, 0.10}},
    {"rail plastic (yield, buckling)", offsetof(cs_energy, rail_plastic), {0.30, 0.32, 0.40}},
    {"friction (tyres, rope sliding)", offsetof(cs_energy, friction), {0.55, 0.40, 0.75}},
    {"released at failures", offsetof(cs_energy, released), {0.85, 0.50, 0.70}},
    {"post elastic", offsetof(cs_energy, post_elastic), {0.55, 0.80, 0.50}},
    {"post kinetic (swing)", offsetof(cs_energy, post_kinetic), {0.70, 0.88, 0.62}},
    {"cable elastic", offsetof(cs_energy, cable_elastic), {0.98, 0.78, 0.40}},
    {"rail elastic", offsetof(cs_energy, rail_elastic), {0.62, 0.66, 0.76}},
    {"anchor elastic (soil spring)", offsetof(cs_energy, anchor_elastic), {0.90, 0.85, 0.55}},
    {"anchor kinetic (slide)", offsetof(cs_energy, anchor_kinetic), {0.62, 0.78, 0.85}},
    {"vehicle potential", offsetof(cs_energy, vehicle_potential), {0.70, 0.70, 0.70}},
    {"vehicle kinetic", offsetof(cs_energy, vehicle_kinetic), {0.35, 0.60, 0.90}},
};
enum { LEDGER_TERMS = sizeof ledger / sizeof ledger[0] };
_Static_assert((int)LEDGER_TERMS == (int)CS_ENERGY_TERMS,
               "the energy figure stacks every term of the ledger");

static double ledger_term(const cs_energy *e, int k) {
    double v;
    memcpy(&v, (const char *)e + ledger[k].offset, sizeof v);
    return v;
}

static void fig_energy(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    int n = r->frame_count, used = 0;
    double *sum = t + n, *y = t + 2 * n;
    const char *labels[LEDGER_TERMS];
    cs_rgb fills[LEDGER_TERMS];
    double ke0 = n ? r->energy[0].initial_kinetic : 0, total0 = n ? r->energy[0].initial_total : 0;
    for (int i = 0; i < n; i++)
        sum[i] = 0;
    for (int k = 0; k < LEDGER_TERMS; k++) {
        double *v = y + (size_t)used * (size_t)n, big = 0;
        for (int i = 0; i < n; i++) {
            v[i] = ledger_term(&r->energy[i], k) / 1e3;
            sum[i] += v[i];
            big = fmax(big, fabs(v[i]));
        }
        if (big <= 1e-6 * fmax(ke0 / 1e3, 1e-3)) continue; /* a term that stays zero takes no band */
        labels[used] = ledger[k].label;
        fills[used++] = ledger[k].color;
    }
    char title[TITLE_SIZE], label[CS_LABEL_SIZE];
    snprintf(label, sizeof label, "energy ledger (balance error at the end %.2f %%)",
             n ? 100 * r->energy[n - 1].balance_error : 0.0);
    cs_axes a;
    time_axes(&a, title, d, label, "energy (kJ)", NULL, 0, t, n);
    a.legend_width = 330;
    cs_axes_fit(&a, NULL, sum, n);
    cs_axes_fit_point(&a, NAN, total0 / 1e3);
    cs_axes_layout(p, &a, whole(p));
    cs_plot_stack(p, &a, t, y, used, n, fills, labels);
    cs_style s_sum = line(BLACK, 1.5), s_ke = dashed(BLACK, 2.5),
             s_tot = (cs_style){RED, 2, CS_DOTTED, CS_MARK_NONE, 0};
    cs_plot_line(p, &a, t, sum, n, &s_sum, "sum of the terms");
    snprintf(label, sizeof label, "initial kinetic energy %.1f kJ", ke0 / 1e3);
    cs_plot_hline(p, &a, ke0 / 1e3, &s_ke, label);
    if (total0 - ke0 > 1e-3 * ke0) {
        snprintf(label, sizeof label, "initial total (with pretension) %.1f kJ", total0 / 1e3);
        cs_plot_hline(p, &a, total0 / 1e3, &s_tot, label);
    }
    cs_plot_legend(p, &a, CS_LEGEND_OUTSIDE_RIGHT);
}

/* ---- 8: roll, pitch and yaw ---- */

static void fig_angles(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    int n = r->frame_count;
    double *y = t + n; /* roll, pitch, yaw from its initial heading: 3 series of n, deg */
    for (int i = 0; i < n; i++) {
        const cs_vehicle_view *v = &r->vehicle[i];
        y[i] = v->roll / CS_DEG;
        y[n + i] = v->pitch / CS_DEG;
        y[2 * n + i] = (v->yaw - r->vehicle[0].yaw) / CS_DEG;
    }
    char title[TITLE_SIZE], label[CS_LABEL_SIZE];
    cs_axes a;
    time_axes(&a, title, d, "roll, pitch and yaw of the vehicle", "angle (deg)", NULL, 0, t, n);
    a.legend_width = 440;
    cs_axes_fit(&a, NULL, y, 3 * n);
    cs_axes_layout(p, &a, whole(p));
    cs_style zero = line(GREY, 1);
    cs_plot_hline(p, &a, 0, &zero, NULL);
    static const char *const names[3] = {"roll (right side down +)", "pitch (nose down +)",
                                         "yaw from the initial heading"};
    for (int k = 0; k < 3; k++) {
        const double *s = y + (size_t)k * (size_t)n;
        int at = -1;
        for (int i = 0; i < n; i++)
            if (at < 0 || fabs(s[i]) > fabs(s[at])) at = i;
        cs_style st = line(cs_plot_palette(k), k == 2 ? 2.5 : 3);
        if (at >= 0) {
            char tt[CS_TIME_TEXT_SIZE];
            snprintf(label, sizeof label, "%s: peak %.1f deg at %s s", names[k], s[at],
                     cs_time_text(t[at], tt));
            cs_plot_line(p, &a, t, s, n, &st, label);
            cs_style m = mark(cs_plot_palette(k), CS_MARK_CIRCLE, 11);
            cs_plot_line(p, &a, &t[at], &s[at], 1, &m, NULL);
        } else {
            cs_plot_line(p, &a, t, s, n, &st, names[k]);
        }
    }
    cs_plot_legend(p, &a, CS_LEGEND_OUTSIDE_RIGHT);
}

/* ---- 9: the path in plan, with the exit box ---- */

/* How far past the run's end the path is drawn straight on (s, 0: not at all): until every wheel is past
 * the exit box's line (a box given) or 10 m on, at most 60 m; only for a vehicle heading back to the
 * traffic side (y < 0). */
static double path_after(const cs_figure_data *d, double w[4][2]) {
    const cs_record *r = d->rec;
    const cs_vehicle_view *e = &r->vehicle[r->frame_count - 1];
    double vx = e->velocity[0], vy = e->velocity[1], speed = hypot(vx, vy);
    if (!(vy < 0) || !(speed > 0)) return 0;
    double tt = 10 / speed;
    if (d->exit_box)
        for (int k = 0; k < 4; k++)
            tt = fmax(tt, (-d->exit_box->a - 1 - w[k][1]) / vy);
    return fmin(tt, 60 / speed);
}

static void fig_path(cs_plot *p, const cs_figure_data *d, double *t) {
    const cs_record *r = d->rec;
    const cs_barrier_def *b = &d->in->barrier;
    const cs_exit_box *box = d->exit_box;
    int n = r->frame_count;
    double *cx = t + n, *cy = t + 2 * n, *wx = t + 3 * n, *wy = t + 7 * n; /* CG, then 4 wheels' x and y */
    double w[4][2];
    for (int i = 0; i < n; i++) {
        cs_vehicle_wheels(&r->vehicle[i], &d->in->vehicle, w);
        cx[i] = r->vehicle[i].position[0], cy[i] = r->vehicle[i].position[1];
        for (int k = 0; k < 4; k++)
            wx[(size_t)k * (size_t)n + (size_t)i] = w[k][0], wy[(size_t)k * (size_t)n + (size_t)i] = w[k][1];
    }
    double after = n > 0 ? path_after(d, w) : 0, ex[2][5], ey[2][5]; /* straight on: CG, wheels */
    if (after > 0) {
        const double *v = r->vehicle[n - 1].velocity;
        for (int k = 0; k < 5; k++) {
            ex[0][k] = k ? w[k - 1][0] : cx[n - 1], ey[0][k] = k ? w[k - 1][1] : cy[n - 1];
            ex[1][k] = ex[0][k] + v[0] * after, ey[1][k] = ey[0][k] + v[1] * after;
        }
    }
    char title[TITLE_SIZE], label[CS_LABEL_SIZE];
    snprintf(title, sizeof title, "%s: the vehicle's path in plan", d->in->name);
    cs_axes a;
    cs_axes_init(&a, title, "x, along the barrier (m)", "y, toward the protected side (m)");
    a.equal = 1;
    a.legend_width = 500;
    cs_axes_fit(&a, cx, cy, n);
    cs_axes_fit(&a, wx, wy, 4 * n);
    for (int k = 0; k < 2 && n > 0; k++) { /* the vehicle at the start and the end */
        double u[4], v[4];
        cs_fig_outline(&d->in->vehicle, &r->vehicle[k ? n - 1 : 0], 0, u, v);
        cs_axes_fit(&a, u, v, 4);
    }
    for (int k = 0; k < 5 && after > 0; k++)
        cs_axes_fit_point(&a, ex[1][k], ey[1][k]);
    double bx[4] = {0}, by[4] = {0};
    if (box) {
        double x1 = box->start_x + box->dir * box->b;
        const double px[4] = {box->start_x, x1, x1, box->start_x}, py[4] = {0, 0, -box->a, -box->a};
        memcpy(bx, px, sizeof bx), memcpy(by, py, sizeof by);
        cs_axes_fit(&a, bx, by, 4);
    }
    cs_axes_fit_point(&a, NAN, 0);
    if (n == 0) /* no run to show: the barrier about the impact point */
        cs_axes_fit_point(&a, d->in->scenario.impact_x - 5, 0),
            cs_axes_fit_point(&a, d->in->scenario.impact_x + 5, 0);
    double xa = fmax(b->start_anchor.x, a.x0 - 2), xb = fmin(b->end_anchor.x, a.x1 + 2);
    cs_axes_fit_point(&a, a.x0 - 1, a.y0 - 1); /* a metre clear of the frame all round */
    cs_axes_fit_point(&a, a.x1 + 1, a.y1 + 1);
    cs_axes_layout(p, &a, whole(p));
    if (box) {
        cs_rgb fill = {0.88, 0.95, 0.88};
        cs_style edge = dashed((cs_rgb){0.10, 0.50, 0.15}, 2),
                 far = (cs_style){RED, 1.5, CS_DOTTED, CS_MARK_NONE, 0};
        int mash = d->standard && strcmp(d->standard, "mash") == 0;
        snprintf(label, sizeof label,
                 mash ? "MASH's exit box: A = %.2f m across, B = %.1f m along"
                      : "MASH's exit box, A = %.2f m, B = %.1f m (not in NCHRP 350)",
                 box->a, box->b);
        cs_plot_polygon(p, &a, bx, by, 4, &fill, &edge);
        cs_axes_legend_add(&a, CS_LEGEND_LINE, &edge, label);
        cs_plot_hline(p, &a, -box->a, &far, "the box's far side, extended (y = -A)");
    }
    cs_style face = line(BLACK, 3), post = mark(GREY, CS_MARK_SQUARE, 7);
    cs_plot_segment(p, &a, xa, 0, xb, 0, &face);
    cs_axes_legend_add(&a, CS_LEGEND_LINE, &face, "the barrier's line before impact (y = 0)");
    for (int q = 0, shown = 0; q < b->post_count; q++) {
        double x = b->posts[q].x, y0 = 0;
        if (x < a.x0 || x > a.x1) continue;
        cs_plot_line(p, &a, &x, &y0, 1, &post, shown++ ? NULL : "posts (where they stood)");
    }
    cs_rgb body_fill = {0.85, 0.85, 0.85};
    cs_style edge = line(GREY, 1.5);
    for (int k = 0; k < 2 && n > 0; k++) {
        double u[4], v[4];
        cs_fig_outline(&d->in->vehicle, &r->vehicle[k ? n - 1 : 0], 0, u, v);
        cs_plot_polygon(p, &a, u, v, 4, &body_fill, &edge);
    }
    if (n > 0)
        cs_axes_legend_add(&a, CS_LEGEND_AREA, &(cs_style){body_fill, 0, CS_SOLID, CS_MARK_NONE, 0},
                           "the vehicle at the start and the end of the run");
    cs_style wheel = line((cs_rgb){0.45, 0.45, 0.45}, 1.2), cg = line(cs_plot_palette(0), 3);
    for (int k = 0; k < 4; k++)
        cs_plot_line(p, &a, wx + (size_t)k * (size_t)n, wy + (size_t)k * (size_t)n, n, &wheel,
                     k ? NULL : "wheel tracks");
    cs_plot_line(p, &a, cx, cy, n, &cg, "path of the CG in the run");
    if (after > 0) {
        cs_style on = dashed(cs_plot_palette(0), 2);
        for (int k = 0; k < 5; k++)
            cs_plot_segment(p, &a, ex[0][k], ey[0][k], ex[1][k], ey[1][k], &on);
        snprintf(label, sizeof label, "after the run: straight on along the last velocity (%.1f s)", after);
        cs_axes_legend_add(&a, CS_LEGEND_LINE, &on, label);
    }
    if (box && isfinite(box->cross_along)) {
        double x = box->start_x + box->dir * box->cross_along, y = -box->a;
        cs_style m = mark(RED, CS_MARK_CROSS, 14);
        snprintf(label, sizeof label, "a wheel crosses y = -A %.1f m along%s", box->cross_along,
                 box->crossed_in_run ? " (in the run)" : " (after it)");
        cs_plot_line(p, &a, &x, &y, 1, &m, label);
    }
    cs_plot_legend(p, &a, CS_LEGEND_OUTSIDE_RIGHT);
}

/* ---- the table of figures ---- */

/* A figure draws on p from d; t holds the frames' times followed by room for SERIES(cable count) more
 * series of as many values. */
typedef void (*figure_fn)(cs_plot *p, const cs_figure_data *d, double *t);
#define SERIES(cables) (3 + LEDGER_TERMS + 2 * NEAR_POSTS + (cables))

static const struct {
    const char *name;
    figure_fn draw;
    double width, height;
} figures[CS_FIG_COUNT] = {
    {"deceleration", fig_deceleration, 1200, 700},
    {"speed", fig_speed, 1200, 700},
    {"penetration", fig_penetration, 1200, 700},
    {"cables", fig_cables, 1200, 700},
    {"posts", fig_posts, 1300, 950},
    {"energy", fig_energy, 1300, 750},
    {"snapshots", cs_fig_snapshots, SNAP_WIDTH, 0},
    {"angles", fig_angles, 1300, 700},
    {"path", fig_path, 1500, 800},
};

const char *cs_figure_name(cs_figure figure) {
    return figure >= 0 && figure < CS_FIG_COUNT ? figures[figure].name : "unknown";
}

void cs_figure_size(cs_figure figure, const cs_figure_data *d, double *width, double *height) {
    *width = figures[figure].width;
    *height = figures[figure].height;
    if (figure == CS_FIG_SNAPSHOTS) *height = cs_fig_snapshots_height(d);
}

typedef struct figure_job {
    const cs_figure_data *d;
    cs_figure figure;
} figure_job;

/* cs_plot_draw_fn: the scratch series of the figure's frames, then the figure. */
static cs_status draw_figure(cs_plot *p, const void *user, cs_error *err) {
    const figure_job *job = user;
    const cs_record *r = job->d->rec;
    size_t n = (size_t)r->frame_count;
    double *t = malloc((n * (size_t)SERIES(r->cable_count) + 1) * sizeof *t);
    if (!t) {
        char message[CS_MESSAGE_SIZE];
        snprintf(message, sizeof message, "out of memory while drawing %s", figures[job->figure].name);
        return cs_status_set(err, CS_ERR_MEMORY, message);
    }
    for (size_t i = 0; i < n; i++)
        t[i] = r->vehicle[i].t;
    figures[job->figure].draw(p, job->d, t);
    free(t);
    return CS_OK;
}

/* Write figure to f in format, or trace it into log (f NULL). */
static cs_status figure_out(FILE *f, cs_plot_format format, cs_plot_log *log, cs_figure figure,
                            const cs_figure_data *d, cs_error *err) {
    char message[CS_MESSAGE_SIZE];
    if (figure < 0 || figure >= CS_FIG_COUNT) {
        snprintf(message, sizeof message, "no figure %d", (int)figure);
        return cs_status_set(err, CS_ERR_INVALID, message);
    }
    double w, h;
    cs_figure_size(figure, d, &w, &h);
    figure_job job = {d, figure};
    return f ? cs_plot_write(f, format, w, h, draw_figure, &job, err)
             : cs_plot_trace(w, h, draw_figure, &job, log, err);
}

cs_status cs_figure_write(FILE *f, cs_plot_format format, cs_figure figure, const cs_figure_data *d,
                          cs_error *err) {
    if (!f) {
        char message[CS_MESSAGE_SIZE];
        snprintf(message, sizeof message, "no file to write %s to", cs_figure_name(figure));
        return cs_status_set(err, CS_ERR_INVALID, message);
    }
    return figure_out(f, format, NULL, figure, d, err);
}

cs_status cs_figure_trace(cs_figure figure, const cs_figure_data *d, cs_plot_log *log, cs_error *err) {
    return figure_out(NULL, CS_PLOT_PNG, log, figure, d, err);
}

cs_status cs_figures_write(cs_outdir *out, const char *subdir, const cs_plot_format *formats,
                           int format_count, const cs_figure_data *d, cs_error *err) {
    char name[128];
    cs_status st = cs_out_subdir(out, subdir, err);
    for (int k = 0; st == CS_OK && k < CS_FIG_COUNT; k++)
        for (int j = 0; st == CS_OK && j < format_count; j++) {
            snprintf(name, sizeof name, "%s/%s.%s", subdir, figures[k].name, cs_plot_extension(formats[j]));
            FILE *f = cs_out_begin(out, name, err);
            if (!f) return err ? err->status : CS_ERR_IO;
            st = cs_out_finish(out, f, cs_figure_write(f, formats[j], (cs_figure)k, d, err), err);
        }
    return st;
}
