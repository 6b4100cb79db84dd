/* SPDX-License-Identifier: MIT */
/* What the elements (src/elements) offer the solver and the run above them: each part's physics on the
 * core's model and state (the rope law, a cable's path and ends, the posts with their footings, rails and
 * attachments, the anchors, the vehicle and its contacts) and the energy ledger over them. How each gives
 * its rows to the barrier's solve: rows.h. */
#ifndef CS_ELEMENTS_H
#define CS_ELEMENTS_H

#include "core/core.h"

/* The HHT-alpha method (Hilber, Hughes and Taylor 1977) that moves the bodies with mass, the posts'
 * swing and the dead-men's slide: M a = (1 + alpha) F - alpha F_c, with Newmark's u = u_c + h v_c +
 * h^2 ((1/2 - beta) a_c + beta a) and v = v_c + h ((1 - gamma) a_c + gamma a). Second order and
 * unconditionally stable; alpha < 0 damps the modes the step does not resolve (docs/theory.md). */
#define CS_HHT_ALPHA (-0.1)
#define CS_HHT_BETA (0.25 * (1.0 - CS_HHT_ALPHA) * (1.0 - CS_HHT_ALPHA))
#define CS_HHT_GAMMA (0.5 - CS_HHT_ALPHA)
/* The acceleration a step of the method gives, from x_c, v_c and a_c at the last commit to x over h,
 * and the rate it ends with. */
static inline double cs_hht_acceleration(double x, double x_c, double v_c, double a_c, double h) {
    return (x - x_c - h * v_c) / (CS_HHT_BETA * h * h) - (0.5 / CS_HHT_BETA - 1.0) * a_c;
}
static inline double cs_hht_rate(double v_c, double a_c, double a, double h) {
    return v_c + h * ((1.0 - CS_HHT_GAMMA) * a_c + CS_HHT_GAMMA * a);
}
/* The inertial force m a of the method's residual, (m a + alpha F_c) / (1 + alpha), and its slope on x. */
static inline double cs_hht_inertia(double m, double a, double f_c) {
    return (m * a + CS_HHT_ALPHA * f_c) / (1.0 + CS_HHT_ALPHA);
}
static inline double cs_hht_inertia_slope(double m, double h) {
    return m / (CS_HHT_BETA * h * h * (1.0 + CS_HHT_ALPHA));
}
/* The material damping of a post's elastic turn, as fractions of critical (post.c): welded steel
 * at working stress and sand at a cyclic shear strain of 1e-4 (0.01%), the least of each
 * (docs/assumptions.md).
 * A post's spring is its bend and its footing's turn in the soil in series; it takes each one's ratio by
 * its share of the compliance (the share of the strain energy each holds). */
#define CS_STEEL_DAMPING_RATIO 0.02
#define CS_SOIL_DAMPING_RATIO 0.05

/* ---- post sections (section.c) ---- */
/* Why a filled section cannot be taken by the plastic stress distribution (no tube geometry, a fill
 * strength outside 3-10 ksi, walls not compact), written into why (size n) and returned; NULL if it can
 * or is hollow. */
const char *cs_section_fill_problem(const cs_section_def *section, char *why, size_t n);
/* A section's shear capacity, N: 0.6 Aw Fy (AISC), past which a post shears off at its base (post.c). */
double cs_section_shear_capacity(const cs_section_def *section);

/* ---- rope law (rope.c) ---- */
/* A rope's law from its definition (EA, Fu, the end of the elastic slope T1 and its strain, the second slope,
 * the strains at Fu and at the break) and its weight per length under gravity g. */
void cs_rope_derive(const cs_rope_def *d, double g, cs_rope *r);
double cs_rope_tension(const cs_rope *rope, double strain, double plastic_strain);
double cs_rope_elastic_energy(const cs_rope *rope, double tension, double material);

