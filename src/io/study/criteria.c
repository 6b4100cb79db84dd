/* SPDX-License-Identifier: MIT */
/* NCHRP Report 350 and MASH evaluation criteria of a roadside test (criteria.h); each criterion's source
 * and certainty in docs/ratings.md, "Criteria". */
#include "criteria.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/units.h"

const char *cs_verdict_name(cs_verdict v) {
    return v == CS_VERDICT_PASS ? "pass" : v == CS_VERDICT_FAIL ? "FAIL" : "not judged";
}

/* The decimals, from d up to 4, at which a and b print differently (the same if they are equal): a
 * value judged against a limit never reads the same as the limit it passed or failed. */
static int apart(double a, double b, int d) {
    char x[64], y[64];
    for (; d < 4 && a != b; d++) {
        snprintf(x, sizeof x, "%.*f", d, a), snprintf(y, sizeof y, "%.*f", d, b);
        if (strcmp(x, y) != 0) break;
    }
    return d;
}

void cs_vehicle_wheels(const cs_vehicle_view *p, const cs_vehicle_def *v, double w[4][2]) {
    double c = cos(p->yaw), s = sin(p->yaw), b[4][3];
    cs_vehicle_wheel_points(v, b);
    for (int k = 0; k < 4; k++)
        w[k][0] = p->position[0] + c * b[k][0] - s * b[k][1],
        w[k][1] = p->position[1] + s * b[k][0] + c * b[k][1];
}

/* The x of the vehicle's outline corner nearest the barrier (largest y) in frame view p. */
static void nearest_corner(const cs_vehicle_view *p, double *x, double *y) {
    const double *c[4] = {p->front_corners[0], p->front_corners[1], p->rear_corners[0], p->rear_corners[1]};
    *x = c[0][0], *y = c[0][1];
    for (int k = 1; k < 4; k++)
        if (c[k][1] > *y) *x = c[k][0], *y = c[k][1];
}

void cs_exit_box_of_record(const cs_record *rec, const cs_vehicle_def *v, double impact_x, double t_exit,
                           cs_exit_box *out) {
    out->a = 2.0 + v->front_width + 0.16 * (v->cg_to_front + v->cg_to_rear);
    out->b = 10.0;
    out->start_x = impact_x;
    out->cross_along = HUGE_VAL;
    out->crossed_in_run = 0;
    out->heading_back = 0;
    out->dir = 1.0;
    int n = cs_record_frame_count(rec);
    if (n < 1) return;
    double dir = out->dir = cs_record_vehicle(rec, 0)->velocity[0] >= 0.0 ? 1.0 : -1.0, w[4][2];
    int from = 0; /* the first frame followed: at or after the loss of contact */
    if (t_exit >= 0.0) {
        while (from + 1 < n && cs_record_vehicle(rec, from)->t < t_exit)
            from++;
        const cs_vehicle_view *q = cs_record_vehicle(rec, from),
                              *p = cs_record_vehicle(rec, from ? from - 1 : 0);
        double xp, yp, xq, yq;
        nearest_corner(p, &xp, &yp);
        nearest_corner(q, &xq, &yq);
        double f = q->t > p->t ? (t_exit - p->t) / (q->t - p->t) : 1.0;
        f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
        out->start_x = xp + f * (xq - xp);
    }
    int started = t_exit >= 0.0;
    for (int i = from; i < n; i++) {
        cs_vehicle_wheels(cs_record_vehicle(rec, i), v, w);
        for (int k = 0; k < 4 && !started; k++)
            if (w[k][1] >= 0.0) out->start_x = w[k][0], started = 1;
        for (int k = 0; k < 4 && started; k++)
            if (w[k][1] <= -out->a) {
                double along = (w[k][0] - out->start_x) * dir;
                if (along < out->cross_along) out->cross_along = along, out->crossed_in_run = 1;
            }
        if (out->crossed_in_run) return;
    }
    /* past the end: each wheel straight on along the CG's last velocity */
    const cs_vehicle_view *e = cs_record_vehicle(rec, n - 1);
    double vx = e->velocity[0], vy = e->velocity[1];
    if (vy >= 0.0) { /* parallel to the barrier it never crosses; toward it, it comes back */
        out->heading_back = vy > 0.0;
        return;
    }
    cs_vehicle_wheels(e, v, w);
    for (int k = 0; k < 4; k++) {
        double t = (-out->a - w[k][1]) / vy, along = (w[k][0] + vx * t - out->start_x) * dir;
        if (along < out->cross_along) out->cross_along = along;
    }
}

typedef struct {
    cs_criterion *out;
    int n;
} list;

static cs_criterion *add(list *l, const char *id, const char *name, cs_verdict v) {
    cs_criterion *c = &l->out[l->n++];
    c->id = id, c->name = name, c->verdict = v, c->detail[0] = '\0';
    return c;
}

