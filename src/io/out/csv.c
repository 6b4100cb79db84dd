/* timeseries.csv and events.csv. */
#include <math.h>
#include <string.h>

#include "writers.h"

void cs_w_num(cs_wout *w, double v, const char *what) {
    if (w->bad) return;
    if (!isfinite(v)) {
        w->bad = 1;
        snprintf(w->why, sizeof w->why, "%s is %s", what, isnan(v) ? "NaN" : "infinite");
        return;
    }
    fprintf(w->f, "%.10g", v);
}

static const char *const energy_names[] = {"ke_j",
                                           "pe_j",
                                           "cable_elastic_j",
                                           "cable_plastic_j",
                                           "post_elastic_j",
                                           "post_kinetic_j",
                                           "post_plastic_j",
                                           "post_damping_j",
                                           "anchor_elastic_j",
                                           "anchor_kinetic_j",
                                           "rail_elastic_j",
                                           "rail_plastic_j",
                                           "soil_j",
                                           "crush_j",
                                           "friction_j",
                                           "released_j",
                                           "energy_balance_error"};
enum { ENERGY_TERMS = sizeof energy_names / sizeof energy_names[0] };

static void energy_values(const cs_energy *e, double v[ENERGY_TERMS]) {
    const double all[ENERGY_TERMS] = {
        e->vehicle_kinetic, e->vehicle_potential, e->cable_elastic, e->cable_plastic,  e->post_elastic,
        e->post_kinetic,    e->post_plastic,      e->post_damping,  e->anchor_elastic, e->anchor_kinetic,
        e->rail_elastic,    e->rail_plastic,      e->soil,          e->crush,          e->friction,
        e->released,        e->balance_error};
    memcpy(v, all, sizeof all);
}

int cs_write_timeseries(FILE *f, const cs_record *rec, char *why, size_t why_size) {
    fprintf(f, "t_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,ax_mps2,ay_mps2,az_mps2,roll_rad,pitch_rad,yaw_rad,"
               "forward_speed_mps,decel_50ms_g,crush_m,face_force_n,penetration_m");
    for (int c = 0; c < rec->cable_count; c++)
        fprintf(f, ",cable%d_max_tension_n,cable%d_state", c, c);
    for (int p = 0; p < rec->post_count; p++)
        fprintf(f, ",post%d_state,post%d_tilt_rad", p, p);
    for (int a = 0; a < 2; a++)
        fprintf(f, ",anchor%d_state,anchor%d_displacement_m,anchor%d_force_n", a, a, a);
    for (size_t k = 0; k < sizeof energy_names / sizeof energy_names[0]; k++)
        fprintf(f, ",%s", energy_names[k]);
    fputc('\n', f);
    cs_wout w = {f, 0, ""};
    char what[96];
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
        snprintf(what, sizeof what, "the vehicle's state at t = %g s", v->t);
        for (size_t k = 0; k < sizeof row / sizeof row[0]; k++) {
            if (k) fputc(',', f);
            cs_w_num(&w, row[k], what);
        }
        for (int c = 0; c < rec->cable_count; c++) {
            const cs_cable_view *cv = &rec->cables[(size_t)i * (size_t)rec->cable_count + (size_t)c];
            snprintf(what, sizeof what, "cable %d's tension at t = %g s", c, v->t);
            fputc(',', f);
            cs_w_num(&w, cv->max_tension, what);
            fprintf(f, ",%s", cs_cable_status_name(cv->status));
        }
        for (int p = 0; p < rec->post_count; p++) {
            const cs_post_view *pv = &rec->posts[(size_t)i * (size_t)rec->post_count + (size_t)p];
            snprintf(what, sizeof what, "post %d's tilt at t = %g s", p, v->t);
            fprintf(f, ",%s,", cs_post_status_name(pv->status));
            cs_w_num(&w, pv->tilt, what);
        }
        for (int a = 0; a < 2; a++) {
            const cs_anchor_view *av = &rec->anchors[(size_t)i * 2 + (size_t)a];
            snprintf(what, sizeof what, "anchor %d at t = %g s", a, v->t);
            fprintf(f, ",%s,", cs_anchor_status_name(av));
            cs_w_num(&w, hypot(av->displacement[0], av->displacement[1]), what);
            fputc(',', f);
            cs_w_num(&w, hypot(av->force[0], av->force[1]), what);
        }
        double e[ENERGY_TERMS];
        energy_values(&rec->energy[i], e);
        snprintf(what, sizeof what, "the energy ledger at t = %g s", v->t);
        for (int k = 0; k < ENERGY_TERMS; k++) {
            fputc(',', f);
            cs_w_num(&w, e[k], what);
        }
        fputc('\n', f);
    }
    if (w.bad) snprintf(why, why_size, "timeseries.csv: %s", w.why);
    return w.bad ? -1 : 0;
}

int cs_write_events(FILE *f, const cs_state *state, char *why, size_t why_size) {
    fprintf(f, "t_s,type,element_kind,element,value_si\n");
    cs_wout w = {f, 0, ""};
    for (int i = 0; i < cs_state_event_count(state) && !w.bad; i++) {
        const cs_event *e = cs_state_event(state, i);
        cs_w_num(&w, e->t, "an event's time");
        fprintf(f, ",%s,%s,%d,", cs_event_type_name(e->type), cs_element_kind_name(e->element_kind),
                e->element);
        cs_w_num(&w, e->value, "an event's value");
        fputc('\n', f);
    }
    if (w.bad) snprintf(why, why_size, "events.csv: %s", w.why);
    return w.bad ? -1 : 0;
}
