/* SPDX-License-Identifier: MIT */
/* Occupant risk (occupant.h): J211/1 filters, the flail-space model, THIV, PHD and ASI; formulas and
 * sources in docs/ratings.md, "Occupant risk". */
#include "occupant.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/units.h"
#include "status.h"

cs_occupant_rules cs_default_occupant_rules(void) {
    cs_occupant_rules r;
    r.cfc = 180.0;
    r.flail_x = 0.6, r.flail_y = 0.3;
    r.ora_window = 0.010;
    r.thiv_dx = 0.6, r.thiv_dy = 0.3;
    r.phd_window = 0.010;
    r.asi_window = 0.050;
    r.asi_limit[0] = 12.0 * CS_G0, r.asi_limit[1] = 9.0 * CS_G0, r.asi_limit[2] = 10.0 * CS_G0;
    return r;
}

int cs_cfc_coefficients(double cfc, double dt, cs_cfc_coeffs *c) {
    double wd = 2.0 * CS_PI * cfc * 2.0775, half = 0.5 * wd * dt;
    if (!(cfc > 0.0) || !(dt > 0.0) || half >= 0.5 * CS_PI) return -1;
    double wa = sin(half) / cos(half), r2 = sqrt(2.0), den = 1.0 + r2 * wa + wa * wa;
    c->a0 = wa * wa / den;
    c->a1 = 2.0 * c->a0;
    c->a2 = c->a0;
    c->b1 = -2.0 * (wa * wa - 1.0) / den;
    c->b2 = (-1.0 + r2 * wa - wa * wa) / den;
    return 0;
}

/* One pass of the 2-pole filter over y[0..n-1] in place, in direction step (+1 or -1), its history the
 * pass's first value. */
static void cfc_pass(const cs_cfc_coeffs *c, double *y, int n, int step) {
    int i = step > 0 ? 0 : n - 1;
    double x1 = y[i], x2 = y[i], y1 = y[i], y2 = y[i];
    for (int k = 0; k < n; k++, i += step) {
        double x = y[i], out = c->a0 * x + c->a1 * x1 + c->a2 * x2 + c->b1 * y1 + c->b2 * y2;
        x2 = x1, x1 = x, y2 = y1, y1 = out;
        y[i] = out;
    }
}

int cs_cfc_filter(double cfc, double dt, const double *x, double *y, int n) {
    cs_cfc_coeffs c;
    if (cs_cfc_coefficients(cfc, dt, &c) != 0) return -1;
    if (n <= 0) return 0;
    if (y != x) memmove(y, x, (size_t)n * sizeof *y);
    cfc_pass(&c, y, n, +1);
    cfc_pass(&c, y, n, -1);
    return 0;
}

double cs_window_mean_max(const double *x, int n, int w, int from, int *at) {
    double best = 0.0, sum = 0.0;
    *at = -1;
    if (w < 1 || from < 0 || from >= n) return 0.0;
    for (int i = from; i < from + w && i < n; i++)
        sum += x[i];
    for (int i = from; i < n; i++) { /* past the end, the window's missing samples are zeros */
        if (*at < 0 || fabs(sum) / w > best) best = fabs(sum) / w, *at = i;
        sum += (i + w < n ? x[i + w] : 0.0) - x[i];
    }
    return best;
}

/* An occupant's (or head's) displacement against the vehicle and its relative velocity at one sample. */
typedef struct rel_sample {
    double d[2], v[2];
} rel_sample;

/* Whether the displacement crosses a bound (lim, two components) between samples p (index i - 1) and q
 * (index i): the impact's time (s) and its velocity components by linear interpolation within the step. */
static int crossed_in_step(const rel_sample *p, const rel_sample *q, int i, double dt, const double lim[2],
                           double *t, double v[2]) {
    double ax = fabs(q->d[0]), ay = fabs(q->d[1]);
    if (ax < lim[0] && ay < lim[1]) return 0;
    double fx = ax >= lim[0] ? (lim[0] - fabs(p->d[0])) / (ax - fabs(p->d[0])) : 2.0;
    double fy = ay >= lim[1] ? (lim[1] - fabs(p->d[1])) / (ay - fabs(p->d[1])) : 2.0;
    double f = fx < fy ? fx : fy;
    f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
    *t = (i - 1 + f) * dt;
    v[0] = p->v[0] + f * (q->v[0] - p->v[0]);
    v[1] = p->v[1] + f * (q->v[1] - p->v[1]);
    return 1;
}