/* The cables the vehicle rode over or went under (override and underride events), appended to buf as
 * "; the vehicle rode over cable 0 at 0.4075 s". With contained, that the others held it: a cable slipping
 * off the vehicle is not an override or underride of the barrier while the barrier contains it. */
static void slips(char *buf, size_t size, const cs_state *state, int contained) {
    int n = state ? cs_state_event_count(state) : 0, said = 0;
    for (int i = 0; i < n; i++) {
        cs_event e = {.size = sizeof e};
        if (cs_state_event(state, i, &e, NULL) != CS_OK ||
            (e.type != CS_EVENT_OVERRIDE && e.type != CS_EVENT_UNDERRIDE))
            continue;
        size_t len = strlen(buf);
        snprintf(buf + len, size - len, "%s%s cable %d at %.6g s", said ? "," : "; the vehicle",
                 e.type == CS_EVENT_OVERRIDE ? " rode over" : " went under", e.element, e.t);
        said++;
    }
    size_t len = strlen(buf);
    if (said && contained)
        snprintf(buf + len, size - len,
                 ", and the other cables held it (no override or underride of the "
                 "barrier)");
}

/* Criterion A: contained and redirected or brought to a controlled stop; no penetration, underride or
 * override. */
static void structural(list *l, const cs_summary *s, const cs_state *state) {
    cs_outcome o = s->outcome;
    int judged = o == CS_REDIRECTED || o == CS_STOPPED || cs_outcome_through(o);
    cs_criterion *c =
        add(l, "A", "contain and redirect or stop the vehicle; no penetration, underride, override",
            !judged                                 ? CS_VERDICT_NOT_JUDGED
            : o == CS_REDIRECTED || o == CS_STOPPED ? CS_VERDICT_PASS
                                                    : CS_VERDICT_FAIL);
    snprintf(c->detail, sizeof c->detail, "%s%s", cs_outcome_name(o),
             !judged ? ": the run did not end with the vehicle redirected, stopped or through" : "");
    if (judged) slips(c->detail, sizeof c->detail, state, c->verdict == CS_VERDICT_PASS);
}

static void not_judged(list *l, const char *id, const char *name, const char *detail) {
    snprintf(add(l, id, name, CS_VERDICT_NOT_JUDGED)->detail, sizeof(cs_criterion){0}.detail, "%s", detail);
}

/* Whether the run ended with the vehicle free of the barrier (redirected or through) or stopped: the
 * motion past its end is then the constant velocity the occupant risk takes there. A run ended otherwise
 * (its time limit, a solve that did not converge, the step limit) stopped mid-collision: what it found is
 * a lower bound of a peak, and what comes after its end is not known. */
static int finished(cs_outcome o) {
    return o == CS_STOPPED || cs_outcome_exits(o);
}

/* A verdict from what is known: a value within its limit passes only if it is the whole story (complete);
 * one over it fails even if it is a lower bound (over); unknown, neither. */
static cs_verdict known(int ok, int complete, int over_known) {
    return ok ? (complete ? CS_VERDICT_PASS : CS_VERDICT_NOT_JUDGED)
              : (over_known ? CS_VERDICT_FAIL : CS_VERDICT_NOT_JUDGED);
}

/* The worse of two verdicts: a failure, else a criterion not judged, else a pass. */
static cs_verdict worse(cs_verdict a, cs_verdict b) {
    return a == CS_VERDICT_FAIL || b == CS_VERDICT_FAIL               ? CS_VERDICT_FAIL
           : a == CS_VERDICT_NOT_JUDGED || b == CS_VERDICT_NOT_JUDGED ? CS_VERDICT_NOT_JUDGED
                                                                      : CS_VERDICT_PASS;
}

/* Upright: roll and pitch at most 75 deg over the run (to its end); of a run that did not finish, only a
 * failure is judged. */
static void upright(list *l, const char *id, const cs_test_result *r, const char *name, const char *note) {
    double lim = 75.0 * CS_DEG;
    int done = finished(r->summary->outcome);
    cs_criterion *c = add(l, id, name, known(r->roll_peak <= lim && r->pitch_peak <= lim, done, 1));
    double roll = r->roll_peak / CS_DEG, pitch = r->pitch_peak / CS_DEG;
    snprintf(c->detail, sizeof c->detail,
             "roll %.*f deg, pitch %.*f deg (limit 75) over the run%s; after it: not judged%s",
             apart(roll, 75.0, 1), roll, apart(pitch, 75.0, 1), pitch,
             done ? "" : ", which ended before the collision did", note);
}

