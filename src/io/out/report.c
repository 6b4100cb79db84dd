/* SPDX-License-Identifier: MIT */
/* The readable summary printed after a run: SI first, US units beside. */
#include <math.h>
#include <string.h>

#include "cablesim/units.h"
#include "out/htmltext.h"
#include "out/numtext.h"
#include "status.h"
#include "writers.h"

/* Events that are the barrier or the vehicle giving way, listed one by one; the posts' yielding (a hinge
 * at the base, a footing turning in the soil) is counted instead. */
static int yielding(cs_event_type t) {
    return t == CS_EVENT_POST_HINGE || t == CS_EVENT_FOOTING_ROTATION;
}

static void events(FILE *f, const cs_state *state) {
    enum { LISTED = 30 };
    int n = cs_state_event_count(state), failures = 0, hinges = 0, footings = 0;
    cs_event first_yield = {0};
    char tt[CS_TIME_TEXT_SIZE];
    for (int i = 0; i < n; i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(state, i, &e_held, NULL);
        const cs_event *e = &e_held;
        if (!yielding(e->type)) {
            failures++;
            continue;
        }
        hinges += e->type == CS_EVENT_POST_HINGE;
        footings += e->type == CS_EVENT_FOOTING_ROTATION;
        if (hinges + footings == 1) first_yield = *e;
    }
    /* the times listed with the places that show each exactly (cs_time_text), the most any needs */
    int places = 4;
    for (int i = 0, listed = 0; i < n && listed < LISTED; i++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(state, i, &e, NULL);
        if (yielding(e.type)) continue;
        listed++;
        const char *dot = strchr(cs_time_text(e.t, tt), '.');
        if (dot && (int)strlen(dot + 1) > places) places = (int)strlen(dot + 1);
    }
    fprintf(f, "  failure events       %d, in order (every event of the run: events.csv)\n", failures);
    for (int i = 0, listed = 0; i < n; i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(state, i, &e_held, NULL);
        const cs_event *e = &e_held;
        if (yielding(e->type)) continue;
        if (listed++ == LISTED) {
            fprintf(f, "    ... %d more in events.csv\n", failures - LISTED);
            break;
        }
        if (e->element_kind == CS_ELEMENT_VEHICLE)
            fprintf(f, "    %8.*f s  %s\n", places, e->t, cs_event_type_name(e->type));
        else if (e->cable >= 0) /* a cable a post let go */
            fprintf(f, "    %8.*f s  %-19s %s %d lets cable %d go\n", places, e->t,
                    cs_event_type_name(e->type), cs_element_kind_name(e->element_kind), e->element, e->cable);
        else if (e->post >= 0) /* a rope broken at a threaded post's hole */
            fprintf(f, "    %8.*f s  %-19s %s %d at post %d's hole\n", places, e->t,
                    cs_event_type_name(e->type), cs_element_kind_name(e->element_kind), e->element, e->post);
        else if (e->cable_end >= 0) /* a termination event: the rope end that slipped or let go */
            fprintf(f, "    %8.*f s  %-19s %s %d at the %s anchor\n", places, e->t,
                    cs_event_type_name(e->type), cs_element_kind_name(e->element_kind), e->element,
                    cs_event_cable_end_name(e));
        else
            fprintf(f, "    %8.*f s  %-19s %s %d\n", places, e->t, cs_event_type_name(e->type),
                    cs_element_kind_name(e->element_kind), e->element);
    }
    if (hinges + footings)
        fprintf(
            f,
            "  posts yielding       %d plastic hinge%s at the base, %d footing%s turning in the soil (the "
            "first at %.*f s, post %d)\n",
            hinges, hinges == 1 ? "" : "s", footings, footings == 1 ? "" : "s", places, first_yield.t,
            first_yield.element);
    else
        fprintf(f, "  posts yielding       none\n");
}

/* A warning for each sudden loss of the barrier's force on the vehicle (docs/theory.md, Response
 * parameters). */
static void sudden_losses(FILE *f, const cs_state *state, const cs_summary *s) {
    cs_sudden_loss losses[CS_SUDDEN_LOSS_KEPT] = {{.size = sizeof losses[0]}};
    int n = cs_state_sudden_losses(state, losses, CS_SUDDEN_LOSS_KEPT, NULL);
    for (int k = 0; k < n; k++) {
        char t0[CS_TIME_TEXT_SIZE], t1[CS_TIME_TEXT_SIZE];
        fprintf(
            f,
            "  WARNING sudden loss: force on the vehicle fell from %.1f kN (%.1f kip) to %.1f kN (%.1f kip) "
            "between %s and %s s with no rope, fitting or attachment failing and no rope passed over or "
            "under\n",
            losses[k].force_before_n / 1e3, losses[k].force_before_n / CS_KIP, losses[k].force_after_n / 1e3,
            losses[k].force_after_n / CS_KIP, cs_time_text(losses[k].t_start_s, t0),
            cs_time_text(losses[k].t_end_s, t1));
    }
    if (s->sudden_loss_count > n)
        fprintf(f, "  WARNING sudden loss: %d more such windows\n", s->sudden_loss_count - n);
}

