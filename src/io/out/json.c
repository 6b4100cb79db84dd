/* SPDX-License-Identifier: MIT */
/* summary.json: the response parameters, the events and the resolved inputs (SI, keys as in the
 * model file). A limit given as "none" is null. */
#include <math.h>
#include <string.h>

#include "cablesim/units.h"
#include "jsondoc.h"
#include "load/schema.h"
#include "status.h"
#include "writers.h"

/* v as a number of the document; NULL (null) and w marked bad, naming what, if it is not finite. */
static json_object *wnum(cs_wout *w, double v, const char *what) {
    return cs_w_finite(w, v, what) ? cs_jnum(v) : NULL;
}

static void jnum(cs_wout *w, json_object *obj, const char *key, double v) {
    json_object_object_add(obj, key, wnum(w, v, key));
}

static void jint(json_object *obj, const char *key, int v) {
    json_object_object_add(obj, key, json_object_new_int(v));
}

static void jstr(json_object *obj, const char *key, const char *v) {
    json_object_object_add(obj, key, cs_jstr(v));
}

static void jbool(json_object *obj, const char *key, int v) {
    json_object_object_add(obj, key, json_object_new_boolean(v));
}

/* The fields of a table that map to members of def, as members of obj. */
static void jfields(cs_wout *w, json_object *obj, const cs_table *t, const void *def) {
    for (int i = 0; i < t->count; i++) {
        const cs_field *fd = &t->fields[i];
        if (fd->offset < 0) continue;
        const char *at = (const char *)def + fd->offset;
        if (cs_field_unset(fd, at)) continue;
        json_object *v = NULL;
        if (fd->kind == CS_F_MAP) {
            v = json_object_new_object();
            jfields(w, v, fd->sub, at);
        } else if (fd->kind == CS_F_INT || fd->kind == CS_F_ENUM) {
            int n;
            memcpy(&n, at, sizeof n);
            if (fd->kind == CS_F_ENUM)
                v = n < 0 ? NULL /* a CS_OWN map's: its parent's */ : cs_jstr(fd->words[n]);
            else
                v = json_object_new_int(n);
        } else {
            double x;
            memcpy(&x, at, sizeof x);
            if (!((fd->flags & CS_NONE_OK) && isinf(x) && x > 0)) v = wnum(w, x, fd->key);
        }
        json_object_object_add(obj, fd->key, v);
    }
}

static void jobject(cs_wout *w, json_object *obj, const char *key, const cs_table *t, const void *def) {
    json_object *sub = json_object_new_object();
    jfields(w, sub, t, def);
    json_object_object_add(obj, key, sub);
}

void cs_json_cables_and_losses(cs_wout *w, json_object *to, const cs_state *state, const cs_summary *s,
                               cs_jnum_fn number) {
    json_object *cables = json_object_new_array(), *list = json_object_new_array();
    for (int c = 0; c < s->cable_count; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        cs_state_cable_summary(state, c, &cb, NULL);
        json_object *o = json_object_new_object();
        jint(o, "index", c);
        json_object_object_add(o, "peak_tension_n", number(w, cb.peak_tension_n, "peak_tension_n"));
        json_object_object_add(o, "peak_tension_time_s",
                               number(w, cb.peak_tension_time_s, "peak_tension_time_s"));
        json_object_object_add(o, "work_on_vehicle_j", number(w, cb.work_on_vehicle_j, "work_on_vehicle_j"));
        json_object_object_add(o, "energy_share", number(w, cb.energy_share, "energy_share"));
        json_object_array_add(cables, o);
    }
    json_object_object_add(to, "cables", cables);
    jint(to, "sudden_loss_count", s->sudden_loss_count);
    cs_sudden_loss losses[CS_SUDDEN_LOSS_KEPT] = {{.size = sizeof losses[0]}};
    int n = cs_state_sudden_losses(state, losses, CS_SUDDEN_LOSS_KEPT, NULL);
    for (int k = 0; k < n; k++) {
        json_object *o = json_object_new_object();
        json_object_object_add(o, "t_start_s", number(w, losses[k].t_start_s, "t_start_s"));
        json_object_object_add(o, "t_end_s", number(w, losses[k].t_end_s, "t_end_s"));
        json_object_object_add(o, "force_before_n", number(w, losses[k].force_before_n, "force_before_n"));
        json_object_object_add(o, "force_after_n", number(w, losses[k].force_after_n, "force_after_n"));
        json_object_array_add(list, o);
    }
    json_object_object_add(to, "sudden_losses", list);
}