/* The crossing after the last sample e (index last) of a record none of whose steps crossed, at the last
 * velocity held. Returns where the impact is. */
static cs_flail_impact crossed_after(const rel_sample *e, int last, double dt, const double lim[2], double *t,
                                     double v[2]) {
    double best = HUGE_VAL;
    for (int k = 0; k < 2; k++)
        if (fabs(e->v[k]) > 1e-9) {
            double tk = ((e->v[k] > 0.0 ? lim[k] : -lim[k]) - e->d[k]) / e->v[k];
            if (tk >= 0.0 && tk < best) best = tk;
        }
    v[0] = e->v[0], v[1] = e->v[1];
    if (!isfinite(best)) {
        *t = NAN;
        return CS_FLAIL_NONE;
    }
    *t = last * dt + best;
    return CS_FLAIL_AFTER_RECORD;
}

/* The largest resultant of the x and y means over windows of w samples from index from on, a window
 * running past the end with zeros there. */
static double resultant_mean_max(const double *x, const double *y, int n, int w, int from, int *at) {
    double best = 0.0, sx = 0.0, sy = 0.0;
    *at = -1;
    if (w < 1 || from < 0 || from >= n) return 0.0;
    for (int i = from; i < from + w && i < n; i++)
        sx += x[i], sy += y[i];
    for (int i = from; i < n; i++) { /* past the end, zeros (cs_window_mean_max) */
        double r = hypot(sx, sy) / w;
        if (*at < 0 || r > best) best = r, *at = i;
        sx += (i + w < n ? x[i + w] : 0.0) - x[i], sy += (i + w < n ? y[i + w] : 0.0) - y[i];
    }
    return best;
}

static int window_samples(double window, double dt) {
    int w = (int)lround(window / dt);
    return w < 1 ? 1 : w;
}

/* The flail-space occupant (NCHRP 350, MASH): a free body that keeps the vehicle's velocity at the first
 * contact, moving against the vehicle's axes without their rotation; integrated sample by sample up to
 * its first crossing of the flail space. */
static void flail(const double *ax, const double *ay, int n, double dt, const cs_occupant_rules *r,
                  cs_occupant_risk *o) {
    const double lim[2] = {r->flail_x, r->flail_y};
    double v[2];
    rel_sample p = {{0.0, 0.0}, {0.0, 0.0}}, q;
    o->impact = CS_FLAIL_NONE;
    for (int i = 1; i < n; i++, p = q) {
        q.v[0] = p.v[0] - 0.5 * dt * (ax[i] + ax[i - 1]);
        q.v[1] = p.v[1] - 0.5 * dt * (ay[i] + ay[i - 1]);
        q.d[0] = p.d[0] + 0.5 * dt * (q.v[0] + p.v[0]);
        q.d[1] = p.d[1] + 0.5 * dt * (q.v[1] + p.v[1]);
        if (crossed_in_step(&p, &q, i, dt, lim, &o->t_impact, v)) {
            o->impact = CS_FLAIL_IN_RECORD;
            break;
        }
    }
    if (o->impact != CS_FLAIL_IN_RECORD) o->impact = crossed_after(&p, n - 1, dt, lim, &o->t_impact, v);
    o->oiv_x = fabs(v[0]), o->oiv_y = fabs(v[1]);
    o->ora_x = o->ora_y = 0.0;
    o->t_ora_x = o->t_ora_y = NAN;
    if (o->impact != CS_FLAIL_IN_RECORD) return;
    int from = (int)ceil(o->t_impact / dt - 1e-9), w = window_samples(r->ora_window, dt), at;
    o->ora_x = cs_window_mean_max(ax, n, w, from, &at) / CS_G0;
    o->t_ora_x = at >= 0 ? at * dt : NAN;
    o->ora_y = cs_window_mean_max(ay, n, w, from, &at) / CS_G0;
    o->t_ora_y = at >= 0 ? at * dt : NAN;
}

