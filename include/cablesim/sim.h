/* The model (immutable, built once from definitions), the state (everything that changes), the step
 * and the run, and read-only views of the state for writers and tests. The library never allocates
 * inside cs_step(), never prints, never exits: errors come back as cs_status with a message. */
#ifndef CABLESIM_SIM_H
#define CABLESIM_SIM_H

#include "cablesim/def.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cs_status {
    CS_OK = 0,
    CS_ERR_INVALID = 1, /* a definition is physically impossible or out of range */
    CS_ERR_MEMORY = 2,  /* allocation failed or a size limit was exceeded */
    CS_ERR_UNSTABLE = 3 /* the run went numerically wrong; the message names time and element */
} cs_status;

enum { CS_MESSAGE_SIZE = 256 };

typedef struct cs_error {
    cs_status status;
    char message[CS_MESSAGE_SIZE];
} cs_error;

typedef struct cs_model cs_model;
typedef struct cs_state cs_state;

/* Build the immutable model. Checks every definition; on failure returns NULL and fills err. */
cs_model *cs_model_create(const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                          const cs_scenario_def *scenario, cs_error *err);
void cs_model_free(cs_model *model);

int cs_model_cable_count(const cs_model *model);
int cs_model_post_count(const cs_model *model);
double cs_model_post_x(const cs_model *model, int post);
double cs_model_cable_height(const cs_model *model, int cable);
/* Eq. 21 lateral capacity of a post's footing for a load at height h above grade, N. */
double cs_model_footing_capacity(const cs_model *model, int post, double h);
const cs_vehicle_def *cs_model_vehicle(const cs_model *model);
const cs_scenario_def *cs_model_scenario(const cs_model *model);

/* State: allocated once for a model (all scratch memory included), reset to t = 0 by cs_state_reset. */
cs_state *cs_state_create(const cs_model *model, cs_error *err);
void cs_state_free(cs_state *state);
void cs_state_reset(const cs_model *model, cs_state *state);

/* One time step. Returns CS_OK, or CS_ERR_UNSTABLE with err filled (state is then frozen). */
cs_status cs_step(const cs_model *model, cs_state *state, cs_error *err);

/* Why a run ended. */
typedef enum cs_outcome {
    CS_RUNNING = 0,
    CS_STOPPED,      /* the vehicle's forward speed fell to the stop speed */
    CS_BREAKTHROUGH, /* the vehicle is past the barrier line with no cable holding it */
    CS_TIME_LIMIT,
    CS_REDIRECTED,      /* the vehicle left the barrier on the traffic side, moving away from it */
    CS_OVERRIDE,        /* it rode over every cable it met (none broke) and went past the barrier line */
    CS_UNDERRIDE,       /* it ran under every cable it met (none broke) and went past the barrier line */
    CS_NO_CONTACT,      /* it never touched the barrier before the time limit */
    CS_DID_NOT_CONVERGE /* the barrier's solves took more than the run's budget (scenario.solve_budget) */
} cs_outcome;

/* Whether a run that ended so has an exit speed and angle (it got through or was redirected). */
int cs_outcome_exits(cs_outcome outcome);
/* Whether the vehicle got through the barrier (broke through, rode over or ran under it). */
int cs_outcome_through(cs_outcome outcome);

typedef void (*cs_output_fn)(const cs_model *model, const cs_state *state, void *user);

/* Step until the run ends. on_output (may be NULL) is called at t = 0, every output interval and at
 * the end. Returns CS_OK or the error of the failing step. */
cs_status cs_run(const cs_model *model, cs_state *state, cs_output_fn on_output, void *user, cs_error *err);

/* ---- events ---- */
typedef enum cs_event_type {
    CS_EVENT_CABLE_BREAK = 0,
    CS_EVENT_TERMINATION_BREAK, /* a rope's end fitting lets go at its strength */
    CS_EVENT_POST_HINGE,
    CS_EVENT_POST_ROTATION_LIMIT,
    CS_EVENT_POST_SHEAR,
    CS_EVENT_POST_PULLOUT,
    CS_EVENT_FOOTING_ROTATION,
    CS_EVENT_ANCHOR_PULLOUT,
    CS_EVENT_ANCHOR_YIELD, /* an anchor's footing starts to move through the soil */
    CS_EVENT_OVERRIDE,     /* the vehicle rides over a cable (cable below the front face) */
    CS_EVENT_UNDERRIDE,    /* the vehicle runs under a cable (cable above the front face) */
    CS_EVENT_STOPPED,
    CS_EVENT_BREAKTHROUGH,
    CS_EVENT_REDIRECTED,
    CS_EVENT_CABLE_RELEASE, /* a slot or hook lets a cable go (element: the post; value: the pull along it) */
    CS_EVENT_TYPE_COUNT
} cs_event_type;