static json_object *jarray(cs_wout *w, const char *what, const double *v, int n) {
    json_object *a = json_object_new_array();
    for (int i = 0; i < n; i++)
        json_object_array_add(a, wnum(w, v[i], what));
    return a;
}

/* Cable c as the run used it: termination_efficiency the strength its fittings are given (0 in the
 * model is its kind's published value, written as that value), and "ends": the fitting at the start and
 * at the end anchor, each its kind, strength over Fu and slip (cs_cable_end_efficiency, cs_cable_end_slip:
 * what report.html's design table shows). */
static json_object *cable_input(cs_wout *w, const cs_cable_def *cable) {
    cs_cable_def used = *cable;
    if (!(used.termination_efficiency > 0.0))
        used.termination_efficiency = cs_termination_efficiency(used.termination, used.rope.diameter);
    json_object *o = json_object_new_object(), *ends = json_object_new_array();
    jfields(w, o, &cs_table_cable, &used);
    jobject(w, o, "rope", &cs_table_rope, &cable->rope);
    for (int k = 0; k < 2; k++) {
        cs_termination kind;
        double travel, efficiency = cs_cable_end_efficiency(cable, k, &kind);
        double slip = cs_cable_end_slip(cable, k, &travel);
        json_object *e = json_object_new_object();
        jstr(e, "termination", cs_termination_word(kind));
        jnum(w, e, "termination_efficiency", efficiency);
        jnum(w, e, "slip_load", slip);
        jnum(w, e, "slip_travel", slip > 0.0 ? travel : 0.0);
        json_object_array_add(ends, e);
    }
    json_object_object_add(o, "ends", ends);
    return o;
}

/* The SI unit of each number a table's fields give, by key, into units ("1" for a pure number or a count;
 * a key has one unit wherever it stands in the schema): its quantities and lists of them, its counts, and
 * its mappings' fields. */
static void junits(json_object *units, const cs_table *t) {
    for (int i = 0; i < t->count; i++) {
        const cs_field *fd = &t->fields[i];
        if (fd->kind == CS_F_MAP && fd->offset >= 0)
            junits(units, fd->sub);
        else if ((fd->kind == CS_F_QTY || fd->kind == CS_F_LIST || fd->kind == CS_F_INT) &&
                 !json_object_object_get_ex(units, fd->key, NULL))
            json_object_object_add(units, fd->key,
                                   cs_jstr(fd->kind == CS_F_INT ? "1" : cs_quantity_get(fd->q)->label));
    }
}

/* "input_units": the unit of every number of "inputs", by its key. */
static json_object *input_units(void) {
    json_object *units = json_object_new_object();
    const cs_table *const tables[] = {&cs_table_cable,   &cs_table_rope,    &cs_table_posts,
                                      &cs_table_section, &cs_table_anchors, &cs_table_vehicle,
                                      &cs_table_scenario};
    for (size_t k = 0; k < sizeof tables / sizeof tables[0]; k++)
        junits(units, tables[k]);
    return units;
}

/* The model as run, each post on a line of its own. */
static json_object *inputs(cs_wout *w, const cs_model_input *in) {
    json_object *top = json_object_new_object(), *barrier = json_object_new_object();
    json_object *cables = json_object_new_array(), *posts = json_object_new_array();
    json_object *vehicle = json_object_new_object();
    jstr(top, "name", in->name);
    jstr(top, "file", in->file);
    for (int c = 0; c < in->barrier.cable_count; c++)
        json_object_array_add(cables, cable_input(w, &in->barrier.cables[c]));
    json_object_object_add(barrier, "cables", cables);
    for (int p = 0; p < in->barrier.post_count; p++) {
        const cs_post_def *post = &in->barrier.posts[p];
        json_object *o = json_object_new_object();
        jnum(w, o, "x", post->x);
        jfields(w, o, &cs_table_posts, post);
        jobject(w, o, "section", &cs_table_section, &post->section);
        json_object_array_add(posts, cs_jline_before(o));
    }
    json_object_object_add(barrier, "posts", posts);
    jobject(w, barrier, "anchors", &cs_table_anchors, &in->barrier);
    json_object_object_add(top, "barrier", barrier);
    jfields(w, vehicle, &cs_table_vehicle, &in->vehicle);
    const cs_vehicle_def *v = &in->vehicle;
    json_object_object_add(vehicle, "crush_deformation",
                           jarray(w, "crush_deformation", v->crush_deformation, v->crush_point_count));
    json_object_object_add(vehicle, "crush_force",
                           jarray(w, "crush_force", v->crush_force, v->crush_point_count));
    json_object_object_add(top, "vehicle", vehicle);
    jobject(w, top, "scenario", &cs_table_scenario, &in->scenario);
    return top;
}