/* EN 1317-1's theoretical head: a free body in the horizontal plane keeping the vehicle's velocity at the
 * first contact, seen from the vehicle as it moves and yaws; it starts at the CG. Integrated sample by
 * sample up to its first crossing of the head's space. */
static void thiv(const cs_vehicle_motion *m, const cs_occupant_rules *r, cs_occupant_risk *o) {
    int n = m->n;
    double dt = m->dt;
    const double lim[2] = {r->thiv_dx, r->thiv_dy};
    double v[2];
    double psi = 0.0, Vx = 0.0, Vy = 0.0, Xx = 0.0, Xy = 0.0; /* the vehicle: yaw, velocity, position */
    double gx_prev = m->ax[0], gy_prev = m->ay[0];            /* its acceleration in the ground frame */
    rel_sample p = {{0.0, 0.0}, {0.0, 0.0}}, q;
    o->thiv_impact = CS_FLAIL_NONE;
    for (int i = 0; i < n; i++, p = q) {
        if (i > 0) {
            psi += 0.5 * dt * (m->yaw_rate[i] + m->yaw_rate[i - 1]);
            double c = cos(psi), s = sin(psi);
            double gx = c * m->ax[i] - s * m->ay[i], gy = s * m->ax[i] + c * m->ay[i];
            double Vx0 = Vx, Vy0 = Vy;
            Vx += 0.5 * dt * (gx + gx_prev), Vy += 0.5 * dt * (gy + gy_prev);
            Xx += 0.5 * dt * (Vx + Vx0), Xy += 0.5 * dt * (Vy + Vy0);
            gx_prev = gx, gy_prev = gy;
        }
        double c = cos(psi), s = sin(psi);
        /* the head's place and velocity against the vehicle, in the vehicle's axes */
        q.d[0] = -(c * Xx + s * Xy);
        q.d[1] = -(-s * Xx + c * Xy);
        q.v[0] = -(c * Vx + s * Vy) + m->yaw_rate[i] * q.d[1];
        q.v[1] = -(-s * Vx + c * Vy) - m->yaw_rate[i] * q.d[0];
        if (i > 0 && crossed_in_step(&p, &q, i, dt, lim, &o->t_thiv, v)) {
            o->thiv_impact = CS_FLAIL_IN_RECORD;
            break;
        }
    }
    if (o->thiv_impact != CS_FLAIL_IN_RECORD)
        o->thiv_impact = crossed_after(&p, n - 1, dt, lim, &o->t_thiv, v);
    o->thiv = hypot(v[0], v[1]);
    o->phd = 0.0;
    o->t_phd = NAN;
    if (o->thiv_impact != CS_FLAIL_IN_RECORD) return;
    int from = (int)ceil(o->t_thiv / dt - 1e-9), at;
    o->phd = resultant_mean_max(m->ax, m->ay, n, window_samples(r->phd_window, dt), from, &at) / CS_G0;
    o->t_phd = at >= 0 ? at * dt : NAN;
}

/* EN 1317-1's ASI: the largest over the windows of sqrt(sum (mean a_k / limit_k)^2). */
static void asi(const double *a[3], int n, double dt, const cs_occupant_rules *r, cs_occupant_risk *o) {
    int w = window_samples(r->asi_window, dt);
    if (w > n) w = n;
    double s[3] = {0, 0, 0};
    for (int i = 0; i < w; i++)
        for (int k = 0; k < 3; k++)
            s[k] += a[k][i];
    o->asi = -1.0;
    for (int i = 0;; i++) {
        double q = 0.0;
        for (int k = 0; k < 3; k++)
            q += pow(s[k] / w / r->asi_limit[k], 2);
        if (sqrt(q) > o->asi) o->asi = sqrt(q), o->t_asi = i * dt;
        if (i + w >= n) break;
        for (int k = 0; k < 3; k++)
            s[k] += a[k][i + w] - a[k][i];
    }
}