/* ---- cable paths (cable.c) ---- */
double cs_span_length(const cs_cable_state *cs, int span);
/* A span's chord d = p_{span+1} - p_span and its length in d[3]. The functions below that take `chords`
 * (a cable's, 4 doubles a span as here; the solver keeps them from its last placement) form them from
 * the node positions where it is NULL. */
void cs_span_chord(const cs_cable_state *cs, int span, double *d);
double cs_span_tension(const cs_cable_model *cm, const cs_cable_state *cs, int span);
/* The same, with the span's chord put into d. */
double cs_span_tension_chord(const cs_cable_model *cm, const cs_cable_state *cs, int span, double *d);
/* A span's tension with its gradient, for the solver's Jacobian: along the chord d = p_{i+1} - p_i and
 * with the material coordinates of its ends (m_i, m_{i+1}); its length and unit chord. */
typedef struct cs_span_grad {
    double t, l, u[3], dt_dd[3], dt_dm[2];
} cs_span_grad;
void cs_span_tension_grad(const cs_cable_model *cm, const cs_cable_state *cs, int span, const double *chord,
                          cs_span_grad *g);
double cs_span_material_at(const cs_cable_model *cm, const cs_cable_state *cs, int span, double t);
/* The rope law of a span (rope.c): its tension with `material` of rope at plastic strain ep over a chord of
 * `length`, sagging (sag term q = cs_span_sag); *arc (unless NULL) gets the arc's strain and *yields
 * whether the backbone capped the tension. */
double cs_span_tension_law(const cs_rope *rope, double length, double material, double ep, double q,
                           double *arc, int *yields);
double cs_span_tension_at(const cs_rope *rope, double length, double material, double ep, double q);
double cs_span_sag(const cs_rope *rope, const double *chord);
/* Plastic strain of span i with its ends at material coordinates lo and hi (the rope that slid in brings
 * its own). */
double cs_span_plastic(const cs_cable_state *cs, int span, double lo, double hi);
/* The same from given committed strains of the span (own) and its neighbours (left, right). */
double cs_span_plastic_of(const cs_cable_state *cs, int span, double lo, double hi, double left, double own,
                          double right);
/* Every span's tension, and its chord into chords if not NULL. */
void cs_cable_update_tensions(const cs_cable_model *cm, cs_cable_state *cs, double *chords);
/* Span i's tension from its ends as they stand (the chord into chord unless NULL). With
 * cs_cable_update_tensions it is where the solve sets a span's tension; the commit (cs_cable_commit)
 * sets it from the same law at the committed ends, and the installer's hold (cs_cable_hold_tension)
 * and a release (cs_cable_release) set it outright. */
void cs_cable_update_span(const cs_cable_model *cm, cs_cable_state *cs, int span, double *chord);
/* Every span at tension t whatever its stretch (the rope as an installer pulls it, before it is laid in). */
void cs_cable_hold_tension(cs_cable_state *cs, double t);
/* Index of node id on the cable's path, -1 if it is not on it. */
int cs_cable_find_node(const cs_cable_state *cs, int id);
/* mu theta at interior node i, theta the path's turning angle there; the ratio is its exponential. */
double cs_node_capstan_exponent(const cs_model *model, const cs_cable_model *cm, const cs_cable_state *cs,
                                int i, const double *chords);
/* tanh(mu theta / 2) at interior node i: the friction band's half-width over T_L + T_R. */
double cs_node_band_fraction(const cs_model *model, const cs_cable_model *cm, const cs_cable_state *cs, int i,
                             const double *chords);
void cs_cable_insert_node(cs_cable_state *cs, int at, int id, const double *p);
void cs_cable_remove_node(cs_cable_state *cs, int at);
void cs_cable_commit(const cs_model *model, int c, cs_state *s);
int cs_cable_check_break(const cs_model *model, int c, cs_state *s);