json_object *cs_json_provenance(const cs_run_info *info) {
    json_object *o = json_object_new_object(), *overrides = json_object_new_array();
    jstr(o, "version", CS_VERSION_STRING);
    jstr(o, "command", info ? info->command : NULL);
    for (int i = 0; info && i < info->override_count; i++)
        json_object_array_add(overrides, cs_jstr(info->overrides[i]));
    json_object_object_add(o, "overrides", overrides);
    char hash[17];
    if (info) cs_model_hash_text(info->model_hash, hash);
    jstr(o, "model_hash", info ? hash : NULL);
    return o;
}

/* "designations_as_run": the standards' designation of the test the run is (docs/ratings.md), in
 * cs_rating_text's words with its parts. */
static void ratings(cs_wout *w, json_object *doc, const cs_run_info *info) {
    json_object *list = json_object_new_array();
    for (int i = 0; info && i < info->rating_count; i++) {
        const cs_rating *r = &info->ratings[i];
        char text[256];
        cs_rating_text(r, text, sizeof text);
        json_object *o = json_object_new_object();
        jstr(o, "standard", cs_standard_name(r->standard));
        jstr(o, "label", r->label);
        jstr(o, "text", text);
        jbool(o, "rated", r->rated);
        jstr(o, "vehicle_class", r->vehicle_class);
        jint(o, "speed_mph", r->speed_mph);
        json_object_object_add(
            o, "penetration_m",
            r->tested && !r->through ? wnum(w, r->penetration, "a designation's penetration") : NULL);
        jstr(o, "measured", r->reference ? r->reference : "");
        json_object_array_add(list, o);
    }
    json_object_object_add(doc, "designations_as_run", list);
}

/* A number, or null if it is not finite (a window that did not fit, an impact that never came). */
static void jopt(cs_wout *w, json_object *obj, const char *key, double v) {
    json_object_object_add(obj, key, isfinite(v) ? wnum(w, v, key) : NULL);
}

/* How a flail impact is named in summary.json: "in_run", "after_run", "none". */
static const char *flail_impact_name(cs_flail_impact k) {
    return k == CS_FLAIL_IN_RECORD ? "in_run" : k == CS_FLAIL_AFTER_RECORD ? "after_run" : "none";
}

/* "occupant_risk" at the CG (docs/ratings.md, Occupant risk), or null with "occupant_risk_note" saying
 * why; "max_roll_deg" and "max_pitch_deg". */
static void occupant_risk(cs_wout *w, json_object *to, const cs_run_info *info) {
    if (!info || !info->motion || !info->occupant_ok) {
        json_object_object_add(to, "occupant_risk", NULL);
        jstr(to, "occupant_risk_note",
             !info || !info->motion ? "no record of the run's motion" : info->occupant_error.message);
    } else {
        const cs_occupant_risk *o = &info->occupant;
        cs_occupant_rules r = cs_default_occupant_rules();
        json_object *risk = json_object_new_object();
        char basis[200];
        snprintf(
            basis, sizeof basis, "%s, accelerations filtered to SAE J211/1 CFC %.0f, from the first contact",
            info->occupant_at ? "a point of the vehicle (point_m: from its centre of gravity, x forward, y "
                                "left, z up)"
                              : "the vehicle's centre of gravity",
            r.cfc);
        jstr(risk, "basis", basis);
        const double cg[3] = {0, 0, 0};
        json_object_object_add(risk, "point_m",
                               jarray(w, "point_m", info->occupant_at ? info->occupant_point : cg, 3));
        jstr(risk, "occupant_impact", flail_impact_name(o->impact));
        jopt(w, risk, "occupant_impact_time_s", o->t_impact);
        jnum(w, risk, "oiv_longitudinal_mps", o->oiv_x);
        jnum(w, risk, "oiv_lateral_mps", o->oiv_y);
        jnum(w, risk, "ora_longitudinal_g", o->ora_x);
        jnum(w, risk, "ora_lateral_g", o->ora_y);
        jstr(risk, "head_impact", flail_impact_name(o->thiv_impact));
        jopt(w, risk, "thiv_time_s", o->t_thiv);
        jnum(w, risk, "thiv_mps", o->thiv);
        jnum(w, risk, "thiv_kmh", o->thiv * 3.6);
        jnum(w, risk, "phd_g", o->phd);
        jnum(w, risk, "asi", o->asi);
        jopt(w, risk, "asi_time_s", o->t_asi);
        json_object_object_add(to, "occupant_risk", risk);
    }
    if (info && info->motion) {
        jnum(w, to, "max_roll_deg", info->roll_peak / CS_DEG);
        jnum(w, to, "max_pitch_deg", info->pitch_peak / CS_DEG);
    }
}