/* The motion's checks, then its accelerations filtered into f[0..2] (each may be its own series). */
static cs_status filter_motion(const cs_vehicle_motion *m, const cs_occupant_rules *rules, double *f[3],
                               cs_error *err) {
    int n = m->n;
    const double *in[4] = {m->ax, m->ay, m->az, m->yaw_rate};
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < n; i++)
            if (!isfinite(in[k][i]))
                return cs_error_set(err, CS_ERR_INVALID,
                                    "the vehicle's motion is not finite at t = %g s (series %d)", i * m->dt,
                                    k);
    for (int k = 0; k < 3; k++)
        if (cs_cfc_filter(rules->cfc, m->dt, in[k], f[k], n) != 0)
            return cs_error_set(err, CS_ERR_INVALID,
                                "a sample interval of %g s is too long for a CFC %g filter", m->dt,
                                rules->cfc);
    return CS_OK;
}

static cs_status too_few(const cs_vehicle_motion *m, cs_error *err) {
    if (m->n >= 2 && m->dt > 0.0) return CS_OK;
    return cs_error_set(err, CS_ERR_INVALID, "the vehicle's motion has %d samples: at least 2 are needed",
                        m->n);
}

/* The risk of a motion whose accelerations are filtered already. */
static void risk_of_filtered(const cs_vehicle_motion *f, const cs_occupant_rules *rules,
                             cs_occupant_risk *out) {
    flail(f->ax, f->ay, f->n, f->dt, rules, out);
    thiv(f, rules, out);
    const double *a[3] = {f->ax, f->ay, f->az};
    asi(a, f->n, f->dt, rules, out);
}

cs_status cs_occupant_risk_compute(const cs_vehicle_motion *m, const cs_occupant_rules *rules,
                                   cs_occupant_risk *out, cs_error *err) {
    memset(out, 0, sizeof *out);
    cs_status rc = too_few(m, err);
    if (rc != CS_OK) return rc;
    int n = m->n;
    double *buf = malloc((size_t)n * 3 * sizeof *buf);
    if (!buf) return cs_error_set(err, CS_ERR_MEMORY, "out of memory for the occupant risk (%d samples)", n);
    double *f[3] = {buf, buf + n, buf + 2 * n};
    rc = filter_motion(m, rules, f, err);
    if (rc == CS_OK)
        risk_of_filtered(&(cs_vehicle_motion){n, m->dt, f[0], f[1], f[2], m->yaw_rate}, rules, out);
    free(buf);
    return rc;
}