/* ---- a rope's end fittings (termination.c) ---- */
/* The larger of the end spans' tensions over their fittings' strengths; its end (0 start, 1 end) in *end. */
double cs_termination_load(const cs_cable_model *cm, const cs_cable_state *cs, int *end);
/* Whether the rope can slip through the fitting at `end` now: it has a slip load and is not yet run out. */
int cs_termination_slips(const cs_cable_model *cm, const cs_cable_state *cs, int end);
/* An end whose rope has slipped through its fitting by the slip travel, or -1. */
int cs_termination_run_out(const cs_cable_model *cm, const cs_cable_state *cs);
/* At the commit, before m_commit takes m: the rope let through each end's fitting, its friction work and
 * the slip's start (termination_slip). */
void cs_termination_commit(const cs_model *model, int c, cs_state *s);
/* The rope's end brought within its diameter of the hole of the post next to its anchor: that post leaves the
 * rope's path (termination_at_post). Returns 1 if any did. */
int cs_termination_check_post(const cs_model *model, int c, cs_state *s);
/* The cable carries nothing from now on (broken, or released by its anchor). */
void cs_cable_release(cs_cable_state *cs, cs_cable_status status);
/* The rope's stored energy: its elastic energy less its sag's weight below the chords; of span i, and of
 * the whole cable (0 unless intact). */
double cs_span_stored_energy(const cs_cable_model *cm, const cs_cable_state *cs, int i);
double cs_cable_stored_energy(const cs_cable_model *cm, const cs_cable_state *cs);
void cs_node_force(const cs_cable_state *cs, int i, const double *chords, double *f);

/* ---- a post's axis (post_axis.c): geometry only ---- */
/* sin t / t, its derivative over t and cos t at t = |alpha|. */
void cs_post_axis_terms(double t, double *s, double *g, double *c);
/* The point at height z (when upright) of post p at a tilt, slid out of the ground by `pull`, straight up
 * if `upright` (cs_post_upright), else along its axis: from cs_post_axis_terms' s and c, or found. */
void cs_post_attachment_from(const cs_model *model, int post, const double *tilt, double pull, int upright,
                             double s, double c, double z, double *out);
void cs_post_attachment(const cs_model *model, int post, const double *tilt, double pull, int upright,
                        double z, double *out);
/* The axis' Jacobian da/dalpha (3 x 2, row-major): from s and g, at a tilt, and with its derivatives along
 * the two tilts (dj, 2 x 6: the solver's linearisation of a post's moment). */
void cs_post_axis_jacobian_from(const double *tilt, double s, double g, double *j);
void cs_post_axis_jacobian_at(const double *tilt, double *j);
/* The unit axis a(alpha) at a tilt. */
void cs_post_axis_at(const double *tilt, double *a);
void cs_post_axis_jacobian(const double *tilt, double *j, double *dj);

/* ---- posts and footings (post.c, footing.c) ---- */
/* Post p's model from the barrier's definition, its cables' mean height load_height and the model's
 * cables (derived before it): which of the post (Zx Fy) and its footing (Eq. 21 times the dynamic factor
 * at that height) yields, the pivot and moment capacity that follow, its spring and damper, shear and
 * pullout capacities, retainers, and its inertia and mass with its rails' share. */
void cs_post_derive(const cs_barrier_def *b, int p, double load_height, const cs_model *m, cs_post_model *pm);
/* Still in the barrier: standing, or down on the ground with its ropes; not ridden over, sheared or pulled
 * out. */
static inline int cs_post_in_barrier(const cs_post_state *ps) {
    return ps->status == CS_POST_ELASTIC || ps->status == CS_POST_HINGED || ps->status == CS_POST_SOIL ||
           ps->status == CS_POST_DOWN;
}
/* Whether post p slides out of its footing straight up: hinged at grade (its steel yields before its
 * footing turns: !soil_yields), the stub in the footing stays vertical and carries the bent post up with
 * it, also once its footing's moment, falling as it comes out, is the weaker, and also once the vehicle
 * strikes it (the edge's pull on the stub, its friction's less its normal force's, is left out: at most
 * mu M_p / z, under a third of the examples' pullout capacities, docs/theory.md). A post whose soil
 * yields first turns with its footing and slides along its leaned axis, struck or not (post_pullout.c;
 * docs/theory.md, "A hinged post's stub stays upright"). */
