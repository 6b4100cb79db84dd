/* SPDX-License-Identifier: MIT */
/* timeseries.csv and events.csv. Every CSV cablesim writes names a column "name [unit]" (SI; "[1]" a
 * fraction), and a column without a unit (a state, a type, a count) by its name alone
 * (docs/file-format.md, "CSV files"). */
#include <math.h>
#include <string.h>

#include "numtext.h"
#include "status.h"
#include "writers.h"

int cs_w_finite(cs_wout *w, double v, const char *what) {
    if (w->bad) return 0;
    if (!isfinite(v)) {
        w->bad = 1;
        snprintf(w->why, sizeof w->why, "%s is %s", what, isnan(v) ? "NaN" : "infinite");
        return 0;
    }
    return 1;
}

void cs_w_oom(cs_wout *w, const char *what) {
    if (w->bad) return;
    w->bad = 1;
    snprintf(w->why, sizeof w->why, "%s: out of memory", what);
}

cs_status cs_w_status(const cs_wout *w, const char *file, cs_error *err) {
    if (!w->bad) return CS_OK;
    char message[CS_MESSAGE_SIZE + sizeof w->why]; /* cs_status_set cuts it to the message's room */
    snprintf(message, sizeof message, "%s: %s", file, w->why);
    return cs_status_set(err, CS_ERR_IO, message);
}

void cs_w_num(cs_wout *w, double v, const char *what) {
    if (!cs_w_finite(w, v, what)) return;
    char text[CS_G10_SIZE];
    fwrite(text, 1, (size_t)cs_g10(v, text), w->f);
}

/* A number of timeseries.csv's row at time t: its message, should it not be finite, names "NOUN at t"
 * (index negative) or "NOUN INDEX TAIL at t"; it is worded only then. */
static void ts_num(cs_wout *w, double v, const char *noun, int index, const char *tail, double t) {
    char what[96] = "";
    if (!isfinite(v)) {
        if (index < 0)
            snprintf(what, sizeof what, "%s at t = %g s", noun, t);
        else
            snprintf(what, sizeof what, "%s %d%s at t = %g s", noun, index, tail, t);
    }
    cs_w_num(w, v, what);
}

cs_status cs_timeseries_csv(FILE *f, const cs_record *rec, cs_error *err) {
    fprintf(
        f,
        "t [s],x [m],y [m],z [m],vx [m/s],vy [m/s],vz [m/s],ax [m/s^2],ay [m/s^2],az [m/s^2],roll [rad],"
        "pitch [rad],yaw [rad],forward_speed [m/s],decel_50ms [g],crush [m],face_force [N],penetration [m]");
    for (int c = 0; c < rec->cable_count; c++)
        fprintf(f, ",cable%d_max_tension [N],cable%d_state", c, c);
    for (int p = 0; p < rec->post_count; p++)
        fprintf(f, ",post%d_state,post%d_tilt [rad]", p, p);
    for (int a = 0; a < 2; a++)
        fprintf(f, ",anchor%d_state,anchor%d_displacement [m],anchor%d_lift [m],anchor%d_force [N]", a, a, a, a);
    for (int k = 0; k < CS_ENERGY_TERMS; k++)
        fprintf(f, ",%s [J]", cs_energy_term_name(k));
    fprintf(f, ",energy_balance_error [1]");
    fputc('\n', f);
    cs_wout w = {f, 0, ""};
    for (int i = 0; i < rec->frame_count && !w.bad; i++) {
        const cs_vehicle_view *v = &rec->vehicle[i];
        const double row[] = {v->t,
                              v->position[0],
                              v->position[1],
                              v->position[2],
                              v->velocity[0],
                              v->velocity[1],
                              v->velocity[2],
                              v->acceleration[0],
                              v->acceleration[1],
                              v->acceleration[2],
                              v->roll,
                              v->pitch,
                              v->yaw,
                              v->forward_speed,
                              v->decel_50ms_g,
                              v->crush,
                              v->face_force,
                              v->penetration};
        for (size_t k = 0; k < sizeof row / sizeof row[0]; k++) {
            if (k) fputc(',', f);
            ts_num(&w, row[k], "the vehicle's state", -1, "", v->t);
        }
        for (int c = 0; c < rec->cable_count; c++) {
            const cs_cable_view *cv = &rec->cables[(size_t)i * (size_t)rec->cable_count + (size_t)c];
            fputc(',', f);
            ts_num(&w, cv->max_tension, "cable", c, "'s tension", v->t);
            fputc(',', f);
            fputs(cs_cable_status_name(cv->status), f);
        }
        for (int p = 0; p < rec->post_count; p++) {
            cs_post_state ps = cs_record_post_state(rec, i, p);
            fputc(',', f);
            fputs(cs_post_status_name(ps.status), f);
            fputc(',', f);
            ts_num(&w, ps.tilt, "post", p, "'s tilt", v->t);
        }
        for (int a = 0; a < 2; a++) {
            const cs_anchor_view *av = &rec->anchors[(size_t)i * 2 + (size_t)a];
            fputc(',', f);
            fputs(cs_anchor_status_name(av), f);
            fputc(',', f);
            ts_num(&w, hypot(av->displacement[0], av->displacement[1]), "anchor", a, "", v->t);
            fputc(',', f);
            ts_num(&w, av->lift, "anchor", a, "'s rise", v->t);
            fputc(',', f);
            ts_num(&w, hypot(av->force[0], av->force[1]), "anchor", a, "", v->t);
        }
        for (int k = 0; k <= CS_ENERGY_TERMS; k++) { /* the terms, then the balance error */
            fputc(',', f);
            ts_num(&w,
                   k < CS_ENERGY_TERMS ? cs_energy_term(&rec->energy[i], k) : rec->energy[i].balance_error,
                   "the energy ledger", -1, "", v->t);
        }
        fputc('\n', f);
    }
    return cs_w_status(&w, "timeseries.csv", err);
}

cs_status cs_events_csv(FILE *f, const cs_state *state, cs_error *err) {
    fprintf(f, "t [s],type,element_kind,element,value,value_unit,cable_end,cable,post\n"); /* value: in its
                                                                                              row's unit */
    cs_wout w = {f, 0, ""};
    for (int i = 0; i < cs_state_event_count(state) && !w.bad; i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(state, i, &e_held, NULL);
        const cs_event *e = &e_held;
        cs_w_num(&w, e->t, "an event's time");
        fprintf(f, ",%s,%s,%d,", cs_event_type_name(e->type), cs_element_kind_name(e->element_kind),
                e->element);
        cs_w_num(&w, e->value, "an event's value");
        fprintf(f, ",%s,%s,", cs_event_value_unit(e->type), cs_event_cable_end_name(e));
        if (e->cable >= 0) fprintf(f, "%d", e->cable); /* the cable a post let go */
        fputc(',', f);
        if (e->post >= 0) fprintf(f, "%d", e->post); /* the post at whose hole a rope broke */
        fputc('\n', f);
    }
    return cs_w_status(&w, "events.csv", err);
}
