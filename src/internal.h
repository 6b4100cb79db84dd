/* SPDX-License-Identifier: MIT */
/* Engine internals shared by the physics files: the model (derived, immutable) and the state.
 * One file per physics area works on these: vehicle.c, rope.c, cable.c, support.c, post.c, footing.c,
 * anchor.c, contact.c; barrier.c and system.c (the quasi-static solve that couples them, with rows.h,
 * newton.c and band.c below it and relax.c its fallback), step.c, energy.c, events.c. */
#ifndef CS_INTERNAL_H
#define CS_INTERNAL_H

#include "cablesim/cablesim.h"

/* Node ids on a cable's path: posts are 0..post_count-1, the rest are negative. */
enum { CS_MAX_CABLES_PER_POST = 64 }; /* = the model's cable limit */
enum { CS_PATH_LEVELS = 2 };          /* how many times a step may be cut into pieces (step.c) */
enum { CS_NODE_START = -1, CS_NODE_END = -2, CS_NODE_CORNER = -3 };

/* The vehicle's plan outline: four corners, k = 0 front left, 1 front right, 2 rear left, 3 rear right
 * (the front ones on the crushable face). A cable wrapped on corner k has node id CS_NODE_CORNER - k. */
enum { CS_CORNERS = 4 };
enum { CS_PUSH_FACE = 0, CS_PUSH_LEFT = 1, CS_PUSH_RIGHT = 2 }; /* the edge a struck post is pushed by */
static inline int cs_node_is_corner(int id) {
    return id <= CS_NODE_CORNER && id > CS_NODE_CORNER - CS_CORNERS;
}
static inline int cs_node_corner(int id) {
    return CS_NODE_CORNER - id;
}
static inline int cs_corner_node(int k) {
    return CS_NODE_CORNER - k;
}
static inline int cs_corner_front(int k) {
    return k < 2;
}

typedef struct cs_rope {
    double ea;      /* axial stiffness E A, N */
    double fu;      /* nominal strength, N */
    double t1;      /* end of the first slope, N */
    double e1;      /* strain there */
    double k2;      /* second slope, N per unit strain */
    double e2;      /* strain at Fu */
    double e_break; /* breaking strain */
    double w;       /* weight per length, N/m (the span's sag) */
} cs_rope;

/* The width, as a fraction of the rope's strength Fu, over which the solver rounds the stick/slip switch
 * of supports and face contacts; also the least force friction holds on the face before a contact
 * slides, however small the rope's pull (docs/assumptions.md). Without that floor a contact of a slack
 * rope has no friction and drifts, within the solver's tolerance, a little every step. At a support the
 * width is a pre-sliding slip of w / c (c = EA / (l_L + l_R)): ~50 um on APS3's 1.75-in rope over 8-ft
 * spans. A sharper switch (1e-4) costs the crash tests 10-12% more instructions for changes of 1.6% or
 * less in their results. */
#define CS_FRICTION_FLOOR 1e-3

/* Barrier solves a run may make per step to t_end on average, by default: a step takes about one (1.01 to
 * 1.04 over the crash tests), a step cut into its finest pieces some 70; a run that needs 20 a step over
 * its whole length is not following its path (docs/robustness.md). */
#define CS_SOLVE_BUDGET 20.0

typedef struct cs_cable_model {
    double z;          /* height at the posts, m */
    double pretension; /* N */
    double mu_post;
    double termination_strength[2]; /* tension at which each end's fitting lets go (0 start, 1 end), N */
    double slip_load[2];            /* end span tension at which the rope slips through each end's fitting,
                                       N (0: it does not slip) */
    double slip_travel[2];          /* rope each lets slip before the rope runs out of it, m */
    cs_rope rope;
} cs_cable_model;