/* "roadside_criteria": the criteria of the roadside test the run stands for, as run, with MASH's exit
 * box (a criterion of MASH's tests only), or null. */
static json_object *roadside_criteria(cs_wout *w, const cs_run_info *info) {
    if (!info || !info->criteria_count) return NULL;
    json_object *o = json_object_new_object(), *list = json_object_new_array(),
                *box = json_object_new_object();
    jstr(o, "standard", info->criteria_test.standard);
    jstr(o, "test", info->criteria_test.name);
    jstr(o, "vehicle", info->criteria_test.vehicle);
    for (int k = 0; k < info->criteria_count; k++) {
        const cs_criterion *c = &info->criteria[k];
        json_object *e = json_object_new_object();
        jstr(e, "id", c->id);
        jstr(e, "criterion", c->name);
        jstr(e, "verdict", cs_verdict_name(c->verdict));
        jstr(e, "detail", c->detail);
        json_object_array_add(list, e);
    }
    json_object_object_add(o, "criteria", list);
    const cs_exit_box *e = &info->exit_box;
    jnum(w, box, "a_m", e->a);
    jnum(w, box, "b_m", e->b);
    jnum(w, box, "start_x_m", e->start_x);
    jnum(w, box, "direction", e->dir);
    jopt(w, box, "cross_along_m", e->cross_along);
    jbool(box, "crossed_in_run", e->crossed_in_run);
    jbool(box, "heading_back", e->heading_back);
    json_object_object_add(o, "exit_box", box);
    return o;
}

void cs_json_evaluation(cs_wout *w, json_object *to, const cs_run_info *info, int line_breaks) {
    occupant_risk(w, to, info);
    if (line_breaks) cs_jline_after_last(to);
    json_object *criteria = roadside_criteria(w, info);
    json_object_object_add(to, "roadside_criteria",
                           criteria && line_breaks ? cs_jline_after(criteria) : criteria);
}

/* An event as summary.json gives it. */
static json_object *event(cs_wout *w, const cs_event *e) {
    char element[48];
    if (e->element_kind == CS_ELEMENT_VEHICLE)
        snprintf(element, sizeof element, "vehicle");
    else
        snprintf(element, sizeof element, "%s %d", cs_element_kind_name(e->element_kind), e->element);
    json_object *o = json_object_new_object();
    jnum(w, o, "t_s", e->t);
    jstr(o, "type", cs_event_type_name(e->type));
    jstr(o, "element", element);
    jnum(w, o, "value", e->value);
    jstr(o, "unit", cs_event_value_unit(e->type));
    if (e->cable_end >= 0) jstr(o, "cable_end", cs_event_cable_end_name(e));
    if (e->cable >= 0) jint(o, "cable", e->cable);
    if (e->post >= 0) jint(o, "post", e->post);
    return o;
}

