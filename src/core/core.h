/* SPDX-License-Identifier: MIT */
/* The engine's bottom layer (src/core): the model (derived from the definitions, immutable) and the state
 * every layer above reads and writes, a cable path's node ids, the state's copies, and the run's events.
 * The layers above: src/elements (each part's physics), src/solver (the barrier's equilibrium), src/run
 * (the model built, the state created, the step); docs/guide.md, "Layout". */
#ifndef CS_CORE_H
#define CS_CORE_H

#include "cablesim/cablesim.h"

enum { CS_MAX_CABLES_PER_POST = 64 }; /* = the model's cable limit */

/* Node ids on a cable's path: posts are 0..post_count-1, the rest are negative. */
enum { CS_NODE_START = -1, CS_NODE_END = -2, CS_NODE_CORNER = -3 };

/* Where the vehicle meets the cables: the plan outline's four corners, k = 0 front left, 1 front right,
 * 2 rear left, 3 rear right (the front ones on the crushable face), the two rear wheels, 4 left and 5
 * right, which take a rope that passes under the rear overhang, and the two front wheels, 6 left and 7
 * right, which take one that passes under the front bumper above their axle (vehicle.c). A cable wrapped
 * on point k has node id CS_NODE_CORNER - k; "corner" below means any of the eight. */