typedef struct cs_post_model {
    double x, height;
    double k_rot;          /* elastic rotational stiffness about the base, 3 E I / h_ref, N m/rad */
    double mp;             /* plastic moment Zx Fy, N m */
    double footing_moment; /* impact capacity (Eq. 21 x dynamic factor) times its load height, N m */
    double moment_cap;     /* mp, or if the footing is weaker its capacity at the lever h + pivot, N m */
    double moment_scale;   /* the barrier solve's unit of moment for this post's balance, N m (model.c) */
    int soil_yields;       /* 1 if the footing is weaker than the post */
    double shear_cap;      /* 0.6 Aw Fy, N */
    double pullout_cap;    /* N */
    double embedment;      /* the length of it in the ground that its pullout capacity holds, m */
    double pull_stiffness; /* its pull along its axis over the slip that mobilises it, N/m (post_pullout.c) */
    double pull_mass;      /* what slides out with it along its axis: its steel and half its rail spans, kg */
    double rot_limit;      /* rad: a struck post's, past which the vehicle's edge rides over it */
    double lie_angle;      /* rad: the tilt at which its top reaches grade, acos(pivot / (height + pivot)) */
    double load_height;    /* mean cable height on the post, m */
    double pivot;          /* depth of the point it turns about: 2/3 D if the soil yields, else 0, m */
    int clamped;
    cs_attachment attach;
    double release_force; /* a slot's or hook's retainer along the post, N */
    double inertia;       /* rotational inertia of the post about its pivot, kg m^2 (0: massless) */
    cs_footing_def footing;
} cs_post_model;

/* A rail as derived from its definition (rail.c). */
typedef struct cs_rail_model {
    double z;             /* m */
    double ea;            /* N */
    double yield_force;   /* A Fy, N */
    double buckling_load; /* over the spans, the shortest's Euler load pi^2 E I / L^2 capped at A Fy, N */
} cs_rail_model;

/* An anchor as derived from its definition (anchor.c). */
typedef struct cs_anchor_model {
    double x, z;
    int rigid;              /* no footing: it never moves */
    double capacity;        /* peak horizontal resistance of its footing at the ropes' height, N */
    double residual;        /* what the soil keeps while it ploughs on past the peak, N */
    double softening;       /* plastic slide over which the resistance falls from the peak to it, m */
    double stiffness;       /* N/m, up to the peak */
    double mass;            /* kg */
    double uplift_capacity; /* N: the ropes' upward pull that lifts it out of the soil */
} cs_anchor_model;

typedef struct cs_vehicle_model {
    cs_vehicle_def def;
    double wheel[4][3]; /* body-frame tyre contact points at rest (FL, FR, RL, RR) */
    double tyre_k[4];   /* N/m */
    double tyre_c[4];   /* N s/m */
    double inv_inertia[3];
} cs_vehicle_model;

struct cs_model {
    int cable_count, post_count, max_nodes, rail_count;
    cs_rail_model *rails;
    cs_cable_model *cables;
    cs_post_model *posts;
    cs_anchor_model anchors[2];
    cs_vehicle_model vehicle;
    cs_scenario_def scenario;
    double dir[3];       /* initial travel direction, unit */
    double start_pos[3]; /* CG at t = 0 */
    double start_yaw;
    int window_steps;    /* steps in the 50-ms average */
    int loss_steps;      /* samples of the sudden-loss check's ring: every step within its window */
    double solve_budget; /* barrier solves the run may make in all (scenario.solve_budget per step) */
    double max_steps;    /* steps the run may take (scenario.max_steps, or CS_MAX_STEPS_DEFAULT) */
    int event_capacity;
};

/* A cable's current path: node ids in order from the start anchor to the end anchor, the material
 * coordinate m of each node (unstretched length from the start anchor), the plastic strain of each
 * span, and cached geometry and tension of each span. */