/* The occupant risk at the CG and the roll and pitch peaks (docs/ratings.md, Occupant risk). */
static void occupant(FILE *f, const cs_run_info *info) {
    if (!info || !info->motion) return;
    fprintf(f, "  roll, pitch (max)    %.1f deg, %.1f deg\n", info->roll_peak / CS_DEG,
            info->pitch_peak / CS_DEG);
    if (!info->occupant_ok) {
        fprintf(f, "  occupant risk        none: %s\n", info->occupant_error.message);
        return;
    }
    const cs_occupant_risk *o = &info->occupant;
    if (info->occupant_at)
        fprintf(f, "  occupant risk at     x %.3f m, y %.3f m, z %.3f m from the CG (forward, left, up)\n",
                info->occupant_point[0], info->occupant_point[1], info->occupant_point[2]);
    if (o->impact == CS_FLAIL_NONE)
        fprintf(f, "  occupant impact      none: the occupant did not move against the vehicle\n");
    else
        fprintf(f,
                "  occupant impact      %.3f s after first contact%s: OIV %.2f m/s (%.1f ft/s) longitudinal, "
                "%.2f m/s (%.1f ft/s) lateral\n",
                o->t_impact, o->impact == CS_FLAIL_AFTER_RECORD ? " (after the run's end)" : "", o->oiv_x,
                o->oiv_x / CS_FT, o->oiv_y, o->oiv_y / CS_FT);
    fprintf(f, "  ridedown (10 ms)     ORA %.2f g longitudinal, %.2f g lateral\n", o->ora_x, o->ora_y);
    fprintf(f, "  EN 1317-1            THIV %.1f km/h (%.2f m/s)%s, PHD %.2f g, ASI %.2f\n", o->thiv * 3.6,
            o->thiv,
            o->thiv_impact == CS_FLAIL_AFTER_RECORD ? " (head impact after the run's end)"
            : o->thiv_impact == CS_FLAIL_NONE       ? " (no head impact)"
                                                    : "",
            o->phd, o->asi);
}

void cs_write_summary_text(FILE *f, const cs_model_input *in, const cs_model *model, const cs_state *state) {
    cs_error err;
    if (cs_status_input(in, &err) != CS_OK) {
        fprintf(f, "%s\n", err.message);
        return;
    }
    cs_run_info info;
    cs_run_info_of(&info, in, state);
    cs_write_summary_text_with(f, in, model, state, &info);
}