static inline int cs_post_upright(const cs_post_model *pm) {
    return !pm->soil_yields;
}
/* The arm of post p's point at height z from its pivot along its axis: z + pivot depth, and its pull if
 * it slides out along its axis (a post sliding upright carries its pivot up with it). */
static inline double cs_post_arm(const cs_model *model, const cs_state *s, int p, double z) {
    return z + model->posts[p].pivot + (cs_post_upright(&model->posts[p]) ? 0.0 : s->posts[p].pull);
}
/* The unit direction post p slides out of its footing along at a tilt: up, or its axis a(alpha). */
void cs_post_slide_direction(const cs_model *model, int p, const double *tilt, double *d);
/* Cable c's height on post p: as built, plus its slot's ride up the slot (attachment.c). */
static inline double cs_post_cable_z(const cs_model *model, const cs_state *s, int p, int c) {
    return model->cables[c].z + (model->posts[p].attach == CS_ATTACH_SLOT ? s->posts[p].lift : 0.0);
}
double cs_footing_capacity(const cs_footing_def *f, double load_height);
double cs_footing_impact_capacity(const cs_footing_def *f, double load_height);
/* The passive wedge's three-dimensional factor R(b/D) of a member of width b and depth D (footing.c), and
 * the dynamic factor of a footing: f_d R(B/D) / R of the bogie tests' post. */
double cs_footing_wedge_factor(double friction_angle, double width, double depth);
/* The soil's resistance at large movement over its peak (critical state over peak friction angle). */
double cs_footing_residual_ratio(const cs_footing_def *f);
/* The soil that moves with a footing pushed through it, as a mass at the footing's speed, kg. */
double cs_footing_wedge_mass(const cs_footing_def *f);
double cs_footing_dynamic_factor(const cs_footing_def *f);
double cs_footing_pullout_capacity(const cs_footing_def *f);
/* A shaft's friction as it slides out of the soil, with x0 of its depth in the ground (footing.c). */
double cs_shaft_return_map(double q0, double kd, double x0, double n, double *x, double *slope);
/* Eq. 21's capacity with only x of the depth in the ground, over the whole depth's (footing.c). */
double cs_footing_remaining_share(double coeff_depth, double coeff_height, double depth, double height,
                                  double x);
/* Movement that mobilises the soil's passive resistance, over the member's depth (Clough and Duncan
 * 1991: about 1% of the height in dense sand, 2% medium, 4% loose): a dead-man's slide, a footing's
 * movement at grade as it turns about its pivot 2D/3 down. */
#define CS_PASSIVE_MOBILISATION 0.02
/* The footing's elastic rotational stiffness about its pivot 2D/3 below grade, N m/rad: its impact
 * capacity at the load height, moment (h + 2D/3) F P(h), reached as grade moves by the mobilisation
 * movement, a turn of 1.5 CS_PASSIVE_MOBILISATION; HUGE_VAL for a rigid footing (no width or depth). */
double cs_footing_rotational_stiffness(const cs_footing_def *f, double load_height);
/* Each intact cable's node at post p where a tilt puts it (one sine and cosine for all), and the post
 * axis' Jacobian there (as cs_post_axis_jacobian's j) into axis if not NULL. */