enum { CS_OUTLINE_CORNERS = 4, CS_CORNERS = 8 };
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
static inline int cs_corner_front(int k) { /* a front corner, on the face */
    return k < 2;
}
static inline int cs_corner_wheel(int k) {
    return k >= CS_OUTLINE_CORNERS;
}
static inline int cs_corner_front_wheel(int k) {
    return k >= CS_OUTLINE_CORNERS + 2;
}
static inline int cs_wheel_of(int k) { /* the wheel behind outline corner k, on its side */
    return cs_corner_front(k) ? k + 6 : k + 2;
}
static inline int cs_wheel_corner(int k) { /* the outline corner ahead of (or behind) wheel k */
    return cs_corner_front_wheel(k) ? k - 6 : k - 2;
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
 * spans. A sharper switch (1e-4) costs the crash tests 5-70% more instructions (APS1 13%, APS3 3.3
 * times) for changes of 0.07% or less in their results (docs/assumptions.md, stick-slip rounding). */
#define CS_FRICTION_FLOOR 1e-3

typedef struct cs_cable_model {
    double z;          /* height at the posts, m */
    double pretension; /* N */
    double mu_post;
    double termination_strength[2]; /* tension at which each end's fitting lets go (0 start, 1 end), N */
    double slip_load[2];            /* end span tension at which the rope slips through each end's fitting,
                                       N (0: it does not slip) */
    double slip_travel[2];          /* rope each lets slip before the rope runs out of it, m */
    double hole_strength;           /* tension at which it breaks where it runs through a threaded post's
                                       hole, N (0: no loss there) */
    double diameter;                /* the rope's: given, or its metallic area's as a solid bar, m */
    cs_rope rope;
} cs_cable_model;

typedef struct cs_post_model {
    double x, height;
    double k_rot; /* elastic rotational stiffness about the pivot: the bend and the soil in series, N m/rad */
    double mp;    /* plastic moment Zx Fy, N m */
    double footing_moment; /* impact capacity (Eq. 21 x dynamic factor) times its load height, N m */
    double moment_cap;     /* mp, or if the footing is weaker its capacity at the lever h + pivot, N m */
    double moment_scale;   /* the barrier solve's unit of moment for this post's balance, N m (post.c) */
    int soil_yields;       /* 1 if the footing is weaker than the post */
    double shear_cap;      /* 0.6 Aw Fy, N (section.c) */
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
    double release_force;   /* a retainer's strength along the post (slot, hook, keyway, bracket), N */
    double lateral_release; /* a keyway bolt's or bracket's strength against a pull off its face, N */
    double face_normal; /* y of that face's outward normal while the post stands: -1 attack, +1 protected */
    double inertia;     /* rotational inertia of the post about its pivot, kg m^2 (0: massless) */
    double damping;     /* the viscous damper beside its elastic spring, N m s/rad (post.c) */
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
    double mass;            /* kg: the footing's own, whose weight holds it down */
    double moving_mass;     /* kg: it and the soil's passive wedge moving with it (footing.c) */
    double uplift_capacity; /* N: the ropes' upward pull that starts to lift it out of the soil */
    double uplift_weight;   /* N: its weight's part of that (0 where the capacity is given) */
    double uplift_skin;     /* N: its skin friction's part, over the whole depth (or the capacity given) */
    double depth;           /* m: its footing's depth, the lift that takes it out of the soil */
    double coeff_depth, coeff_height; /* its footing's Eq. 21 coefficients (the capacity as it rises) */
    double drag; /* kg/m: the soil its face sweeps per metre of travel, rho b D (anchor.c) */
} cs_anchor_model;

typedef struct cs_vehicle_model {
    cs_vehicle_def def;
    double wheel[4][3]; /* body-frame tyre contact points at rest (FL, FR, RL, RR) */
    double tyre_k[4];   /* N/m */
    double tyre_c[4];   /* N s/m */
    double rim_travel;  /* m: the compression at which a tyre bottoms on its rim (HUGE_VAL: no rim given) */
    double rim_k[4];    /* N/m: the rim's stop past it (vehicle.c) */
    double rim_c[4];    /* N s/m: its damper, at the tyre's damping ratio */
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
    double work_budget;  /* the solver's work the run may do in all, in rows evaluated (solver/work.h:
                          * solve_budget solves of CS_SOLVE_WORK passes over work_rows rows each) */
    double work_rows;    /* the barrier's unknowns as installed: two tilts a post, a support a post and
                          * rope, two a dead-man, the crush */
    double max_steps;    /* steps the run may take (scenario.max_steps, or CS_MAX_STEPS_DEFAULT) */
    int event_capacity;
};

/* A cable's current path: node ids in order from the start anchor to the end anchor, the material
 * coordinate m of each node (unstretched length from the start anchor), the plastic strain of each
 * span, and cached geometry and tension of each span. */
typedef struct cs_cable_state {
    cs_cable_status status;
    int engaged;
    int passed;   /* the vehicle went over or under it (override, underride): it stays anchored and strung
                     over its posts, out of contact with the vehicle for good (contact.c) */
    int handover; /* bit k: wheel k may take the rope at any depth at the next contact update (a corner
                     hands it to its wheel as it slides down past the face's or the side's bottom) */
    int passing;  /* bit k: corner or wheel k crossed the rope's path with the rope out of its band (a
                     front corner: below it), or a corner let the rope slide down off it to its wheel,
                     and is still across it (contact.c) */
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
    double tilt[2];         /* rotation vector: direction and angle the top moves, rad */
    double plastic[2];      /* plastic part of the rotation (committed), rad */
    double moment[2];       /* resisting generalised moment (spring and damper, at most the capacity), N m */
    double shear, axial;    /* N */
    int yielded;            /* hinge or soil event already reported */
    int captured;           /* struck by the vehicle: pushed over by it, off the cable paths */
    int pusher;             /* what pushes a captured post: CS_PUSH_FACE, _LEFT or _RIGHT (side) */
    double lever;           /* from the pivot to where the vehicle struck it, along the post; for a post
                             * hinged at grade, the edge's height above the hinge now, m */
    double arm, arm_commit; /* the struck point's distance from the pivot, now and at the last commit, m */
    double bend, bend_commit; /* its resistance's moment along the push, now and then, N m */
    double sense;             /* which way the edge slid along it over the last step: +1 up, -1 down */
    double reach;             /* the struck point's lean at the strike less the edge's reach there, m */
    double push;              /* force of the vehicle on a captured post, N */
    double lift;           /* how far its slot's cables have ridden up the slot together, m (attachment.c) */
    int bearing;           /* a captured post the vehicle's edge bears on (not backed off) */
    int passed;            /* the edge that struck it has passed it (committed): free till the next strikes */
    int waiting;           /* struck at a step's new pose, before its solve: pushes from the step's end */
    double tilt_commit[2]; /* tilt at the last commit, rad */
    double rate[2];        /* rate of tilt at the last commit, rad/s */
    double acc[2];         /* its acceleration then, rad/s^2 (the HHT-alpha method's) */
    double net[2];         /* the net generalised moment (cables, rails, less the resistance) then, N m */
    double damper[2];      /* the damper's share of the resistance then, N m (post.c) */
    int withdrawing;       /* its pull has reached its pullout capacity: it slides out (post_pullout.c) */
    double pull;           /* how far it has slid out along its axis, m */
    double pull_plastic;   /* the plastic part of that (committed), m */
    double pull_commit;    /* the pull at the last commit, m */
    double pull_rate;      /* its rate then, m/s */
    double pull_net;       /* the net pull (ropes and rails less the shaft) then, N */
} cs_post_state;

/* The step's workspace (solver/work.h): a state points to it, only the solver and the run open it. */
typedef struct cs_work cs_work;

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
    /* the vehicle left the barrier's contact moving away from it at exit_t, with exit_vel; 0 again if it
     * comes back */
    int exit_pending;
    double exit_t, exit_vel[3];

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
        double force[2];  /* the soil's resistance at the last commit (a rigid anchor: the ropes' pull), N */
        double net[2];    /* the ropes' pull less that resistance and the drag at the last commit, N */
        double uplift;    /* the ropes' upward pull at the last commit, N */
        double peak_pull; /* the ropes' largest horizontal pull at any commit, N (an output, not hashed) */
        double swept;     /* the drag's work so far, J (in the soil's: hashed there) */
        int lifting;      /* the ropes' uplift has reached its capacity: it is rising out of the soil */
        double lift;      /* how far it has risen out of the soil, m (an unknown of the solve) */
        double lift_commit;  /* at the last commit, m */
        double lift_plastic; /* the skin's plastic slip, less the slip that mobilises it, m (committed) */
        double lift_rate;    /* its upward rate at the last commit, m/s */
        double lift_net;     /* the net upward force at the last commit, N */
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

    cs_work *work; /* the step's workspace (solver/work.h); NULL in a copy that only holds a state */
};

typedef struct cs_anchor_state cs_anchor_state;

/* ---- the state's copies (state.c) ---- */
void cs_state_copy(const cs_model *model, cs_state *dst, const cs_state *src);
void cs_state_restore_barrier(const cs_model *model, cs_state *s, const cs_state *from);

/* ---- events (events.c) ---- */
/* The event added (its cable_end -1), or NULL if the list is full. */
cs_event *cs_event_add(const cs_model *model, cs_state *s, cs_event_type type, cs_element_kind kind,
                       int element, double value);

#endif