json_object *cs_summary_json(const cs_model_input *in, const cs_model *model, const cs_state *state,
                             const cs_run_info *info, cs_error *err) {
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    cs_wout w = {NULL, 0, ""};
    json_object *doc = json_object_new_object();
    if (!doc) {
        cs_status_set(err, CS_ERR_MEMORY, "summary.json: out of memory");
        return NULL;
    }
    /* "cablesim": where the results come from, on a line of its own */
    json_object_object_add(doc, "cablesim", cs_jline_after(cs_json_provenance(info)));
    jstr(doc, "outcome", cs_outcome_name(s.outcome));
    jnum(&w, doc, "t_end_s", s.t_end_s);
    jnum(&w, doc, "max_50ms_decel_g", s.max_50ms_decel_g);
    jnum(&w, doc, "t_max_50ms_decel_s", s.t_max_50ms_decel_s);
    /* a penetration only where the vehicle stopped short of it; else how far it had got, "beyond" */
    int final = cs_penetration_is_final(s.outcome), exits = cs_outcome_exits(s.outcome);
    json_object_object_add(doc, "max_dynamic_penetration_m",
                           final ? wnum(&w, s.max_dynamic_penetration_m, "max_dynamic_penetration_m") : NULL);
    json_object_object_add(doc, "penetration_beyond_m",
                           final ? NULL : wnum(&w, s.max_dynamic_penetration_m, "penetration_beyond_m"));
    jnum(&w, doc, "max_barrier_deflection_m", s.max_barrier_deflection_m);
    jnum(&w, doc, "working_width_m", s.working_width_m);
    jbool(doc, "stopped", s.outcome == CS_STOPPED);
    json_object_object_add(doc, "stop_time_s",
                           s.outcome == CS_STOPPED ? wnum(&w, s.stop_time_s, "stop_time_s") : NULL);
    json_object_object_add(doc, "exit_speed_mps",
                           exits ? wnum(&w, s.exit_speed_mps, "exit_speed_mps") : NULL);
    json_object_object_add(doc, "exit_angle_deg",
                           exits ? wnum(&w, s.exit_angle_deg, "exit_angle_deg") : NULL);
    json_object_object_add(doc, "exit_time_s", exits ? wnum(&w, s.exit_time_s, "exit_time_s") : NULL);
    json_object_object_add(
        doc, "first_contact_time_s",
        s.first_contact_time_s >= 0 ? wnum(&w, s.first_contact_time_s, "first_contact_time_s") : NULL);
    jint(doc, "posts_failed_left", s.posts_failed_left);
    jint(doc, "posts_failed_right", s.posts_failed_right);
    const char *const by_kind[6] = {"posts_failed_rotation_left", "posts_failed_rotation_right",
                                    "posts_failed_shear_left",    "posts_failed_shear_right",
                                    "posts_failed_pullout_left",  "posts_failed_pullout_right"};
    const int counts[6] = {s.posts_failed_rotation_left, s.posts_failed_rotation_right,
                           s.posts_failed_shear_left,    s.posts_failed_shear_right,
                           s.posts_failed_pullout_left,  s.posts_failed_pullout_right};
    for (int k = 0; k < 6; k++)
        jint(doc, by_kind[k], counts[k]);
    for (int a = 0; a < 2; a++) {
        cs_anchor_view av = {.size = sizeof av};
        cs_state_anchor(model, state, a, &av, NULL);
        json_object *o = json_object_new_object();
        jstr(o, "state", cs_anchor_status_name(&av));
        jnum(&w, o, "capacity_n", av.capacity);
        jnum(&w, o, "residual_n", av.residual);
        jnum(&w, o, "slide_m", av.slide);
        jnum(&w, o, "displacement_m", hypot(av.displacement[0], av.displacement[1]));
        jnum(&w, o, "lift_m", av.lift);
        jnum(&w, o, "peak_pull_n", av.peak_pull);
        json_object_object_add(doc, a ? "anchor_end" : "anchor_start", o);
    }
    jint(doc, "cables_broken", s.cables_broken);
    jnum(&w, doc, "max_cable_tension_n", s.max_cable_tension_n);
    jnum(&w, doc, "initial_kinetic_energy_j", s.initial_kinetic_energy_j);
    jnum(&w, doc, "energy_balance_error", s.energy_balance_error);
    jbool(doc, "energy_balance_warning", fabs(s.energy_balance_error) > CS_LEDGER_WARNING);
    json_object_object_add(doc, "final_position_m", jarray(&w, "final_position_m", s.final_position_m, 3));
    jint(doc, "solver_warnings", s.solver_warnings);
    jnum(&w, doc, "max_solver_residual", s.max_solver_residual);
    cs_jline_after_last(doc);
    jint(doc, "cable_count", s.cable_count);
    cs_json_cables_and_losses(&w, doc, state, &s, wnum);
    cs_jline_after_last(doc); /* a line break after the sudden losses */
    ratings(&w, doc, info);
    cs_json_evaluation(&w, doc, info, 1);
    json_object *events = json_object_new_array(); /* each on a line of its own */
    for (int i = 0; i < cs_state_event_count(state); i++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(state, i, &e, NULL);
        json_object_array_add(events, cs_jline_before(event(&w, &e)));
    }
    json_object_object_add(doc, "events", events);
    json_object_object_add(doc, "inputs", inputs(&w, in));
    json_object_object_add(doc, "input_units", input_units());
    static const char *const new_line[] = {"inputs", "input_units", NULL};
    cs_jkeys_on_new_line(doc, new_line);
    if (cs_w_status(&w, "summary.json", err) == CS_OK) return doc;
    json_object_put(doc);
    return NULL;
}

cs_status cs_write_summary_json_with(FILE *f, const cs_model_input *in, const cs_model *model,
                                     const cs_state *state, const cs_run_info *info, cs_error *err) {
    cs_error own;
    json_object *doc = cs_summary_json(in, model, state, info, err ? err : &own);
    if (!doc) return err ? err->status : own.status;
    int written = cs_json_write(f, doc, 0, "\n") == 0;
    json_object_put(doc);
    return written ? CS_OK : cs_status_set(err, CS_ERR_MEMORY, "summary.json: out of memory");
}