typedef enum cs_element_kind {
    CS_ELEMENT_CABLE,
    CS_ELEMENT_POST,
    CS_ELEMENT_ANCHOR,
    CS_ELEMENT_VEHICLE
} cs_element_kind;

typedef struct cs_event {
    double t; /* s */
    cs_event_type type;
    cs_element_kind element_kind;
    int element;  /* index of the cable, post or anchor (0 start, 1 end); 0 for the vehicle */
    double value; /* what triggered it, SI (tension N, rotation rad, shear N, speed m/s) */
} cs_event;

const char *cs_event_type_name(cs_event_type type);     /* "cable_break", "post_hinge", ... */
const char *cs_element_kind_name(cs_element_kind kind); /* "cable", "post", "anchor", "vehicle" */
int cs_state_event_count(const cs_state *state);
const cs_event *cs_state_event(const cs_state *state, int index);

/* ---- views ---- */
typedef struct cs_vehicle_view {
    double t;                   /* s */
    double position[3];         /* CG, m */
    double velocity[3];         /* CG, m/s */
    double acceleration[3];     /* CG, m/s^2 */
    double roll, pitch, yaw;    /* rad (yaw 0 = body x along world x) */
    double angular_velocity[3]; /* body frame, rad/s */
    double forward_speed;       /* along the initial travel direction, m/s */
    double decel_50ms_g;        /* 50-ms moving average of the deceleration along travel, g */
    double crush;               /* permanent-plus-elastic set of the front face, m */
    double face_force;          /* normal force on the front face, N */
    double penetration;         /* furthest point of the front face past the attack face (y), m */
    double barrier_force[3];    /* resultant force of the barrier on the vehicle, N */
    double front_corners[2][3]; /* left and right ends of the front face at mid-face height, m */
    double rear_corners[2][3];  /* left and right rear corners at mid-side height, m */
} cs_vehicle_view;

void cs_state_vehicle(const cs_model *model, const cs_state *state, cs_vehicle_view *out);

typedef enum cs_cable_status {
    CS_CABLE_INTACT = 0,
    CS_CABLE_BROKEN,
    CS_CABLE_RELEASED,
    CS_CABLE_SLIPPED
} cs_cable_status;

typedef struct cs_cable_view {
    cs_cable_status status;
    int engaged;        /* 1 while the vehicle's face pushes it */
    double max_tension; /* largest span tension now, N */
    double max_strain;  /* largest span strain now */
    int node_count;     /* points of the cable's path (anchors, standing posts, face corners) */
} cs_cable_view;

void cs_state_cable(const cs_model *model, const cs_state *state, int cable, cs_cable_view *out);
const char *cs_cable_status_name(cs_cable_status status); /* "intact", "broken", "released", "slipped" */
/* Copy up to capacity path points (x, y, z triplets) and span tensions (node_count - 1 of them). */
int cs_state_cable_path(const cs_model *model, const cs_state *state, int cable, double *xyz, double *tension,
                        int capacity);

typedef enum cs_post_status {
    CS_POST_ELASTIC = 0,
    CS_POST_HINGED, /* plastic hinge at the base, rotating at Mp */
    CS_POST_SOIL,   /* footing rotating in the soil at its capacity */
    CS_POST_FAILED_ROTATION,
    CS_POST_FAILED_SHEAR,
    CS_POST_FAILED_PULLOUT
} cs_post_status;

typedef struct cs_post_view {
    cs_post_status status;
    double tilt;            /* rotation from vertical, rad */
    double tilt_dir[2];     /* horizontal direction the top moves, unit */
    double base_moment;     /* N m */
    double base_shear;      /* N */
    double axial_pull;      /* N, positive pulling the post out */
    double moment_capacity; /* min(Mp, footing), N m */
    double top[3];          /* m */
} cs_post_view;

void cs_state_post(const cs_model *model, const cs_state *state, int post, cs_post_view *out);
const char *cs_post_status_name(cs_post_status status);

typedef struct cs_anchor_view {
    int rigid;              /* no footing: it does not move */
    int yielded, failed;    /* moving through the soil; pulled out */
    double displacement[2]; /* horizontal, m */
    double force[2];        /* the soil's resistance, N */
    double capacity;        /* its footing's horizontal capacity, N */
    double travel_limit;    /* m */
    double uplift;          /* the ropes' upward pull, N */
    double uplift_capacity; /* N */
} cs_anchor_view;