/* An occupant risk value against its maximum (and preferred limit, 0 if none). */
static int within(char *buf, size_t size, const char *what, double v, const char *unit, double preferred,
                  double max) {
    char pref[64] = "";
    int d = apart(v, max, 2);
    if (preferred > 0.0) {
        snprintf(pref, sizeof pref, "%s the preferred %.4g, ", v <= preferred ? "within" : "over", preferred);
        if (apart(v, preferred, 2) > d) d = apart(v, preferred, 2);
    }
    snprintf(buf, size, "%s %.*f %s (%smaximum %.4g)", what, d, v, unit, pref, max);
    return v <= max;
}

/* H and I (both directions, preferred and maximum), or NCHRP 350's L (longitudinal, maximum only). The
 * occupant risk reads the motion past the run's end as constant velocity; of a run that did not finish,
 * an occupant impact after its end is not known, and the ridedown found is a lower bound (over the limit
 * it fails, within it it is not judged). */
static void occupant(list *l, const cs_test_result *r, const char *id, double oiv_pref, double oiv_max,
                     double ora_pref, double ora_max, int longitudinal_only) {
    const cs_occupant_risk *o = r->occupant;
    const char *oname =
        longitudinal_only ? "longitudinal OIV and ORA within limits" : "occupant impact velocity";
    if (!o) {
        not_judged(l, id, oname, r->occupant_why ? r->occupant_why : "no occupant risk");
        if (!longitudinal_only) not_judged(l, "I", "occupant ridedown acceleration", "no occupant risk");
        return;
    }
    cs_outcome out = r->summary->outcome;
    int done = finished(out), in_run = o->impact == CS_FLAIL_IN_RECORD, oiv_known = done || in_run;
    char oiv_note[160] = "", ora_note[160] = "";
    if (!oiv_known)
        snprintf(oiv_note, sizeof oiv_note,
                 " (the occupant had not met the interior when the run ended, %s, with the vehicle still on "
                 "the barrier: not known)",
                 cs_outcome_name(out));
    if (!done && in_run)
        snprintf(ora_note, sizeof ora_note, " (a lower bound: the run ended, %s, before the collision did)",
                 cs_outcome_name(out));
    else if (!done)
        snprintf(ora_note, sizeof ora_note, "%s", oiv_note);
    else if (o->impact == CS_FLAIL_AFTER_RECORD)
        snprintf(ora_note, sizeof ora_note, " (the occupant's impact comes after the run's end)");
    char a[128], b[128], c2[128], d[128];
    if (longitudinal_only) {
        int oiv_ok = within(a, sizeof a, "OIV", o->oiv_x, "m/s", 0.0, oiv_max);
        int ora_ok = within(b, sizeof b, "ORA", o->ora_x, "g", 0.0, ora_max);
        cs_verdict v = worse(known(oiv_ok, oiv_known, oiv_known), known(ora_ok, done, done || in_run));
        snprintf(add(l, id, oname, v)->detail, sizeof(cs_criterion){0}.detail, "longitudinal %s; %s%s", a, b,
                 ora_note);
        return;
    }
    int ok = within(a, sizeof a, "longitudinal", o->oiv_x, "m/s", oiv_pref, oiv_max) &
             within(b, sizeof b, "lateral", o->oiv_y, "m/s", oiv_pref, oiv_max);
    snprintf(add(l, id, oname, known(ok, oiv_known, oiv_known))->detail, sizeof(cs_criterion){0}.detail,
             "%s; %s%s", a, b, oiv_note);
    ok = within(c2, sizeof c2, "longitudinal", o->ora_x, "g", ora_pref, ora_max) &
         within(d, sizeof d, "lateral", o->ora_y, "g", ora_pref, ora_max);
    snprintf(add(l, "I", "occupant ridedown acceleration", known(ok, done, done || in_run))->detail,
             sizeof(cs_criterion){0}.detail, "%s; %s%s", c2, d, ora_note);
}

/* NCHRP 350's M: exit angle under 60% of the impact angle, at the (last) loss of contact (a preference). */
static void exit_angle(list *l, const cs_roadside_test *t, const cs_summary *s) {
    const char *name = "exit angle preferably under 60% of the impact angle";
    if (s->outcome != CS_REDIRECTED) {
        not_judged(l, "M", name, "the vehicle did not leave the barrier on the traffic side");
        return;
    }
    double lim = cs_roadside_exit_angle_limit_deg(t);
    int d = apart(s->exit_angle_deg, lim, 1);
    snprintf(add(l, "M", name, cs_roadside_read(t, s).exit_angle_within ? CS_VERDICT_PASS : CS_VERDICT_FAIL)
                 ->detail,
             sizeof(cs_criterion){0}.detail, "exit %.*f deg (60%% of %.1f deg: %.*f deg)", d,
             s->exit_angle_deg, t->angle / CS_DEG, d, lim);
}