typedef struct cs_cable_state {
    cs_cable_status status;
    int engaged;
    int node_count;
    int *node;                          /* [max_nodes] */
    int *where;                         /* [post_count] index of each post in node[], -1 if not on the path */
    double *m;                          /* [max_nodes] material coordinate, m */
    double *m_commit;                   /* [max_nodes] at the end of the previous step */
    double *ep;                         /* [max_nodes - 1] plastic strain of each span (committed) */
    double *tension;                    /* [max_nodes - 1] N */
    double *pos;                        /* [max_nodes * 3] node positions, m */
    double corner_z[CS_CORNERS];        /* body-frame z of the contact at each corner, m */
    double corner_z_commit[CS_CORNERS]; /* the same at the end of the previous step */
    double max_tension_seen;
    double max_tension_time; /* when it was seen (the step's end), s */
    double max_strain;       /* largest span strain at the last commit */
    double end_load; /* the larger of the end spans' tensions over their fittings' strengths, last commit */
    double slip[2];  /* rope slipped out of each end's fitting into its end span (committed), m */
    int slipping[2]; /* each end's fitting has started to slip (its termination_slip given) */
    double push[6];  /* the rope's force on the vehicle and its moment about the CG, at the last
                        cs_barrier_force (world), N and N m */
    double work_on_vehicle; /* the work that force has done on the vehicle (the vehicle's side: a barrier
                               put back to its last commit keeps it, step.c), J */
} cs_cable_state;

typedef struct cs_post_state {
    cs_post_status status;
    double tilt[2];        /* rotation vector: direction and angle the top moves, rad */
    double plastic[2];     /* plastic part of the rotation (committed), rad */
    double moment[2];      /* resisting generalised moment, N m */
    double shear, axial;   /* N */
    int yielded;           /* hinge or soil event already reported */
    int captured;          /* struck by the vehicle: pushed over by it, off the cable paths */
    int pusher;            /* what pushes a captured post: CS_PUSH_FACE, _LEFT or _RIGHT (side) */
    double lever;          /* from the pivot to where the vehicle struck it, along the post, m */
    double reach;          /* the struck point's lean at the strike less the edge's reach there, m */
    double push;           /* force of the vehicle on a captured post, N */
    int bearing;           /* a captured post the vehicle's edge bears on (not backed off) */
    double tilt_commit[2]; /* tilt at the last commit, rad */
    double rate[2];        /* rate of tilt at the last commit, rad/s */
    double net[2];         /* the net generalised moment (cables, rails, less the resistance) then, N m */
    int withdrawing;       /* its pull has reached its pullout capacity: it slides out (post_pullout.c) */
    double pull;           /* how far it has slid out along its axis, m */
    double pull_plastic;   /* the plastic part of that (committed), m */
    double pull_commit;    /* the pull at the last commit, m */
    double pull_rate;      /* its rate then, m/s */
    double pull_net;       /* the net pull (ropes and rails less the shaft) then, N */
} cs_post_state;

typedef struct cs_work cs_work; /* work.h */

/* The sudden-loss check (response.c), fed the magnitude of the barrier's force on the vehicle sample by
 * sample: a ring of the newest samples (every one within the window of the newest), the largest force so
 * far, the newest sample's fall not yet judged (an event of the next sample may excuse it) and the
 * stretches of flagged falls, each by its largest. */
typedef struct cs_loss_scan {
    double *t, *f; /* the ring: s, N */
    int size;      /* its room */
    long fed;      /* samples so far */
    double step;   /* the sample step: an excusing event this close to a window excuses it, s */
    double peak;   /* the largest force so far, N */
    int pending;   /* the newest sample ends a fall (`fall`) not yet judged */
    int open;      /* the last sample judged ended a flagged fall: 1 kept in found[kept - 1], 2 missed */
    cs_sudden_loss fall;
    int kept;   /* stretches in found */
    int missed; /* stretches found once `found` was full */
    cs_sudden_loss found[CS_SUDDEN_LOSS_KEPT];
} cs_loss_scan;

struct cs_state {
    double t;
    double h; /* time since the barrier was last committed: the posts' swing over it (post.c), s */
    long step;
    cs_outcome outcome;
    int frozen;

    /* vehicle */
    double pos[3], vel[3], quat[4], omega[3]; /* omega in the body frame */
    double acc[3], ang_acc[3];  /* linear (world) and angular (body) accelerations at the pose */
    double tyre_power;          /* power the tyres dissipate at the pose, W */
    double force[3], moment[3]; /* barrier resultant on the vehicle (world, about the CG) */
    double crush, crush_max;    /* face set-back now and the largest reached, m */
    double crush_committed, crush_force_committed;
    double face_force; /* N */
    int contact_started;