/* A world-frame vector into the vehicle's axes: the transpose of Rz(yaw) Ry(pitch) Rx(roll). */
static void world_to_body(const cs_vehicle_view *v, const double w[3], double b[3]) {
    double cr = cos(v->roll), sr = sin(v->roll), cp = cos(v->pitch), sp = sin(v->pitch), cy = cos(v->yaw),
           sy = sin(v->yaw);
    const double R[3][3] = {{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                            {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                            {-sp, cp * sr, cp * cr}};
    for (int i = 0; i < 3; i++)
        b[i] = R[0][i] * w[0] + R[1][i] * w[1] + R[2][i] * w[2];
}

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Frame i's acceleration in the vehicle's axes at point r from the CG (NULL: the CG itself). */
static void frame_acceleration(const cs_record *rec, int i, const double *r, double b[3]) {
    const cs_vehicle_view *v = cs_record_vehicle(rec, i);
    world_to_body(v, v->acceleration, b);
    if (!r) return;
    int frames = cs_record_frame_count(rec), lo = i > 0 ? i - 1 : i, hi = i + 1 < frames ? i + 1 : i;
    const cs_vehicle_view *p = cs_record_vehicle(rec, lo), *q = cs_record_vehicle(rec, hi);
    double alpha[3] = {0, 0, 0}, wr[3], wwr[3], ar[3];
    for (int k = 0; k < 3 && q->t > p->t; k++)
        alpha[k] = (q->angular_velocity[k] - p->angular_velocity[k]) / (q->t - p->t);
    cross(alpha, r, ar);
    cross(v->angular_velocity, r, wr);
    cross(v->angular_velocity, wr, wwr);
    for (int k = 0; k < 3; k++)
        b[k] += ar[k] + wwr[k];
}

cs_status cs_vehicle_motion_of_record(const cs_record *rec, double t_contact, double dt, const double *point,
                                      cs_vehicle_motion *m, cs_error *err) {
    memset(m, 0, sizeof *m);
    int frames = cs_record_frame_count(rec);
    double t_last = frames > 0 ? cs_record_vehicle(rec, frames - 1)->t : -1.0;
    if (frames < 2 || t_contact < 0.0 || t_last <= t_contact)
        return cs_error_set(err, CS_ERR_INVALID, "%s",
                            t_contact < 0.0 ? "the vehicle never touched the barrier"
                                            : "the record has no motion after the first contact");
    int n = (int)floor((t_last - t_contact) / dt + 1e-9) + 1;
    double *buf = malloc((size_t)n * 4 * sizeof *buf);
    double *body = malloc((size_t)frames * 3 * sizeof *body); /* each frame's, found once */
    if (!buf || !body) {
        free(buf);
        free(body);
        return cs_error_set(err, CS_ERR_MEMORY, "out of memory for the vehicle's motion (%d samples)", n);
    }
    double *ax = buf, *ay = buf + n, *az = buf + 2 * n, *r = buf + 3 * n;
    int j = 0, found = 0; /* the frame at or before the sample; the frames whose acceleration is found */
    for (int i = 0; i < n; i++) {
        double t = t_contact + i * dt;
        while (j + 2 < frames && cs_record_vehicle(rec, j + 1)->t <= t)
            j++;
        for (; found <= j + 1; found++)
            frame_acceleration(rec, found, point, body + 3 * found);
        const cs_vehicle_view *p = cs_record_vehicle(rec, j), *q = cs_record_vehicle(rec, j + 1);
        double f = q->t > p->t ? (t - p->t) / (q->t - p->t) : 0.0;
        const double *bp = body + 3 * j, *bq = body + 3 * (j + 1);
        f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
        ax[i] = bp[0] + f * (bq[0] - bp[0]);
        ay[i] = bp[1] + f * (bq[1] - bp[1]);
        az[i] = bp[2] + f * (bq[2] - bp[2]);
        r[i] = p->angular_velocity[2] + f * (q->angular_velocity[2] - p->angular_velocity[2]);
    }
    free(body);
    *m = (cs_vehicle_motion){n, dt, ax, ay, az, r};
    return CS_OK;
}

void cs_record_roll_pitch_peaks(const cs_record *rec, double *roll, double *pitch) {
    *roll = *pitch = 0.0;
    for (int i = 0; i < cs_record_frame_count(rec); i++) {
        const cs_vehicle_view *v = cs_record_vehicle(rec, i);
        if (fabs(v->roll) > *roll) *roll = fabs(v->roll);
        if (fabs(v->pitch) > *pitch) *pitch = fabs(v->pitch);
    }
}

cs_status cs_occupant_risk_for_run(const cs_record *rec, double t_contact, const double *point,
                                   cs_occupant_risk *out, cs_error *err) {
    cs_vehicle_motion m;
    cs_status rc = cs_vehicle_motion_of_record(rec, t_contact, 1e-4, point, &m, err);
    if (rc != CS_OK) return rc;
    cs_occupant_rules rules = cs_default_occupant_rules();
    /* the motion's arrays are this function's own (one block from m.ax): filtered in place */
    double *own = (double *)m.ax, *f[3] = {own, own + m.n, own + 2 * m.n};
    memset(out, 0, sizeof *out);
    rc = too_few(&m, err);
    if (rc == CS_OK) rc = filter_motion(&m, &rules, f, err);
    if (rc == CS_OK) risk_of_filtered(&m, &rules, out);
    free(own);
    return rc;
}
