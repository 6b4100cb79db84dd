/* SPDX-License-Identifier: MIT */
/* summary.json: the response parameters, the events and the resolved inputs (SI, keys as in the
 * model file). A limit given as "none" is null. */
#include <math.h>
#include <string.h>

#include "cablesim/units.h"
#include "load/schema.h"
#include "writers.h"

void cs_json_string(FILE *f, const char *s) {
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(f, "\\u%04x", *s);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

static void jkey(cs_wout *w, int *first, const char *key) {
    fprintf(w->f, "%s", *first ? "" : ",");
    *first = 0;
    cs_json_string(w->f, key);
    fputc(':', w->f);
}

static void jnum(cs_wout *w, int *first, const char *key, double v) {
    jkey(w, first, key);
    cs_w_num(w, v, key);
}

/* The fields of a table that map to members of def, as "key":value pairs. */
static void jfields(cs_wout *w, int *first, const cs_table *t, const void *def) {
    for (int i = 0; i < t->count; i++) {
        const cs_field *fd = &t->fields[i];
        if (fd->offset < 0) continue;
        const char *at = (const char *)def + fd->offset;
        if (cs_field_unset(fd, at)) continue;
        jkey(w, first, fd->key);
        if (fd->kind == CS_F_MAP) {
            int sub = 1;
            fputc('{', w->f);
            jfields(w, &sub, fd->sub, at);
            fputc('}', w->f);
        } else if (fd->kind == CS_F_INT || fd->kind == CS_F_ENUM) {
            int v;
            memcpy(&v, at, sizeof v);
            if (fd->kind == CS_F_ENUM && v < 0)
                fprintf(w->f, "null"); /* a CS_OWN map's: its parent's */
            else if (fd->kind == CS_F_ENUM)
                cs_json_string(w->f, fd->words[v]);
            else
                fprintf(w->f, "%d", v);
        } else {
            double v;
            memcpy(&v, at, sizeof v);
            if ((fd->flags & CS_NONE_OK) && isinf(v) && v > 0)
                fprintf(w->f, "null");
            else
                cs_w_num(w, v, fd->key);
        }
    }
}

static void jobject(cs_wout *w, int *first, const char *key, const cs_table *t, const void *def) {
    int sub = 1;
    jkey(w, first, key);
    fputc('{', w->f);
    jfields(w, &sub, t, def);
    fputc('}', w->f);
}

/* Every cable's peak tension and work on the vehicle, and the sudden losses (cs_summary's, each of them). */
static void cables_and_losses(cs_wout *w, int *first, const cs_state *state, const cs_summary *s) {
    jkey(w, first, "cable_count");
    fprintf(w->f, "%d", s->cable_count);
    jkey(w, first, "cables");
    fputc('[', w->f);
    for (int c = 0; c < s->cable_count; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        cs_state_cable_summary(state, c, &cb, NULL);
        int cf = 1;
        fprintf(w->f, "%s{", c ? "," : "");
        jkey(w, &cf, "index");
        fprintf(w->f, "%d", c);
        jnum(w, &cf, "peak_tension_n", cb.peak_tension_n);
        jnum(w, &cf, "peak_tension_time_s", cb.peak_tension_time_s);
        jnum(w, &cf, "work_on_vehicle_j", cb.work_on_vehicle_j);
        jnum(w, &cf, "energy_share", cb.energy_share);
        fputc('}', w->f);
    }
    fputc(']', w->f);
    jkey(w, first, "sudden_loss_count");
    fprintf(w->f, "%d", s->sudden_loss_count);
    jkey(w, first, "sudden_losses");
    fputc('[', w->f);
    cs_sudden_loss losses[CS_SUDDEN_LOSS_KEPT] = {{.size = sizeof losses[0]}};
    int n = cs_state_sudden_losses(state, losses, CS_SUDDEN_LOSS_KEPT, NULL);
    for (int k = 0; k < n; k++) {
        int lf = 1;
        fprintf(w->f, "%s{", k ? "," : "");
        jnum(w, &lf, "t_start_s", losses[k].t_start_s);
        jnum(w, &lf, "t_end_s", losses[k].t_end_s);
        jnum(w, &lf, "force_before_n", losses[k].force_before_n);
        jnum(w, &lf, "force_after_n", losses[k].force_after_n);
        fputc('}', w->f);
    }
    fputs("]\n", w->f);
}

static void jarray(cs_wout *w, int *first, const char *key, const double *v, int n) {
    jkey(w, first, key);
    fputc('[', w->f);
    for (int i = 0; i < n; i++) {
        if (i) fputc(',', w->f);
        cs_w_num(w, v[i], key);
    }
    fputc(']', w->f);
}

/* Cable c as the run used it: termination_efficiency the strength its fittings are given (0 in the
 * model is its kind's published value, written as that value), and "ends": the fitting at the start and
 * at the end anchor, each its kind, strength over Fu and slip (cs_cable_end_efficiency, cs_cable_end_slip:
 * what report.html's design table shows). */
static void cable_input(cs_wout *w, const cs_cable_def *cable) {
    FILE *f = w->f;
    cs_cable_def used = *cable;
    if (!(used.termination_efficiency > 0.0))
        used.termination_efficiency = cs_termination_efficiency(used.termination, used.rope.diameter);
    int first = 1;
    fputc('{', f);
    jfields(w, &first, &cs_table_cable, &used);
    jobject(w, &first, "rope", &cs_table_rope, &cable->rope);
    jkey(w, &first, "ends");
    for (int k = 0; k < 2; k++) {
        cs_termination kind;
        double travel, efficiency = cs_cable_end_efficiency(cable, k, &kind);
        double slip = cs_cable_end_slip(cable, k, &travel);
        int ef = 1;
        fputs(k ? ",{" : "[{", f);
        jkey(w, &ef, "termination");
        cs_json_string(f, cs_termination_word(kind));
        jnum(w, &ef, "termination_efficiency", efficiency);
        jnum(w, &ef, "slip_load", slip);
        jnum(w, &ef, "slip_travel", slip > 0.0 ? travel : 0.0);
        fputc('}', f);
    }
    fputs("]}", f);
}

static void inputs(cs_wout *w, const cs_model_input *in) {
    FILE *f = w->f;
    int top = 1, b = 1, v = 1;
    fprintf(f, "{");
    jkey(w, &top, "name");
    cs_json_string(f, in->name);
    jkey(w, &top, "file");
    cs_json_string(f, in->file);
    jkey(w, &top, "barrier");
    fprintf(f, "{");
    jkey(w, &b, "cables");
    fprintf(f, "[");
    for (int c = 0; c < in->barrier.cable_count; c++) {
        if (c) fputc(',', f);
        cable_input(w, &in->barrier.cables[c]);
    }
    fprintf(f, "]");
    jkey(w, &b, "posts");
    fprintf(f, "[");
    for (int p = 0; p < in->barrier.post_count; p++) {
        const cs_post_def *post = &in->barrier.posts[p];
        int first = 1;
        fprintf(f, "%s\n{", p ? "," : "");
        jnum(w, &first, "x", post->x);
        jfields(w, &first, &cs_table_posts, post);
        jobject(w, &first, "section", &cs_table_section, &post->section);
        fprintf(f, "}");
    }
    fprintf(f, "]");
    jobject(w, &b, "anchors", &cs_table_anchors, &in->barrier);
    fprintf(f, "}");
    jkey(w, &top, "vehicle");
    fprintf(f, "{");
    jfields(w, &v, &cs_table_vehicle, &in->vehicle);
    jarray(w, &v, "crush_deformation", in->vehicle.crush_deformation, in->vehicle.crush_point_count);
    jarray(w, &v, "crush_force", in->vehicle.crush_force, in->vehicle.crush_point_count);
    fprintf(f, "}");
    jobject(w, &top, "scenario", &cs_table_scenario, &in->scenario);
    fprintf(f, "}");
}

void cs_json_provenance(FILE *f, const cs_run_info *info, cs_json_text_fn text) {
    fputs("{\"version\":", f);
    text(f, CS_VERSION_STRING);
    fputs(",\"command\":", f);
    if (info && info->command)
        text(f, info->command);
    else
        fputs("null", f);
    fputs(",\"overrides\":[", f);
    for (int i = 0; info && i < info->override_count; i++) {
        if (i) fputc(',', f);
        text(f, info->overrides[i]);
    }
    fputs("],\"model_hash\":", f);
    if (info) {
        char hash[17];
        cs_model_hash_text(info->model_hash, hash);
        text(f, hash);
    } else {
        fputs("null", f);
    }
    fputc('}', f);
}

/* "cablesim": where the results come from, on a line of its own. */
static void provenance(cs_wout *w, int *first, const cs_run_info *info) {
    jkey(w, first, "cablesim");
    cs_json_provenance(w->f, info, cs_json_string);
    fputc('\n', w->f);
}

/* "designations_as_run": the standards' designation of the test the run is (docs/ratings.md), in
 * cs_rating_text's words with its parts. */
static void ratings(cs_wout *w, int *first, const cs_run_info *info) {
    FILE *f = w->f;
    jkey(w, first, "designations_as_run");
    fputc('[', f);
    for (int i = 0; info && i < info->rating_count; i++) {
        const cs_rating *r = &info->ratings[i];
        char text[256];
        int rf = 1;
        cs_rating_text(r, text, sizeof text);
        fputs(i ? ",{" : "{", f);
        jkey(w, &rf, "standard");
        cs_json_string(f, cs_standard_name(r->standard));
        jkey(w, &rf, "label");
        cs_json_string(f, r->label);
        jkey(w, &rf, "text");
        cs_json_string(f, text);
        jkey(w, &rf, "rated");
        fputs(r->rated ? "true" : "false", f);
        jkey(w, &rf, "vehicle_class");
        cs_json_string(f, r->vehicle_class);
        jkey(w, &rf, "speed_mph");
        fprintf(f, "%d", r->speed_mph);
        jkey(w, &rf, "penetration_m");
        if (r->tested && !r->through)
            cs_w_num(w, r->penetration, "a designation's penetration");
        else
            fputs("null", f);
        jkey(w, &rf, "measured");
        cs_json_string(f, r->reference ? r->reference : "");
        fputc('}', f);
    }
    fputc(']', f);
}

/* A number, or null if it is not finite (a window that did not fit, an impact that never came). */
static void jopt(cs_wout *w, int *first, const char *key, double v) {
    jkey(w, first, key);
    if (isfinite(v))
        cs_w_num(w, v, key);
    else
        fputs("null", w->f);
}

const char *cs_flail_impact_name(cs_flail_impact k) {
    return k == CS_FLAIL_IN_RECORD ? "in_run" : k == CS_FLAIL_AFTER_RECORD ? "after_run" : "none";
}

/* "occupant_risk" at the CG (docs/ratings.md, Occupant risk), or null with "occupant_risk_note" saying
 * why; "max_roll_deg" and "max_pitch_deg". */
static void occupant_risk(cs_wout *w, int *first, const cs_run_info *info, cs_json_text_fn text) {
    FILE *f = w->f;
    jkey(w, first, "occupant_risk");
    if (!info || !info->motion || !info->occupant_ok) {
        fputs("null", f);
        jkey(w, first, "occupant_risk_note");
        text(f, !info || !info->motion ? "no record of the run's motion" : info->occupant_why);
    } else {
        const cs_occupant_risk *o = &info->occupant;
        cs_occupant_rules r = cs_default_occupant_rules();
        int of = 1;
        fputc('{', f);
        jkey(w, &of, "basis");
        fprintf(f, "\"%s, accelerations filtered to SAE J211/1 CFC %.0f, from the first contact\"",
                info->occupant_at
                    ? "a point of the vehicle (point_m: from its centre of gravity, x forward, y "
                      "left, z up)"
                    : "the vehicle's centre of gravity",
                r.cfc);
        const double cg[3] = {0, 0, 0};
        jarray(w, &of, "point_m", info->occupant_at ? info->occupant_point : cg, 3);
        jkey(w, &of, "occupant_impact");
        text(f, cs_flail_impact_name(o->impact));
        jopt(w, &of, "occupant_impact_time_s", o->t_impact);
        jnum(w, &of, "oiv_longitudinal_mps", o->oiv_x);
        jnum(w, &of, "oiv_lateral_mps", o->oiv_y);
        jnum(w, &of, "ora_longitudinal_g", o->ora_x);
        jnum(w, &of, "ora_lateral_g", o->ora_y);
        jkey(w, &of, "head_impact");
        text(f, cs_flail_impact_name(o->thiv_impact));
        jopt(w, &of, "thiv_time_s", o->t_thiv);
        jnum(w, &of, "thiv_mps", o->thiv);
        jnum(w, &of, "thiv_kmh", o->thiv * 3.6);
        jnum(w, &of, "phd_g", o->phd);
        jnum(w, &of, "asi", o->asi);
        jopt(w, &of, "asi_time_s", o->t_asi);
        fputc('}', f);
    }
    if (info && info->motion) {
        jnum(w, first, "max_roll_deg", info->roll_peak / CS_DEG);
        jnum(w, first, "max_pitch_deg", info->pitch_peak / CS_DEG);
    }
    fputc('\n', f);
}

/* "roadside_criteria": the criteria of the roadside test the run stands for, as run, with MASH's exit
 * box (a criterion of MASH's tests only), or null. */
static void roadside_criteria(cs_wout *w, int *first, const cs_run_info *info, cs_json_text_fn text) {
    FILE *f = w->f;
    jkey(w, first, "roadside_criteria");
    if (!info || !info->criteria_count) {
        fputs("null", f);
        return;
    }
    int cf = 1, bf = 1;
    fputc('{', f);
    jkey(w, &cf, "standard");
    text(f, info->criteria_test.standard);
    jkey(w, &cf, "test");
    text(f, info->criteria_test.name);
    jkey(w, &cf, "vehicle");
    text(f, info->criteria_test.vehicle);
    jkey(w, &cf, "criteria");
    fputc('[', f);
    for (int k = 0; k < info->criteria_count; k++) {
        const cs_criterion *c = &info->criteria[k];
        int kf = 1;
        fputs(k ? ",{" : "{", f);
        jkey(w, &kf, "id");
        text(f, c->id);
        jkey(w, &kf, "criterion");
        text(f, c->name);
        jkey(w, &kf, "verdict");
        text(f, cs_verdict_name(c->verdict));
        jkey(w, &kf, "detail");
        text(f, c->detail);
        fputc('}', f);
    }
    fputc(']', f);
    const cs_exit_box *e = &info->exit_box;
    jkey(w, &cf, "exit_box");
    fputc('{', f);
    jnum(w, &bf, "a_m", e->a);
    jnum(w, &bf, "b_m", e->b);
    jnum(w, &bf, "start_x_m", e->start_x);
    jnum(w, &bf, "direction", e->dir);
    jopt(w, &bf, "cross_along_m", e->cross_along);
    jkey(w, &bf, "crossed_in_run");
    fputs(e->crossed_in_run ? "true" : "false", f);
    fputs("}}\n", f);
}

void cs_json_evaluation(cs_wout *w, int *first, const cs_run_info *info, cs_json_text_fn text) {
    occupant_risk(w, first, info, text);
    roadside_criteria(w, first, info, text);
}

int cs_write_summary_json_with(FILE *f, const cs_model_input *in, const cs_model *model,
                               const cs_state *state, const cs_run_info *info, char *why, size_t why_size) {
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    cs_wout w = {f, 0, ""};
    int first = 1;
    fprintf(f, "{");
    provenance(&w, &first, info);
    jkey(&w, &first, "outcome");
    cs_json_string(f, cs_outcome_name(s.outcome));
    jnum(&w, &first, "t_end_s", s.t_end_s);
    jnum(&w, &first, "max_50ms_decel_g", s.max_50ms_decel_g);
    jnum(&w, &first, "t_max_50ms_decel_s", s.t_max_50ms_decel_s);
    /* a penetration only where the vehicle stopped short of it; else how far it had got, "beyond" */
    int final = cs_penetration_is_final(s.outcome);
    jkey(&w, &first, "max_dynamic_penetration_m");
    if (final)
        cs_w_num(&w, s.max_dynamic_penetration_m, "max_dynamic_penetration_m");
    else
        fputs("null", f);
    jkey(&w, &first, "penetration_beyond_m");
    if (final)
        fputs("null", f);
    else
        cs_w_num(&w, s.max_dynamic_penetration_m, "penetration_beyond_m");
    jnum(&w, &first, "max_barrier_deflection_m", s.max_barrier_deflection_m);
    jnum(&w, &first, "working_width_m", s.working_width_m);
    jkey(&w, &first, "stopped");
    fprintf(f, s.outcome == CS_STOPPED ? "true" : "false");
    jkey(&w, &first, "stop_time_s");
    if (s.outcome == CS_STOPPED)
        cs_w_num(&w, s.stop_time_s, "stop_time_s");
    else
        fprintf(f, "null");
    jkey(&w, &first, "exit_speed_mps");
    if (cs_outcome_exits(s.outcome))
        cs_w_num(&w, s.exit_speed_mps, "exit_speed_mps");
    else
        fprintf(f, "null");
    jkey(&w, &first, "exit_angle_deg");
    if (cs_outcome_exits(s.outcome))
        cs_w_num(&w, s.exit_angle_deg, "exit_angle_deg");
    else
        fprintf(f, "null");
    jkey(&w, &first, "first_contact_time_s");
    if (s.first_contact_time_s >= 0)
        cs_w_num(&w, s.first_contact_time_s, "first_contact_time_s");
    else
        fprintf(f, "null");
    jkey(&w, &first, "posts_failed_left");
    fprintf(f, "%d", s.posts_failed_left);
    jkey(&w, &first, "posts_failed_right");
    fprintf(f, "%d", s.posts_failed_right);
    const char *const by_kind[6] = {"posts_failed_rotation_left", "posts_failed_rotation_right",
                                    "posts_failed_shear_left",    "posts_failed_shear_right",
                                    "posts_failed_pullout_left",  "posts_failed_pullout_right"};
    const int counts[6] = {s.posts_failed_rotation_left, s.posts_failed_rotation_right,
                           s.posts_failed_shear_left,    s.posts_failed_shear_right,
                           s.posts_failed_pullout_left,  s.posts_failed_pullout_right};
    for (int k = 0; k < 6; k++) {
        jkey(&w, &first, by_kind[k]);
        fprintf(f, "%d", counts[k]);
    }
    for (int a = 0; a < 2; a++) {
        cs_anchor_view av = {.size = sizeof av};
        cs_state_anchor(model, state, a, &av, NULL);
        char key[48];
        snprintf(key, sizeof key, "anchor_%s", a ? "end" : "start");
        jkey(&w, &first, key);
        int af = 1;
        fprintf(f, "{");
        jkey(&w, &af, "state");
        cs_json_string(f, cs_anchor_status_name(&av));
        jnum(&w, &af, "capacity_n", av.capacity);
        jnum(&w, &af, "residual_n", av.residual);
        jnum(&w, &af, "slide_m", av.slide);
        jnum(&w, &af, "displacement_m", hypot(av.displacement[0], av.displacement[1]));
        fprintf(f, "}");
    }
    jkey(&w, &first, "cables_broken");
    fprintf(f, "%d", s.cables_broken);
    jnum(&w, &first, "max_cable_tension_n", s.max_cable_tension_n);
    jnum(&w, &first, "initial_kinetic_energy_j", s.initial_kinetic_energy_j);
    jnum(&w, &first, "energy_balance_error", s.energy_balance_error);
    jkey(&w, &first, "energy_balance_warning");
    fputs(fabs(s.energy_balance_error) > CS_LEDGER_WARNING ? "true" : "false", f);
    jarray(&w, &first, "final_position_m", s.final_position_m, 3);
    jkey(&w, &first, "solver_warnings");
    fprintf(f, "%d", s.solver_warnings);
    jnum(&w, &first, "max_solver_residual", s.max_solver_residual);
    fputc('\n', f);
    cables_and_losses(&w, &first, state, &s);
    ratings(&w, &first, info);
    cs_json_evaluation(&w, &first, info, cs_json_string);
    jkey(&w, &first, "events");
    fprintf(f, "[");
    for (int i = 0; i < cs_state_event_count(state); i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(state, i, &e_held, NULL);
        const cs_event *e = &e_held;
        char element[48];
        int ef = 1;
        if (e->element_kind == CS_ELEMENT_VEHICLE)
            snprintf(element, sizeof element, "vehicle");
        else
            snprintf(element, sizeof element, "%s %d", cs_element_kind_name(e->element_kind), e->element);
        fprintf(f, "%s\n{", i ? "," : "");
        jnum(&w, &ef, "t_s", e->t);
        jkey(&w, &ef, "type");
        cs_json_string(f, cs_event_type_name(e->type));
        jkey(&w, &ef, "element");
        cs_json_string(f, element);
        jnum(&w, &ef, "value", e->value);
        jkey(&w, &ef, "unit");
        cs_json_string(f, cs_event_value_unit(e->type));
        if (e->cable_end >= 0) {
            jkey(&w, &ef, "cable_end");
            cs_json_string(f, cs_event_cable_end_name(e));
        }
        if (e->cable >= 0) {
            jkey(&w, &ef, "cable");
            fprintf(f, "%d", e->cable);
        }
        if (e->post >= 0) {
            jkey(&w, &ef, "post");
            fprintf(f, "%d", e->post);
        }
        fprintf(f, "}");
    }
    fprintf(f, "],\n\"inputs\":");
    inputs(&w, in);
    fprintf(f, "}\n");
    if (w.bad) snprintf(why, why_size, "summary.json: %s", w.why);
    return w.bad ? -1 : 0;
}