/* MASH's exit box. */
static void exit_box(list *l, const cs_test_result *r) {
    const char *name = "the wheel tracks leave within the exit box";
    const cs_exit_box *e = r->exit_box;
    cs_outcome o = r->summary->outcome;
    if (o == CS_STOPPED) {
        snprintf(add(l, "exit box", name, CS_VERDICT_PASS)->detail, sizeof(cs_criterion){0}.detail,
                 "the vehicle stopped in the barrier: it did not leave");
        return;
    }
    if (o != CS_REDIRECTED || !e) {
        not_judged(l, "exit box", name, "the vehicle did not leave the barrier on the traffic side");
        return;
    }
    if (e->heading_back) { /* where it goes next is a second impact, which the run does not follow */
        char why[200];
        snprintf(why, sizeof why,
                 "no wheel crossed the line %.2f m from the barrier in the run, and at its end the vehicle "
                 "moves back toward the barrier",
                 e->a);
        not_judged(l, "exit box", name, why);
        return;
    }
    cs_criterion *c = add(l, "exit box", name, e->cross_along >= e->b ? CS_VERDICT_PASS : CS_VERDICT_FAIL);
    if (isfinite(e->cross_along))
        snprintf(c->detail, sizeof c->detail,
                 "a wheel crosses the line %.2f m from the barrier %.*f m past the loss of contact (box "
                 "%.*f m); %s",
                 e->a, apart(e->cross_along, e->b, 1), e->cross_along, apart(e->cross_along, e->b, 1), e->b,
                 e->crossed_in_run ? "in the run" : "on the path extrapolated straight from the run's end");
    else /* moving parallel to the barrier at the run's end */
        snprintf(c->detail, sizeof c->detail,
                 "no wheel crosses the line %.2f m from the barrier (the path extrapolated straight from the "
                 "run's end runs parallel to it)",
                 e->a);
}

int cs_roadside_criteria(const cs_roadside_test *t, const cs_test_result *r, cs_criterion *out) {
    list l = {out, 0};
    int mash = strcmp(t->standard, "mash") == 0, truck = strcmp(t->name + 1, "-12") == 0;
    int car = strcmp(t->name + 1, "-10") == 0;
    structural(&l, r->summary, r->state);
    not_judged(&l, "D",
               "no debris penetrating or endangering the occupant compartment or others; compartment "
               "deformation within limits",
               "the model has no debris and no occupant compartment");
    if (truck)
        upright(&l, "G", r, "preferably upright", " (a preference, not essential)");
    else
        upright(&l, "F", r, "upright, roll and pitch at most 75 deg",
                mash ? "" : " (NCHRP 350 gives no number; MASH's 75 deg is used)");
    if (mash && !truck)
        occupant(&l, r, "H", 9.1, 12.2, 15.0, 20.49, 0);
    else if (!mash && car)
        occupant(&l, r, "H", 9.0, 12.0, 15.0, 20.0, 0);
    else if (!mash && !truck)
        occupant(&l, r, "L", 0.0, 12.0, 0.0, 20.0, 1);
    if (mash) {
        exit_box(&l, r);
    } else {
        not_judged(
            &l, "K", "preferably no intrusion into adjacent traffic lanes after the collision",
            "the run ends a vehicle's length past the loss of contact: the trajectory further on is not "
            "simulated");
        exit_angle(&l, t, r->summary);
    }
    return l.n;
}

int cs_roadside_test_as_run(const cs_vehicle_def *v, double speed, double angle, cs_roadside_test *out) {
    static const char *const standards[] = {"nchrp-350", "mash"};
    if (!(angle > 0.0 && angle < 45.0 * CS_DEG)) return 0;
    for (int k = 0; k < 4; k++) { /* level 3 of each standard, then level 4 (the 4-12 trucks) */
        cs_roadside_test t[3];
        int n = cs_roadside_tests(standards[k % 2], 3 + k / 2, NULL, t);
        for (int i = 0; i < n; i++) {
            double mass = atof(t[i].vehicle);
            if (fabs(v->mass - mass) <= 0.05 * mass) {
                *out = t[i];
                out->speed = speed, out->angle = angle;
                if (strcmp(out->name + 1, "-12") != 0) { /* x-10, x-11: the level the run's speed is */
                    static const char *const names[3][2] = {
                        {"1-10", "1-11"}, {"2-10", "2-11"}, {"3-10", "3-11"}};
                    double kmh = speed * 3.6; /* nearest of the levels' 50, 70 and 100 km/h */
                    out->name = names[kmh < 60.0 ? 0 : kmh < 85.0 ? 1 : 2][out->name[3] == '1'];
                }
                return 1;
            }
        }
    }
    return 0;
}