void cs_post_place_nodes(const cs_model *model, cs_state *s, int post, const double *tilt, double *axis);
void cs_post_commit(const cs_model *model, cs_state *s, int post);
/* Elastic plus kinetic. */
double cs_post_stored_energy(const cs_model *model, const cs_state *s, int post);
double cs_post_elastic_energy(const cs_model *model, const cs_state *s, int post);
double cs_post_kinetic_energy(const cs_model *model, const cs_state *s, int post);
int cs_post_solved(const cs_model *model, const cs_state *s, int post);
int cs_post_check_failure(const cs_model *model, cs_state *s, int post);
/* How far a standing post folds: a post carrying ropes until its top reaches grade (cs_post_lie_angle),
 * where the ground stops it; a struck post until the vehicle's edge rides over it: hinged at grade, its
 * top down to the edge (or its own rotation limit, if less), turning in the soil, its footing's rotation
 * limit; rad. */
double cs_post_fold_limit(const cs_post_model *pm, const cs_post_state *ps);
/* The tilt at which its top reaches grade: acos(pivot / (height + pivot)) as built (lie_angle), and for a
 * post slid upright by w, its pivot w higher, acos((pivot - w) / (height + pivot)), past 90 degrees; w that
 * of the last commit, so that the ground's stop holds still over a step (as a sliding post's capacity). */
double cs_post_lie_angle(const cs_post_model *pm, const cs_post_state *ps);
/* The residual at a tilt, the post's cable nodes where they stand (the caller places them; chords, axis
 * and rails as formed by the placement, or NULL: found here). */
void cs_post_residual_at(const cs_model *model, const cs_state *s, int post, const double *tilt,
                         const double *chords, const double *axis, const double *rails, double *r);
/* Whether a post of this model swings over a time h since the last commit (it has mass, h in (0, inf)). */
int cs_post_swings(const cs_post_model *pm, double h);
void cs_post_resistance(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double *q);
/* Posts struck by the vehicle: placed for a crush (the sum of the face's pushes returned), and their
 * resistance on the vehicle as placed (face_only: of those the face pushes), added to force and moment. */
double cs_post_place_captured(const cs_model *model, cs_state *s, double crush);
void cs_post_captured_force(const cs_model *model, const cs_state *s, double crush, int face_only,
                            double *force, double *moment);
int cs_post_capture(const cs_model *model, cs_state *s, int waiting);
/* The posts struck at this step's pose before its solve (waiting) push from here on; 1 if there were. */
int cs_post_end_waiting(const cs_model *model, cs_state *s);

/* ---- a post sliding out of its footing (post_pullout.c) ---- */
#define CS_SHAFT_MOBILISATION (0.1 * CS_IN) /* slip that mobilises a shaft's friction in sand, m */
/* The pull along its axis that the length of it still in the ground holds, N. */
double cs_post_pull_cap(const cs_post_model *pm, const cs_post_state *ps);
double cs_post_moment_cap(const cs_post_model *pm, const cs_post_state *ps);
/* The ropes' and rails' pull on post p along the direction it slides out (up, or its axis) as placed, N. */
double cs_post_axial_pull(const cs_model *model, const cs_state *s, int p);
/* The balance of post p's pull as placed: the ropes' and rails' pull out of it less the shaft's resistance
 * and the slide's inertial force over the time since the last commit (the pull's row, in N). */
double cs_post_pull_balance(const cs_model *model, const cs_state *s, int p);
/* A post whose pull has reached its capacity starts to slide out: returns 1 if it started. */
int cs_post_pull_start(const cs_model *model, cs_state *s, int p);
/* End of step: the slide's plastic work (soil) and the post out of the ground at its embedment. */
void cs_post_pull_commit(const cs_model *model, cs_state *s, int p);
/* The energy its shaft's slip stores, counted from where the slide started; the kinetic energy of the slide.
 */
double cs_post_pull_energy(const cs_model *model, const cs_state *s, int p);
double cs_post_pull_kinetic_energy(const cs_model *model, const cs_state *s, int p);
/* A struck post dragged out by the edge that pushes it: rigid-plastic, its slide w all plastic. Set its
 * slide; the shaft's capacity at a slide, N; start the slide; take over a slide its ropes started (before
 * it is captured); book the slide's work at the end of a step. */