    int cable_count_alloc;
    cs_cable_state *cables;
    cs_post_state *posts;
    struct cs_anchor_state {
        int failed, yielded;
        double u[2];        /* horizontal displacement, m */
        double plastic[2];  /* its plastic part (committed), m */
        double slide;       /* the plastic slide's length so far (committed), m */
        double u_commit[2]; /* at the last commit, m */
        double rate[2];     /* its rate at the last commit, m/s */
        double acc[2];      /* its acceleration at the last commit, m/s^2 */
        double force[2];    /* the soil's resistance at the last commit, N */
        double net[2];      /* the ropes' pull less that resistance at the last commit, N */
        double uplift;      /* the ropes' upward pull at the last commit, N */
    } anchors[2];

    double *rail_plastic;  /* [rail_count * post_count] each span's plastic change of length, m (rail.c) */
    double e_rail_elastic; /* the rails' elastic energy at the last commit, J (rail.c) */
    /* The rails' points where post.c last placed each post, and the tilt and pull they were placed at: a
     * cache rail.c reads instead of finding them again (the same numbers). Allocated with the workspace,
     * neither copied nor hashed; NULL in a copy that only holds a state. */
    double *rail_pos;  /* [post_count * rail_count * 3] m */
    double *rail_tilt; /* [post_count * 3] rad, rad, m (NaN: none placed yet) */

    /* energy accumulators, J: the barrier's (friction: over supports and on the face) and the tyres' */
    double e_rail_plastic, e_cable_plastic, e_post_plastic, e_post_damping, e_soil, e_crush, e_friction,
        e_released, e_tyre;
    double e_initial_total, e_initial_kinetic;
    double e_initial_potential_ref; /* CG height at t = 0 */
    cs_energy energy;

    /* response */
    double *speed_ring; /* forward speed at the last window_steps steps */
    int ring_fill;
    double decel_50ms_g;
    double *loss_ring; /* the sudden-loss check's ring, 2 loss_steps: times and forces */
    cs_loss_scan loss;
    cs_summary summary;

    cs_event *events;
    int event_count;

    cs_work *work; /* the step's workspace (work.h); NULL in a copy that only holds a state */
};

/* A state's memory and its workspace, not yet set for a run (cs_state_create resets it: cs_state_reset,
 * step.c). NULL with err set if out of memory. */
cs_state *cs_state_allocate(const cs_model *model, cs_error *err);
void cs_state_copy(const cs_model *model, cs_state *dst, const cs_state *src);
void cs_state_restore_barrier(const cs_model *model, cs_state *s, const cs_state *from);

/* ---- rope law (rope.c) ---- */
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
/* The cable carries nothing from now on (broken, released by its anchor, slipped off the face). */
void cs_cable_release(cs_cable_state *cs, cs_cable_status status);
double cs_cable_stored_energy(const cs_cable_model *cm, const cs_cable_state *cs);
void cs_node_force(const cs_cable_state *cs, int i, const double *chords, double *f);

/* ---- a post's axis (post_axis.c): geometry only ---- */
/* sin t / t, its derivative over t and cos t at t = |alpha|. */
void cs_post_axis_terms(double t, double *s, double *g, double *c);
/* The point at height z (when upright) of post p at a tilt, slid out of the ground by `pull` along its
 * axis: from cs_post_axis_terms' s and c, or found. */
void cs_post_attachment_from(const cs_model *model, int post, const double *tilt, double pull, double s,
                             double c, double z, double *out);
void cs_post_attachment(const cs_model *model, int post, const double *tilt, double pull, double z,
                        double *out);
/* The axis' Jacobian da/dalpha (3 x 2, row-major): from s and g, at a tilt, and with its derivatives along
 * the two tilts (dj, 2 x 6: the solver's linearisation of a post's moment). */
void cs_post_axis_jacobian_from(const double *tilt, double s, double g, double *j);
void cs_post_axis_jacobian_at(const double *tilt, double *j);
/* The unit axis a(alpha) at a tilt. */
void cs_post_axis_at(const double *tilt, double *a);
void cs_post_axis_jacobian(const double *tilt, double *j, double *dj);