void cs_write_summary_text_with(FILE *f, const cs_model_input *in, const cs_model *model,
                                const cs_state *state, const cs_run_info *info) {
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    const cs_scenario_def *sc = &in->scenario;
    char tt[CS_TIME_TEXT_SIZE];
    cs_term_text(f, in->name);
    fprintf(f, ": ");
    if (s.outcome == CS_STOPPED)
        fprintf(f, "the vehicle stopped at t = %s s\n", cs_time_text(s.stop_time_s, tt));
    else if (cs_outcome_through(s.outcome))
        fprintf(f, "the vehicle %s, exit speed %.2f m/s (%.1f mph)\n",
                s.outcome == CS_OVERRIDE    ? "rode over the cables"
                : s.outcome == CS_UNDERRIDE ? "ran under the cables"
                                            : "broke through",
                s.exit_speed_mps, s.exit_speed_mps / CS_MPH);
    else if (s.outcome == CS_NO_CONTACT)
        fprintf(f, "the vehicle never touched the barrier (t = %s s)\n", cs_time_text(s.t_end_s, tt));
    else if (s.outcome == CS_DID_NOT_CONVERGE)
        fprintf(f,
                "the run did not converge: its barrier solves used up their budget (their count or "
                "their work) at t = %s s (scenario.solve_budget); what it reached is below\n",
                cs_time_text(s.t_end_s, tt));
    else if (s.outcome == CS_STEP_LIMIT)
        fprintf(f,
                "the run took its %.0f steps (scenario.max_steps) at t = %s s, before its end time; what "
                "it reached is below\n",
                in->scenario.max_steps > 0.0 ? floor(in->scenario.max_steps) : CS_MAX_STEPS_DEFAULT,
                cs_time_text(s.t_end_s, tt));
    else if (s.outcome == CS_REDIRECTED)
        fprintf(f,
                "the vehicle was redirected, exit speed %.2f m/s (%.1f mph, %.1f km/h) at %.1f deg, leaving "
                "contact at t = %s s\n",
                s.exit_speed_mps, s.exit_speed_mps / CS_MPH, s.exit_speed_mps * 3.6, s.exit_angle_deg,
                cs_time_text(s.exit_time_s, tt));
    else
        fprintf(f, "the time limit was reached at t = %s s\n", cs_time_text(s.t_end_s, tt));
    if (info) {
        char hash[17];
        cs_model_hash_text(info->model_hash, hash);
        fprintf(f, "  model hash           %s (cablesim %s)\n", hash, CS_VERSION_STRING);
    }
    fprintf(f,
            "  impact               %.2f m/s (%.1f mph), %.1f deg, x = %.2f m (%.2f ft), %.0f kg (%.0f lb)\n",
            sc->speed, sc->speed / CS_MPH, sc->angle / CS_DEG, sc->impact_x, sc->impact_x / CS_FT,
            in->vehicle.mass, in->vehicle.mass / CS_LB);
    fprintf(f, "  max 50-ms deceleration %.3f g at t = %s s\n", s.max_50ms_decel_g,
            cs_time_text(s.t_max_50ms_decel_s, tt));
    double pen = s.max_dynamic_penetration_m;
    if (cs_penetration_is_final(s.outcome))
        fprintf(f, "  max penetration      %.3f m (%.2f ft)\n", pen, pen / CS_FT);
    else
        fprintf(f, "  penetration          beyond %.3f m (%.2f ft): %s\n", pen, pen / CS_FT,
                cs_outcome_through(s.outcome) ? "the vehicle got through"
                                              : "the run ended with the vehicle still going");
    fprintf(f, "  max deflection       %.3f m (%.2f ft)\n", s.max_barrier_deflection_m,
            s.max_barrier_deflection_m / CS_FT);
    fprintf(f, "  working width        %.3f m (%.2f ft)\n", s.working_width_m, s.working_width_m / CS_FT);
    fprintf(f, "  max cable tension    %.1f kN (%.1f kip)\n", s.max_cable_tension_n / 1e3,
            s.max_cable_tension_n / CS_KIP);
    for (int c = 0; c < s.cable_count; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        cs_state_cable_summary(state, c, &cb, NULL);
        fprintf(f,
                "  cable %-2d             peak %.1f kN (%.1f kip) at %s s; work on the vehicle %.1f kJ (%.0f "
                "ft-kip), %.1f%% of its kinetic energy taken\n",
                c, cb.peak_tension_n / 1e3, cb.peak_tension_n / CS_KIP,
                cs_time_text(cb.peak_tension_time_s, tt), cb.work_on_vehicle_j / 1e3,
                cb.work_on_vehicle_j / (CS_KIP * CS_FT), 100.0 * cb.energy_share);
    }
    fprintf(f, "  cables broken        %d of %d\n", s.cables_broken, in->barrier.cable_count);
    fprintf(f,
            "  posts failed         %d left, %d right (of %d): rotation limit %d + %d, shear %d + %d, "
            "pullout %d + %d\n",
            s.posts_failed_left, s.posts_failed_right, in->barrier.post_count, s.posts_failed_rotation_left,
            s.posts_failed_rotation_right, s.posts_failed_shear_left, s.posts_failed_shear_right,
            s.posts_failed_pullout_left, s.posts_failed_pullout_right);
    for (int a = 0; a < 2; a++) {
        cs_anchor_view av = {.size = sizeof av};
        cs_state_anchor(model, state, a, &av, NULL);
        fprintf(f, "  %s anchor         ", a ? "end  " : "start");
        if (av.rigid)
            fputs("rigid", f);
        else
            fprintf(f, "%s, moved %.3f m (the soil's peak %.1f kN, %.1f kip; residual %.1f kN, %.1f kip)",
                    cs_anchor_status_name(&av), hypot(av.displacement[0], av.displacement[1]),
                    av.capacity / 1e3, av.capacity / CS_KIP, av.residual / 1e3, av.residual / CS_KIP);
        if (av.lift > 0.0)
            fprintf(f, ", risen %.3f m (%.2f ft) out of the soil by the ropes' uplift", av.lift,
                    av.lift / CS_FT);
        fprintf(f, "; the ropes pulled it with up to %.1f kN (%.1f kip)\n", av.peak_pull / 1e3,
                av.peak_pull / CS_KIP);
    }
    fprintf(f, "  kinetic energy       %.1f kJ (%.0f ft-kip)\n", s.initial_kinetic_energy_j / 1e3,
            s.initial_kinetic_energy_j / (CS_KIP * CS_FT));
    fprintf(f, "  energy balance error %.3f %%%s\n", 100 * s.energy_balance_error,
            fabs(s.energy_balance_error) > CS_LEDGER_WARNING
                ? " (WARNING: over 1%, the ledger does not close: docs/robustness.md)"
                : "");
    sudden_losses(f, state, &s);
    if (s.solver_warnings)
        fprintf(f, "  solver warnings      %d steps (largest residual %.2g)\n", s.solver_warnings,
                s.max_solver_residual);
    occupant(f, info);
    if (info && info->criteria_count) {
        fprintf(f, "  criteria (as run)    %s %s:", info->criteria_test.standard, info->criteria_test.name);
        for (int k = 0; k < info->criteria_count; k++)
            fprintf(f, "%s %s %s", k ? "," : "", info->criteria[k].id,
                    cs_verdict_name(info->criteria[k].verdict));
        fprintf(f, " (each with its numbers: summary.json roadside_criteria)\n");
    }
    for (int i = 0; info && i < info->rating_count; i++) {
        char text[256];
        cs_rating_text(&info->ratings[i], text, sizeof text);
        fprintf(f, "  %-20s %s\n", i ? "" : "designation (as run)", text);
    }
    events(f, state);
}