void cs_post_struck_slide_set(const cs_post_model *pm, cs_post_state *ps, double w);
double cs_post_struck_slide_cap(const cs_post_model *pm, double w);
void cs_post_struck_slide_start(const cs_model *model, cs_state *s, int p);
void cs_post_struck_slide_take(const cs_model *model, cs_state *s, int p);
void cs_post_struck_slide_commit(const cs_model *model, cs_state *s, int p);

/* ---- attachments (attachment.c) ---- */
/* Ride post p's slotted cables up their slot until friction holds them or the highest reaches the open
 * end, booking the ropes' stored energy spent on the way as friction; returns 1 if they moved by more
 * than CS_RIDE_MOVED (a micron), which the barrier's solve must then settle around. */
int cs_attachment_ride(const cs_model *model, cs_state *s, int p);
/* Let go of the cables post p's slot or hooks no longer hold; returns 1 if any went. */
int cs_attachment_check_release(const cs_model *model, cs_state *s, int p);

/* ---- vehicle (vehicle.c) ---- */
/* The vehicle's model from its definition under gravity g: the tyres' contact points, springs (each
 * carrying its share of the axle load at its static deflection) and dampers, the inverse inertias. */
void cs_vehicle_derive(const cs_vehicle_def *v, double g, cs_vehicle_model *vm);
void cs_vehicle_face_point(const cs_model *model, const cs_state *s, double crush, double y_body,
                           double z_body, double *world);
/* Corner k (CS_CORNERS: the outline's four and the four wheels) at body height z_body, in the world (the
 * front ones crush back), and the body-z band it meets cables over (the face's, the side's, a rear wheel's
 * from the ground to the side's top, or a front wheel's from its axle's height at rest to the side's top). */
void cs_vehicle_corner_point(const cs_model *model, const cs_state *s, double crush, int k, double z_body,
                             double *world);
void cs_vehicle_corner_band(const cs_model *model, int k, double *lo, double *hi);
void cs_vehicle_start(const cs_model *model, cs_state *s); /* accelerations at t = 0 */
void cs_vehicle_integrate(cs_state *s, double h);
void cs_vehicle_finish(const cs_model *model, cs_state *s, double h);
/* The barrier's push changed at an instant (a failure at the step's end) from old to s->force, s->moment:
 * the accelerations the next step starts from take the new push. */
void cs_vehicle_push_changed(const cs_model *model, cs_state *s, const double *old_force,
                             const double *old_moment);
double cs_crush_force(const cs_vehicle_def *v, double crush, double crush_max);
double cs_crush_curve(const cs_vehicle_def *v, double crush);
double cs_crush_permanent(const cs_vehicle_def *v, double crush_max);
double cs_vehicle_kinetic_energy(const cs_model *model, const cs_state *s);
double cs_vehicle_potential_energy(const cs_model *model, const cs_state *s);

/* ---- contact (contact.c) ---- */
void cs_contact_update(const cs_model *model, cs_state *s);
void cs_contact_place_corners(const cs_model *model, cs_state *s, double crush);
void cs_contact_drop_failed(const cs_model *model, cs_state *s);
/* The band of a face contact's Coulomb friction for a pull fn into the body: mu fn, held up to the
 * friction floor where the rope pulls little into it; its slope in fn into *slope if not NULL. */
double cs_contact_band(const cs_model *model, int c, double fn, double *slope);
void cs_contact_face_force(const cs_model *model, const cs_state *s, int c, int i, const double *chords,
                           double *fz, double *fn);
/* Put the contact of corner k (node i of cable c) at body height z on the face. */
void cs_contact_place_one(const cs_model *model, cs_state *s, int c, int i, int k, double z);
/* Whether anything pushes on the face, and its normal force at the state as placed (chords: every
 * cable's, max_nodes spans each, or NULL). */