/* ---- posts and footings (post.c, footing.c) ---- */
/* Still in the barrier: not fallen, sheared or pulled out. */
static inline int cs_post_standing(const cs_post_state *ps) {
    return ps->status == CS_POST_ELASTIC || ps->status == CS_POST_HINGED || ps->status == CS_POST_SOIL;
}
/* The arm of post p's point at height z from its pivot along its axis: z + pivot depth + its pull. */
static inline double cs_post_arm(const cs_model *model, const cs_state *s, int p, double z) {
    return z + model->posts[p].pivot + s->posts[p].pull;
}
double cs_footing_capacity(const cs_footing_def *f, double load_height);
double cs_footing_impact_capacity(const cs_footing_def *f, double load_height);
/* The passive wedge's three-dimensional factor R(b/D) of a member of width b and depth D (footing.c), and
 * the dynamic factor of a footing: f_d R(B/D) / R of the bogie tests' post. */
double cs_footing_wedge_factor(double friction_angle, double width, double depth);
/* The soil's resistance at large movement over its peak (critical state over peak friction angle). */
double cs_footing_residual_ratio(const cs_footing_def *f);
double cs_footing_dynamic_factor(const cs_footing_def *f);
double cs_footing_pullout_capacity(const cs_footing_def *f);
/* Each intact cable's node at post p where a tilt puts it (one sine and cosine for all), and the post
 * axis' Jacobian there (as cs_post_axis_jacobian's j) into axis if not NULL. */
void cs_post_place_nodes(const cs_model *model, cs_state *s, int post, const double *tilt, double *axis);
/* The posts' lean under the ropes' tensions as they stand (held, not following the spans' stretch), at
 * rest: one Newton solve over every standing post's tilt (settle.c). Returns the largest scaled residual
 * left (-1 if the band did not fit). */
double cs_settle_posts(const cs_model *model, cs_state *s);
void cs_post_commit(const cs_model *model, cs_state *s, int post);
/* Elastic plus kinetic. */
double cs_post_stored_energy(const cs_model *model, const cs_state *s, int post);
double cs_post_elastic_energy(const cs_model *model, const cs_state *s, int post);
double cs_post_kinetic_energy(const cs_model *model, const cs_state *s, int post);
int cs_post_held(const cs_model *model, const cs_state *s, int post);
int cs_post_check_failure(const cs_model *model, cs_state *s, int post);
/* How far a standing post folds before it is down: a post carrying ropes until its top reaches grade
 * (lie_angle), a struck post to its rotation limit, where the vehicle's edge rides over it; rad. */
double cs_post_fold_limit(const cs_post_model *pm, const cs_post_state *ps);
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
int cs_post_capture(const cs_model *model, cs_state *s);

/* ---- a post sliding out of its footing (post_pullout.c) ---- */
#define CS_SHAFT_MOBILISATION (0.1 * CS_IN) /* slip that mobilises a shaft's friction in sand, m */
/* The pull along its axis that the length of it still in the ground holds, N. */
double cs_post_pull_cap(const cs_post_model *pm, const cs_post_state *ps);
double cs_post_moment_cap(const cs_post_model *pm, const cs_post_state *ps);
/* The ropes' and rails' pull along post p's axis as placed, N. */
double cs_post_axial_pull(const cs_model *model, const cs_state *s, int p);
/* A post whose pull has reached its capacity starts to slide out: returns 1 if it started. */
int cs_post_pull_start(const cs_model *model, cs_state *s, int p);
/* End of step: the slide's plastic work (soil) and the post out of the ground at its embedment. */
void cs_post_pull_commit(const cs_model *model, cs_state *s, int p);
/* The energy its shaft's slip stores, counted from where the slide started; the kinetic energy of the slide.
 */
double cs_post_pull_energy(const cs_model *model, const cs_state *s, int p);
double cs_post_pull_kinetic_energy(const cs_model *model, const cs_state *s, int p);