/* anchor: 0 the start (low x), 1 the end. */
void cs_state_anchor(const cs_model *model, const cs_state *state, int anchor, cs_anchor_view *out);
/* "rigid", "holding" (in the soil's elastic range), "sliding" (it has yielded), "pulled_out". */
const char *cs_anchor_status_name(const cs_anchor_view *anchor);

/* Energy ledger, J. Every term is a state function or an accumulated dissipation computed on its own;
 * balance_error = (sum now - sum at t = 0) / initial kinetic energy (for a vehicle starting at rest:
 * / m g h_cg). */
typedef struct cs_energy {
    double vehicle_kinetic;
    double vehicle_potential; /* gravity and tyre springs, relative to t = 0 */
    double cable_elastic;
    double cable_plastic;
    double post_elastic;
    double post_kinetic; /* the posts' swing */
    double post_plastic;
    double post_damping;   /* of the posts' swing and the anchors' slide by their implicit integration */
    double anchor_elastic; /* the soil's elastic spring at the anchors */
    double anchor_kinetic; /* the anchors' slide */
    double rail_elastic;   /* the rails' axial strain energy */
    double rail_plastic;   /* the rails' yielding and buckling */
    double soil;           /* plastic work of footings and anchors moving through the soil */
    double crush;
    double friction; /* tyres, cable sliding over supports */
    double released; /* stored energy lost at sudden failures (massless cable and posts) */
    double initial_total;
    double initial_kinetic;
    double balance_error;
} cs_energy;

void cs_state_energy(const cs_state *state, cs_energy *out);
/* The ledger's terms in the order of cs_energy, vehicle_kinetic to released: a short name of each ("ke",
 * "pe", "cable_elastic", ...) and its value, J. */
enum { CS_ENERGY_TERMS = 16 };
const char *cs_energy_term_name(int term);
double cs_energy_term(const cs_energy *energy, int term);
/* A run's ledger closes when its balance error stays within CS_LEDGER_WARNING of the initial kinetic
 * energy (beyond it the run is flagged); one that goes past CS_LEDGER_FAILURE stops with an error naming
 * the term that moved most in the step (docs/robustness.md). */
#define CS_LEDGER_WARNING 0.01
#define CS_LEDGER_FAILURE 0.05

/* Response parameters, updated every step. */
typedef struct cs_summary {
    cs_outcome outcome;
    double t;                       /* time reached, s */
    double max_decel_50ms_g;        /* g */
    double t_max_decel;             /* s */
    double max_dynamic_penetration; /* m, front face past the attack face */
    double max_barrier_deflection;  /* m, largest y of any cable path point (the dynamic deflection) */
    double working_width; /* m, largest y reached by any part of the vehicle's outline, a cable or a standing
                             post's top: the reach past the barrier's line (y = 0) */
    double stop_time;     /* s, valid if outcome == CS_STOPPED */
    double exit_speed;    /* m/s, valid if cs_outcome_exits(outcome) */
    double exit_angle;    /* rad between the CG's velocity at exit and the barrier's line, positive away
                             from the barrier (to -y); valid with exit_speed */
    double first_contact_time; /* s, < 0 before contact */
    int posts_failed_left;     /* x below the impact point */
    int posts_failed_right;
    /* the same by how they failed, [0] left and [1] right: turned to their rotation limit (bent over, or
     * their footing turned in the soil), sheared at the base, pulled out of the ground */
    int posts_failed_rotation[2], posts_failed_shear[2], posts_failed_pullout[2];
    int cables_broken;
    double initial_kinetic_energy; /* J */
    double energy_balance_error;   /* fraction, largest |error| over the run */
    double max_cable_tension;      /* N over the run */
    double final_position[3];      /* CG, m */
    int solver_warnings;           /* steps whose barrier solve hit its sweep cap */
    double max_solver_residual;    /* largest relative residual left by such a step */
} cs_summary;

void cs_state_summary(const cs_state *state, cs_summary *out);
const char *cs_outcome_name(cs_outcome outcome);

/* FNV-1a hash of the state's numbers, for determinism tests. */
unsigned long long cs_state_hash(const cs_model *model, const cs_state *state);

/* 64-bit FNV-1a of n bytes, continuing from h (start from CS_FNV1A64_BASIS): the hash of cs_state_hash,
 * and of the model a run's outputs record. */
#define CS_FNV1A64_BASIS 1469598103934665603ULL
unsigned long long cs_fnv1a64(unsigned long long h, const void *data, size_t n);

#ifdef __cplusplus
}
#endif
#endif