int cs_face_loaded(const cs_model *model, const cs_state *s);
double cs_face_normal_force(const cs_model *model, const cs_state *s, const double *chords);
void cs_contact_commit(const cs_model *model, cs_state *s);
int cs_contact_check_slip(const cs_model *model, cs_state *s);

/* ---- rails (rail.c) ---- */
/* A rail's model from its definition: its stiffness, its yield force A Fy, and its buckling load, the
 * Euler load pi^2 E I / L^2 over the barrier's shortest span `shortest` (HUGE_VAL: none), capped at A Fy. */
void cs_rail_derive(const cs_rail_def *d, double shortest, cs_rail_model *rm);
/* Add the rails' generalised moment on post p at a tilt (its neighbours where they stand; axis: the axis'
 * Jacobian at that tilt) to q. */
void cs_rail_moment(const cs_model *model, const cs_state *s, int p, const double *tilt, const double *axis,
                    double *q);
/* Every post's share of the same with the posts as placed (axes: 18 per post, as the solver keeps them),
 * each span computed once: rails[4 (rail_count p + r) + 2 side + e], side 0 the span ending at p, 1 the
 * span starting there (0 where it does not act); added in that order they make cs_rail_moment's sum. */
void cs_rail_moments(const cs_model *model, const cs_state *s, const double *axes, double *rails);
void cs_rail_commit(const cs_model *model, cs_state *s);
/* The rails' pull on post p along its unit axis a, N. */
double cs_rail_pull(const cs_model *model, const cs_state *s, int p, const double *a);
/* The neighbours post p is tied to by rails now (-1: none); returns whether it has any. */
int cs_rail_ties(const cs_model *model, const cs_state *s, int p, int *left, int *right);

/* ---- anchors (anchor.c) ---- */
void cs_anchor_derive(const cs_anchor_def *d, double gravity, cs_anchor_model *am);
/* Whether anchor a is an unknown of the barrier solve now (it has a footing, holds, and can move). */
int cs_anchor_active(const cs_model *model, const cs_state *s, int a);
/* Every intact rope's end on anchor a where its displacement puts it. */
void cs_anchor_place_nodes(const cs_model *model, cs_state *s, int a);
/* The barrier as installed: each anchor deflected elastically by the ropes' held tensions. */
void cs_anchor_settle(const cs_model *model, cs_state *s);
/* r = the ropes' horizontal pull - the soil's resistance - the inertial force, N (chords as cs_node_force).
 */
void cs_anchor_residual(const cs_model *model, const cs_state *s, int a, const double *chords, double *r);
void cs_anchor_commit(const cs_model *model, cs_state *s);
int cs_anchor_check(const cs_model *model, cs_state *s);
/* What an anchor's face holds as it rises, over what it held in place (anchor.c). */
double cs_anchor_face_share(const cs_anchor_model *am, const cs_anchor_state *as);
/* The balance of anchor a's rise as it stands: the ropes' uplift (their spans' chords from the solve's
 * rows if given) less its weight, its skin's hold and the rise's inertial force, N (anchor.c). */
double cs_anchor_lift_balance(const cs_model *model, const cs_state *s, int a, const double *chords);
/* The cap on an anchor's resistance after a plastic slide s (m): its peak falling to its residual, N. */
double cs_anchor_cap(const cs_anchor_model *am, double s);
/* What anchor a holds: its soil spring's elastic energy, and once it rises the weight lifted and its
 * skin's slip; its kinetic energy (its slide's and its rise's) into *kinetic. */
double cs_anchor_stored_energy(const cs_model *model, const cs_state *s, int a, double *kinetic);

/* ---- the energy ledger (energy.c) ---- */
void cs_energy_update(const cs_model *model, cs_state *s);
double cs_energy_total(const cs_energy *e);
double cs_energy_scale(const cs_model *model, const cs_state *s);

#endif