/* ---- attachments (attachment.c) ---- */
/* The cosine of the lean at which a cable held at height z reaches the open end of post pm's slot. */
double cs_attachment_slot_open(const cs_post_model *pm, double z);
/* Let go of the cables post p's slot or hooks no longer hold; returns 1 if any went. */
int cs_attachment_check_release(const cs_model *model, cs_state *s, int p);

/* ---- vehicle (vehicle.c) ---- */
void cs_vehicle_face_point(const cs_model *model, const cs_state *s, double crush, double y_body,
                           double z_body, double *world);
/* Corner k of the outline (CS_CORNERS) at body height z_body, in the world (the front ones crush back),
 * and the body-z band it meets cables over (the face's or the side's). */
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

/* ---- barrier solve (barrier.c), and its fallback (relax.c) ---- */
double cs_barrier_solve(const cs_model *model, cs_state *s);
void cs_barrier_force(const cs_model *model, cs_state *s);
void cs_barrier_commit(const cs_model *model, cs_state *s);
/* The stored and dissipated energy the barrier would hold if committed as it stands (on a trial copy in
 * the workspace). */
double cs_barrier_trial_energy(const cs_model *model, const cs_state *s, cs_work *work);
double cs_barrier_stored_energy(const cs_model *model, const cs_state *s);
/* Gauss-Seidel sweeps of the elements' local problems (may_fall: a post with no equilibrium near falls
 * to the next one); the largest relative residual of the last sweep. */
double cs_relax(const cs_model *model, cs_state *s, int sweeps, int may_fall);
/* The fallback's local solve of support i of a cable: the rope slides until the capstan condition holds
 * with its neighbours held; the relative violation found on entry. */
double cs_relax_slide_node(const cs_model *model, const cs_cable_model *cm, cs_cable_state *cs, int i,
                           double tol);
/* The fallback's local problem at each end of cable c that can slip: the largest change it made to an end
 * span's tension, over Fu (0 where the ends already kept the law). */
double cs_relax_ends(const cs_model *model, int c, cs_state *s);
/* The fallback's local solve of post p's tilt (its cables sliding through it) with its neighbours held;
 * the relative residual found on entry. */
double cs_relax_post(const cs_model *model, cs_state *s, int p, double tol, int may_fall);
/* The crush alone in balance with the face's load (the paper's crush correction); the residual on entry. */
double cs_relax_crush(const cs_model *model, cs_state *s);

/* ---- rails (rail.c) ---- */
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
typedef struct cs_anchor_state cs_anchor_state;
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
/* The cap on an anchor's resistance after a plastic slide s (m): its peak falling to its residual, N. */
double cs_anchor_cap(const cs_anchor_model *am, double s);
/* The elastic energy of anchor a's soil spring; its kinetic energy into *kinetic. */
double cs_anchor_stored_energy(const cs_model *model, const cs_state *s, int a, double *kinetic);

/* ---- energy, events, response ---- */
void cs_energy_update(const cs_model *model, cs_state *s);
double cs_energy_total(const cs_energy *e);
double cs_energy_scale(const cs_model *model, const cs_state *s);
/* The event added (its cable_end -1), or NULL if the list is full. */
cs_event *cs_event_add(const cs_model *model, cs_state *s, cs_event_type type, cs_element_kind kind,
                       int element, double value);
void cs_response_update(const cs_model *model, cs_state *s);
/* The sudden-loss check on samples fed one by one (cs_sudden_losses): start with a ring of `size`
 * samples (t and f), feed each with the events up to its time, finish at the end with all of them. */
void cs_loss_scan_start(cs_loss_scan *scan, double *t, double *f, int size, double step);
void cs_loss_scan_feed(cs_loss_scan *scan, double t, double force, const cs_event *events, int event_count);
/* The windows flagged, kept ones in found[0 .. kept), the rest counted in missed: kept + missed. */
int cs_loss_scan_finish(cs_loss_scan *scan, const cs_event *events, int event_count);
/* End the run as "did not converge": its solves have used up the budget. */
void cs_response_give_up(const cs_model *model, cs_state *s, cs_outcome why);

#endif
