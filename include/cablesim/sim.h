/* SPDX-License-Identifier: MIT */
/** @file
 * The model (immutable, built once from definitions), the state (everything that changes), the step
 * and the run, and read-only views of the state for writers and tests. The library never allocates
 * inside cs_step(), never prints, never exits: errors come back as cs_status with a message. */
#ifndef CABLESIM_SIM_H
#define CABLESIM_SIM_H

#include "cablesim/def.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What a call of the engine came to. */
typedef enum cs_status {
    CS_OK = 0,           /**< done */
    CS_ERR_INVALID = 1,  /**< a definition is physically impossible or out of range */
    CS_ERR_MEMORY = 2,   /**< allocation failed or a size limit was exceeded */
    CS_ERR_UNSTABLE = 3, /**< the run went numerically wrong; the message names time and element */
    CS_ERR_IO = 4        /**< a file could not be read or written; the message names it and says why */
} cs_status;

/** The size of cs_error's message. */
enum { CS_MESSAGE_SIZE = 256 };

/** A failure: its status and a sentence saying what failed and where. */
typedef struct cs_error {
    cs_status status;              /**< what kind of failure */
    char message[CS_MESSAGE_SIZE]; /**< the sentence, NUL-terminated */
} cs_error;

/** The immutable model of a barrier, a vehicle and an attack (opaque); threads may share it. */
typedef struct cs_model cs_model;
/** Everything of a run that changes (opaque): the vehicle, the cables, posts and anchors, the events, the
 * energy ledger and the response parameters. */
typedef struct cs_state cs_state;

/** Build the immutable model. Checks every definition.
 * @return the model, or NULL with err filled (CS_ERR_INVALID naming the element, or CS_ERR_MEMORY). */
CS_API cs_model *cs_model_create(const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                                 const cs_scenario_def *scenario, cs_error *err);
/** Free a model. NULL is allowed. */
CS_API void cs_model_free(cs_model *model);

/** The number of cables. */
CS_API int cs_model_cable_count(const cs_model *model);
/** The number of posts. */
CS_API int cs_model_post_count(const cs_model *model);
/** The most points a cable's path can hold (its anchors, every post and every point of the vehicle a
 * cable can wrap): the capacity that cs_state_cable_path never truncates. */
CS_API int cs_model_path_capacity(const cs_model *model);
/** A post's position along the barrier, m. */
CS_API double cs_model_post_x(const cs_model *model, int post);
/** A cable's height at the posts, m. */
CS_API double cs_model_cable_height(const cs_model *model, int cable);
/** Eq. 21 lateral capacity of a post's footing for a load at height h above grade, N. */
CS_API double cs_model_footing_capacity(const cs_model *model, int post, double h);
/** The model's vehicle, as checked: the library's struct, its size the library's. A program that copies it
 * into its own struct copies sizeof its own and sets size to that before it hands the copy back. */
CS_API const cs_vehicle_def *cs_model_vehicle(const cs_model *model);
/** The model's scenario, as checked: the library's struct, read as cs_model_vehicle's. */
CS_API const cs_scenario_def *cs_model_scenario(const cs_model *model);

/** A state for a model, at t = 0, allocated once with all its scratch memory.
 * @return the state, or NULL with err filled. */
CS_API cs_state *cs_state_create(const cs_model *model, cs_error *err);
/** Free a state. NULL is allowed. */
CS_API void cs_state_free(cs_state *state);
/** Put a state back to t = 0, for another run of the same model. */
CS_API void cs_state_reset(const cs_model *model, cs_state *state);

/** One time step. Once the run has ended (cs_state_summary's outcome is no longer CS_RUNNING) a step does
 * nothing and returns CS_OK, and the time stays where the run ended: a loop of steps tests the outcome, not
 * the time alone (or calls cs_run).
 * @return CS_OK, or CS_ERR_UNSTABLE with err filled (the state is then frozen). */
CS_API cs_status cs_step(const cs_model *model, cs_state *state, cs_error *err);

/** Why a run ended. */
typedef enum cs_outcome {
    CS_RUNNING = 0,      /**< it has not ended */
    CS_STOPPED,          /**< the vehicle's forward speed fell to the stop speed */
    CS_BREAKTHROUGH,     /**< the vehicle is past the barrier line with no cable holding it */
    CS_TIME_LIMIT,       /**< the run reached scenario.t_end */
    CS_REDIRECTED,       /**< the vehicle left the barrier on the traffic side, moving away from it */
    CS_OVERRIDE,         /**< it rode over every cable it left behind (none broke before it passed) */
    CS_UNDERRIDE,        /**< it ran under every cable it left behind (none broke before it passed) */
    CS_NO_CONTACT,       /**< it never touched the barrier before the time limit */
    CS_DID_NOT_CONVERGE, /**< the barrier's solves took more than the run's budget, in count or in work
                              (scenario.solve_budget) */
    CS_STEP_LIMIT        /**< the run took scenario.max_steps steps */
} cs_outcome;

/** Whether a run that ended so has an exit speed and angle (it got through or was redirected). */
CS_API int cs_outcome_exits(cs_outcome outcome);
/** Whether the vehicle got through the barrier (broke through, rode over or ran under it). */
CS_API int cs_outcome_through(cs_outcome outcome);
/** Whether a run that ended so has a penetration (the vehicle stopped, was redirected or never touched the
 * barrier), rather than how far it had got with the vehicle through or still going (a lower bound:
 * cs_summary's penetration_beyond_m). */
CS_API int cs_penetration_is_final(cs_outcome outcome);

/** Called by cs_run with the state at each output; user is cs_run's. cs_record_frame is one. */
typedef void (*cs_output_fn)(const cs_model *model, const cs_state *state, void *user);

/** Step until the run ends (an outcome other than CS_RUNNING).
 * @param model the model
 * @param state its state, at t = 0 or where an earlier call left it
 * @param on_output called at t = 0, every scenario.output_interval and at the end (may be NULL)
 * @param user passed to on_output
 * @param err filled on failure
 * @return CS_OK, or the error of the failing step. */
CS_API cs_status cs_run(const cs_model *model, cs_state *state, cs_output_fn on_output, void *user,
                        cs_error *err);

/* ---- events ---- */
/** What happened: a failure, a release or the run's end. */
typedef enum cs_event_type {
    CS_EVENT_CABLE_BREAK = 0,     /**< a rope breaks along a span, or at a threaded post's hole (post: that
                                     post; value: its largest span tension there, N) */
    CS_EVENT_TERMINATION_BREAK,   /**< a rope's end fitting lets go (value: that end span's tension, N;
                                       cable_end: which end) */
    CS_EVENT_POST_HINGE,          /**< a plastic hinge forms at a post's base (value: its capacity, N m) */
    CS_EVENT_POST_ROTATION_LIMIT, /**< a post the vehicle struck turns until the vehicle rides over it (its
                                     top down to the pushing edge, or its rotation limit) and it leaves the
                                     barrier (value: its tilt, rad) */
    CS_EVENT_POST_SHEAR,          /**< a post shears at its base (value: shear, N) */
    CS_EVENT_POST_PULLOUT,        /**< a post is pulled out of the ground (value: pull, N) */
    CS_EVENT_FOOTING_ROTATION,    /**< a post's footing starts to turn in the soil (value: capacity, N m) */
    CS_EVENT_ANCHOR_PULLOUT,      /**< an anchor has risen all the way out of the ground, releasing its ropes
                                       (value: the ropes' uplift then, N) */
    CS_EVENT_ANCHOR_YIELD,        /**< an anchor's footing starts to move through the soil (value: its
                                       capacity, N) */
    CS_EVENT_OVERRIDE,            /**< the vehicle rides over a cable, below its front face (value: t, s) */
    CS_EVENT_UNDERRIDE,           /**< the vehicle runs under a cable, above its front face (value: t, s) */
    CS_EVENT_STOPPED,             /**< the run ends: the vehicle stopped (value: its penetration, m) */
    CS_EVENT_BREAKTHROUGH,        /**< the run ends: the vehicle got through (value: speed, m/s) */
    CS_EVENT_REDIRECTED,          /**< the run ends: the vehicle was redirected (value: speed, m/s) */
    CS_EVENT_CABLE_RELEASE,       /**< a slot, hook, keyway bolt or bracket lets a cable go along the post
                                       (element: the post; value: the pull along it, N; cable: which) */
    CS_EVENT_TERMINATION_SLIP,    /**< a rope starts to slip through its end fitting (value: that end span's
                                       tension, N; cable_end: which end) */
    CS_EVENT_POST_WITHDRAWAL,     /**< the ropes' pull out of a post's footing (up for a post hinged at grade,
                                       along it for one whose footing turns) reaches its pullout capacity: it
                                       starts to slide out (value: that pull, N) */
    CS_EVENT_POST_DOWN,        /**< a post folded over by its ropes lies on the ground, its top at grade; it
                                    keeps the ropes threaded or clamped on it (value: its tilt, rad) */
    CS_EVENT_CABLE_PULLED_OFF, /**< a keyway bolt or bracket pulled off its post's face lets a cable go
                                    (element: the post; value: the pull off the face, N; cable: which) */
    CS_EVENT_TERMINATION_AT_POST, /**< a rope's end, at its anchor, reaches the hole of the post next to it:
                                       the post lets the rope run straight on to the anchor (element: the
                                       post; value: how far that anchor has moved, m; cable_end: which end;
                                       cable: which) */
    CS_EVENT_ANCHOR_WITHDRAWAL,   /**< the ropes' uplift on an anchor reaches its pullout capacity: it starts
                                       to rise out of the soil (value: that uplift, N) */
    CS_EVENT_CABLE_STRUCK_OFF,    /**< the vehicle strikes a post a cable is still on: the post leaves the
                                       cable's path and lets it go (element: the post; value: the cable's pull
                                       on the post then, N; cable: which) */
    CS_EVENT_TYPE_COUNT           /**< the number of event types */
} cs_event_type;

/** The kind of element an event happened to. */
typedef enum cs_element_kind {
    CS_ELEMENT_CABLE,  /**< a cable, by index */
    CS_ELEMENT_POST,   /**< a post, by index in increasing x */
    CS_ELEMENT_ANCHOR, /**< an anchor: 0 the start, 1 the end */
    CS_ELEMENT_VEHICLE /**< the vehicle */
} cs_element_kind;

/** An event of a run. */
typedef struct cs_event {
    size_t size; /**< the size of this struct in the program: set it (cs_event e = {.size = sizeof e}); the
                      library fills only that much */
    double t;    /**< when, s */
    cs_event_type type;           /**< what */
    cs_element_kind element_kind; /**< to what kind of element */
    int element;   /**< index of the cable, post or anchor (0 start, 1 end); 0 for the vehicle */
    double value;  /**< what triggered it, SI: by type (cs_event_type) */
    int cable_end; /**< a termination event's rope end: 0 at the start anchor, 1 at the end anchor; else -1 */
    int cable;     /**< the cable a post lets go (cable_release, cable_pulled_off, termination_at_post,
                        cable_struck_off); else -1 */
    int post;      /**< the post at whose hole a rope broke (cable_break there); else -1 */
} cs_event;

/** An event type's name in events.csv and summary.json: "cable_break", "post_hinge", ... */
CS_API const char *cs_event_type_name(cs_event_type type);
/** The SI unit of an event type's value: "N", "N m", "rad", "m/s", "m" or "s". */
CS_API const char *cs_event_value_unit(cs_event_type type);
/** An element kind's name: "cable", "post", "anchor", "vehicle". */
CS_API const char *cs_element_kind_name(cs_element_kind kind);
/** An event's cable end as events.csv and summary.json give it: "start", "end", or "" for none. */
CS_API const char *cs_event_cable_end_name(const cs_event *event);
/** The number of events so far. */
CS_API int cs_state_event_count(const cs_state *state);
/** Fill out with the index-th event, in time order, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): index out of range, or out's size 0 or
 *         larger than this library's. */
CS_API cs_status cs_state_event(const cs_state *state, int index, cs_event *out, cs_error *err);

/* ---- views ---- */
/* A view, like cs_summary and cs_event, starts with its size: the caller sets it to sizeof the struct
 * (cs_post_view v = {.size = sizeof v}) and the library fills that much of it, so a program built against
 * an earlier cablesim, whose structs lack the fields added since, gets the ones it has. A size of 0, or
 * larger than this library's, is refused with CS_ERR_INVALID naming the struct. */

/** The vehicle now. World frame: x along the barrier, y the direction of attack, z up. */
typedef struct cs_vehicle_view {
    size_t size;                /**< the size of this struct in the program (set it; see above) */
    double t;                   /**< the state's time, s */
    double position[3];         /**< CG, m */
    double velocity[3];         /**< CG, m/s */
    double acceleration[3];     /**< CG, m/s^2 */
    double roll;                /**< rad */
    double pitch;               /**< rad */
    double yaw;                 /**< rad (0: body x along world x) */
    double angular_velocity[3]; /**< body frame, rad/s */
    double forward_speed;       /**< along the initial travel direction, m/s */
    double decel_50ms_g;        /**< 50-ms moving average of the deceleration along travel, g */
    double crush;               /**< permanent-plus-elastic set of the front face, m */
    double face_force;          /**< normal force on the front face, N */
    double penetration;         /**< furthest point of the front face past the attack face (y), m */
    double barrier_force[3];    /**< resultant force of the barrier on the vehicle, N */
    double front_corners[2][3]; /**< left and right ends of the front face at mid-face height, m */
    double rear_corners[2][3];  /**< left and right rear corners at mid-side height, m */
} cs_vehicle_view;

/** Fill out with the vehicle now, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL) for a size 0 or larger than this library's.
 */
CS_API cs_status cs_state_vehicle(const cs_model *model, const cs_state *state, cs_vehicle_view *out,
                                  cs_error *err);

/** A cable's condition. */
typedef enum cs_cable_status {
    CS_CABLE_INTACT = 0, /**< holding */
    CS_CABLE_BROKEN,     /**< broken along a span or at an end fitting */
    CS_CABLE_RELEASED,   /**< let go by an anchor that pulled out */
    CS_CABLE_SLIPPED     /**< the vehicle went over or under it: holding, anchored and strung over its posts,
                              out of contact with the vehicle */
} cs_cable_status;

/** A cable now. */
typedef struct cs_cable_view {
    size_t size;            /**< the size of this struct in the program (set it) */
    cs_cable_status status; /**< its condition */
    int engaged;            /**< 1 while a corner or wheel of the vehicle holds it */
    double max_tension;     /**< largest span tension now, N */
    double max_strain;      /**< largest span strain now */
    int node_count;         /**< points of the cable's path (anchors, standing posts, corners, wheels) */
} cs_cable_view;

/** Fill out with a cable now, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such cable, or out's size 0 or larger
 *         than this library's. */
CS_API cs_status cs_state_cable(const cs_model *model, const cs_state *state, int cable, cs_cable_view *out,
                                cs_error *err);
/** A cable status's name: "intact", "broken", "released", "slipped". */
CS_API const char *cs_cable_status_name(cs_cable_status status);
/** 1 if a cable of this status is in the barrier, anchored and holding (intact, or passed by the vehicle). */
CS_API int cs_cable_status_holds(cs_cable_status status);
/** Copy up to capacity path points (x, y, z triplets, m) and span tensions (node_count - 1 of them, N).
 * @return the number of points copied. */
CS_API int cs_state_cable_path(const cs_model *model, const cs_state *state, int cable, double *xyz,
                               double *tension, int capacity);

/** A post's condition. */
typedef enum cs_post_status {
    CS_POST_ELASTIC = 0,     /**< bending elastically */
    CS_POST_HINGED,          /**< plastic hinge at the base, rotating at Mp */
    CS_POST_SOIL,            /**< footing rotating in the soil at its capacity */
    CS_POST_FAILED_ROTATION, /**< out: struck by the vehicle and turned to its rotation limit */
    CS_POST_FAILED_SHEAR,    /**< out: sheared at the base */
    CS_POST_FAILED_PULLOUT,  /**< out: pulled out of the ground */
    CS_POST_DOWN             /**< lying on the ground, its top at grade, still holding its ropes */
} cs_post_status;

/** A post now. */
typedef struct cs_post_view {
    size_t size;           /**< the size of this struct in the program (set it) */
    cs_post_status status; /**< its condition */
    double tilt;           /**< rotation from vertical, rad */
    double tilt_dir[2];    /**< horizontal direction the top moves, unit */
    double base_moment;    /**< N m */
    double base_shear;     /**< N */
    double axial_pull;     /**< N, positive pulling the post out */
    double withdrawal;     /**< how far it has slid out of its footing (up, or along its axis), m */
    double
        moment_capacity;   /**< Mp about the base, or the footing's P (h + 2D/3) about its pivot if it is the
                              weaker (a footing sliding out: what its length still in the ground holds), N m */
    double top[3];         /**< the top's position, m */
    double rotation_limit; /**< the tilt past which a vehicle that strikes it rides over it, rad: its
                              footing's rotation limit if it turns in the soil, else its own (pi / 2: none;
                              it goes when its top comes down to the pushing edge) */
} cs_post_view;

/** Fill out with a post now, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such post, or out's size 0 or larger
 *         than this library's. */
CS_API cs_status cs_state_post(const cs_model *model, const cs_state *state, int post, cs_post_view *out,
                               cs_error *err);
/** A post status's name: "elastic", "hinged", ... */
CS_API const char *cs_post_status_name(cs_post_status status);

/** An anchor (a dead-man in the soil) now. */
typedef struct cs_anchor_view {
    size_t size;            /**< the size of this struct in the program (set it) */
    int rigid;              /**< no footing: it does not move */
    int yielded;            /**< moving through the soil */
    int failed;             /**< pulled out */
    double displacement[2]; /**< horizontal, m */
    double force[2];        /**< the soil's resistance (a rigid anchor: the ropes' pull it holds), N */
    double capacity;        /**< its footing's peak horizontal resistance, N */
    double residual;        /**< what the soil keeps resisting with as it ploughs on past the peak, N */
    double slide;           /**< how far it has ploughed through the soil past its elastic range, m */
    double uplift;          /**< the ropes' upward pull, N */
    double uplift_capacity; /**< the upward pull at which it starts to rise out of the soil, N */
    double peak_pull;       /**< the ropes' largest horizontal pull on it so far, N */
    double lift;            /**< how far the ropes' uplift has raised it out of the soil, m */
} cs_anchor_view;

/** Fill out with an anchor now, 0 the start (low x), 1 the end, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such anchor, or out's size 0 or larger
 *         than this library's. */
CS_API cs_status cs_state_anchor(const cs_model *model, const cs_state *state, int anchor,
                                 cs_anchor_view *out, cs_error *err);
/** "rigid", "holding" (in the soil's elastic range), "sliding" (it has yielded and ploughs through the soil),
 * "rising" (the ropes' uplift is raising it out of the soil), "pulled_out" (risen all the way out). */
CS_API const char *cs_anchor_status_name(const cs_anchor_view *anchor);

/** Energy ledger, J. Every term is a state function or an accumulated dissipation computed on its own;
 * balance_error = (sum now - sum at t = 0) / initial kinetic energy (for a vehicle starting at rest:
 * / m g h_cg). It starts with its size, as the views do; new fields go at its end. */
typedef struct cs_energy {
    size_t size;              /**< the size of this struct in the program: set it (cs_energy e =
                                   {.size = sizeof e}); the library fills only that much */
    double vehicle_kinetic;   /**< the vehicle's kinetic energy, translation and rotation */
    double vehicle_potential; /**< gravity and tyre springs, relative to t = 0 */
    double cable_elastic;     /**< the ropes' elastic strain energy less their sag's weight below the
                                   chords: below zero where slack ropes hang (docs/theory.md, Own weight) */
    double cable_plastic;     /**< the ropes' plastic work */
    double post_elastic;      /**< the posts' elastic bending */
    double post_kinetic;      /**< the posts' swing */
    double post_plastic;      /**< the posts' plastic hinges */
    double post_damping;      /**< of the posts' swing and the anchors' slide by their implicit integration */
    double anchor_elastic;    /**< the soil's elastic spring at the anchors, and a rising one's weight lifted
                                   and its skin's slip */
    double anchor_kinetic;    /**< the anchors' slide and rise */
    double rail_elastic;      /**< the rails' axial strain energy */
    double rail_plastic;      /**< the rails' yielding and buckling */
    double soil;              /**< plastic work of footings and anchors moving through the soil */
    double crush;             /**< the vehicle's front crush */
    double friction;          /**< tyres, cable sliding over supports */
    double released;          /**< stored energy lost at sudden failures (massless cable and posts), and
                                   the change of the sag's reference when a corner takes up or lets go a
                                   hanging rope */
    double initial_total;     /**< the sum at t = 0 */
    double initial_kinetic;   /**< the vehicle's kinetic energy at t = 0 */
    double balance_error;     /**< (sum now - initial_total) over initial_kinetic */
} cs_energy;

/** Fill out with the ledger now, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL) for a size 0 or larger than this library's.
 */
CS_API cs_status cs_state_energy(const cs_state *state, cs_energy *out, cs_error *err);
/** The number of the ledger's terms: those of cs_energy from vehicle_kinetic to released, in that order. */
enum { CS_ENERGY_TERMS = 16 };
/** A term's short name ("ke", "pe", "cable_elastic", ...; timeseries.csv's columns NAME_j), "?" out of range.
 */
CS_API const char *cs_energy_term_name(int term);
/** A term's value, J: 0 out of range, or for a term past energy's size (a struct of an earlier cablesim). */
CS_API double cs_energy_term(const cs_energy *energy, int term);
/** A run's ledger closes when its balance error stays within this fraction of the initial kinetic energy;
 * beyond it the run is flagged (summary.json's energy_balance_warning). */
#define CS_LEDGER_WARNING 0.01
/** A run whose balance error goes past this fraction stops with an error naming the term that moved most in
 * the step (docs/robustness.md). */
#define CS_LEDGER_FAILURE 0.05

/** How many cables cs_summary gives one by one (cs_state_cable_summary gives any cable). */
enum { CS_SUMMARY_CABLES = 8 };

/** One cable over the run: its largest tension and the work its rope did on the vehicle. It starts with its
 * size, as the views do; new fields go at its end (cs_summary's cables keep the first layout:
 * cs_summary_cable). */
typedef struct cs_cable_summary {
    size_t size;                /**< the size of this struct in the program: set it (cs_cable_summary c =
                                     {.size = sizeof c}); the library fills only that much */
    double peak_tension_n;      /**< largest span tension over the run, at a commit of the barrier, N */
    double peak_tension_time_s; /**< when it was reached (the end of its step), s */
    double work_on_vehicle_j;   /**< work of the rope's force on the vehicle over the run: the integral of
                                     that force dotted with the vehicle's velocity at the contact, J
                                     (negative while it slows the vehicle) */
    double energy_share;        /**< -work_on_vehicle_j over the initial kinetic energy: the share of it the
                                     cable took from the vehicle (negative if it gave the vehicle energy) */
} cs_cable_summary;

/** cs_cable_summary's first fields, as cs_summary holds them in an array: this layout never changes (a
 * field added to cs_cable_summary comes through cs_state_cable_summary alone). */
typedef struct cs_summary_cable {
    double peak_tension_n;      /**< as cs_cable_summary's, N */
    double peak_tension_time_s; /**< as cs_cable_summary's, s */
    double work_on_vehicle_j;   /**< as cs_cable_summary's, J */
    double energy_share;        /**< as cs_cable_summary's */
} cs_summary_cable;

/** How many sudden losses cs_summary gives one by one (cs_state_sudden_losses gives the rest). */
enum { CS_SUMMARY_SUDDEN_LOSSES = 4 };

/** A sudden loss: within 10 ms the magnitude of the barrier's force on the vehicle (ropes and struck posts)
 * fell by more than half of its largest over the run, and no rope broke, no end fitting let go and no
 * attachment let a cable go within that window or a sample step of it. It starts with its size, as the
 * views do; new fields go at its end (cs_summary's sudden losses keep the first layout: cs_summary_loss). */
typedef struct cs_sudden_loss {
    size_t size;           /**< the size of this struct in the program: set it (cs_sudden_loss w =
                                {.size = sizeof w}; in an array, the first one's); the library fills only
                                that much */
    double t_start_s;      /**< the window's start: the force before, s */
    double t_end_s;        /**< its end: the force after, s (t_end_s - t_start_s <= 10 ms) */
    double force_before_n; /**< N */
    double force_after_n;  /**< N */
} cs_sudden_loss;

/** cs_sudden_loss's first fields, as cs_summary holds them in an array: this layout never changes (a field
 * added to cs_sudden_loss comes through cs_state_sudden_losses alone). */
typedef struct cs_summary_loss {
    double t_start_s;      /**< as cs_sudden_loss's, s */
    double t_end_s;        /**< as cs_sudden_loss's, s */
    double force_before_n; /**< as cs_sudden_loss's, N */
    double force_after_n;  /**< as cs_sudden_loss's, N */
} cs_summary_loss;

/** The window of the sudden-loss check, s. */
#define CS_SUDDEN_LOSS_WINDOW 0.010
/** The fall, as a fraction of the run's largest force on the vehicle, it takes to flag a window. */
#define CS_SUDDEN_LOSS_FRACTION 0.5
/** How many sudden losses a run keeps (cs_state_sudden_losses); more are counted. */
enum { CS_SUDDEN_LOSS_KEPT = 64 };

/** Response parameters, updated every step. Each field is named as its key in summary.json, its unit in the
 * name's last part (_s, _m, _g, _mps, _deg, _n, _j); summary.json also has what follows from them (stopped,
 * energy_balance_warning), the anchors, the events and the inputs. It starts with its size, as the views do;
 * new fields go at its end (its arrays of cables and sudden losses hold cs_summary_cable and cs_summary_loss,
 * whose layouts never change; the sized cs_cable_summary and cs_sudden_loss that grow come through
 * cs_state_cable_summary and cs_state_sudden_losses). */
typedef struct cs_summary {
    size_t size;                      /**< the size of this struct in the program: set it (cs_summary s =
                                           {.size = sizeof s}); the library fills only that much */
    cs_outcome outcome;               /**< why the run ended (CS_RUNNING while it goes on) */
    double t_end_s;                   /**< time reached, s */
    double max_50ms_decel_g;          /**< largest 50-ms average deceleration along travel, g */
    double t_max_50ms_decel_s;        /**< the end of that 50-ms window, s */
    double max_dynamic_penetration_m; /**< front face past the attack face, m: the run's penetration where
                                           cs_penetration_is_final(outcome), else how far the front had
                                           got (penetration_beyond_m) */
    double max_barrier_deflection_m;  /**< largest y of any cable path point (the dynamic deflection), m */
    double working_width_m;          /**< largest y reached by any part of the vehicle's outline, a cable or a
                                          standing post's top: the reach past the barrier's line (y = 0), m */
    double stop_time_s;              /**< valid if outcome == CS_STOPPED, s */
    double exit_speed_mps;           /**< valid if cs_outcome_exits(outcome), m/s */
    double exit_angle_deg;           /**< between the CG's velocity at exit and the barrier's line, positive
                                          away from the barrier (to -y), degrees; valid with exit_speed_mps */
    double first_contact_time_s;     /**< < 0 before contact, s */
    int posts_failed_left;           /**< posts down at x below the impact point (scenario.impact_x) */
    int posts_failed_right;          /**< posts down at x from the impact point up */
    int posts_failed_rotation_left;  /**< of those left, turned to their rotation limit (bent over, or their
                                          footing turned in the soil) */
    int posts_failed_rotation_right; /**< of those right, turned to their rotation limit */
    int posts_failed_shear_left;     /**< of those left, sheared at the base */
    int posts_failed_shear_right;    /**< of those right, sheared at the base */
    int posts_failed_pullout_left;   /**< of those left, pulled out of the ground */
    int posts_failed_pullout_right;  /**< of those right, pulled out of the ground */
    int cables_broken;               /**< cables broken along a span or at an end fitting */
    double initial_kinetic_energy_j; /**< J */
    double energy_balance_error;     /**< fraction, largest |error| over the run */
    double max_cable_tension_n;      /**< over the run, N */
    double final_position_m[3];      /**< CG, m */
    int solver_warnings;             /**< steps whose barrier solve hit its sweep cap */
    double max_solver_residual;      /**< largest relative residual left by such a step */
    int cable_count;                 /**< cables of the model; the first CS_SUMMARY_CABLES are in cables */
    cs_summary_cable cables[CS_SUMMARY_CABLES]; /**< each cable's peak tension and work on the vehicle */
    int sudden_loss_count; /**< sudden losses of the barrier's force on the vehicle, found at the
                                run's end from its force at every step (0 while it runs) */
    cs_summary_loss sudden_losses[CS_SUMMARY_SUDDEN_LOSSES]; /**< the first of them, in time order */
    double penetration_beyond_m; /**< a vehicle through the barrier or still going (not
                                      cs_penetration_is_final(outcome)): how far its front had got when the
                                      run ended, m, its penetration beyond it (summary.json's
                                      penetration_beyond_m); NAN where the penetration is final */
    double exit_time_s;          /**< when the vehicle last left the barrier's contact, at which
                                      exit_speed_mps and exit_angle_deg are taken, s; valid with them */
} cs_summary;

/** Fill out with the response parameters now (at the run's end: the run's), to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL) for a size 0 or larger than this library's.
 */
CS_API cs_status cs_state_summary(const cs_state *state, cs_summary *out, cs_error *err);
/** Fill out with cable `cable`'s peak tension and work on the vehicle over the run so far, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such cable, or out's size 0 or larger
 *         than this library's. */
CS_API cs_status cs_state_cable_summary(const cs_state *state, int cable, cs_cable_summary *out,
                                        cs_error *err);
/** The sudden losses of the run, once it has ended (cs_summary's sudden_loss_count in all).
 * @param state the state at the run's end
 * @param out filled with up to capacity of them, in time order, each at the size of the first (set out[0]'s
 *        size; each one filled gets that size)
 * @param capacity out's room
 * @param err filled on failure (may be NULL)
 * @return how many it holds (at most CS_SUDDEN_LOSS_KEPT; a run with more counts them in sudden_loss_count),
 *         or -1 with err filled (CS_ERR_INVALID) for out's size 0 or larger than this library's. */
CS_API int cs_state_sudden_losses(const cs_state *state, cs_sudden_loss *out, int capacity, cs_error *err);
/** The sudden-loss check on a force history, as a run makes it from its force at every step.
 * @param t the samples' times, increasing, s
 * @param force the magnitude of the barrier's force on the vehicle at each, N
 * @param n how many
 * @param step the output step: an event this close to a window excuses it, s
 * @param events the run's events, in time order (a cable_break, termination_break or cable_release
 *        excuses a fall), each of the first one's size (as cs_state_event filled them)
 * @param event_count how many
 * @param out filled with up to capacity windows, in time order (overlapping windows flagged at successive
 *        samples are given once, by the largest fall among them), each at the size of the first (set
 *        out[0]'s size; may be NULL with capacity 0)
 * @param capacity out's room
 * @param err filled on failure (may be NULL)
 * @return the number of windows flagged (those past capacity, or past CS_SUDDEN_LOSS_KEPT, counted too), or
 *         -1 with err filled: CS_ERR_MEMORY, or CS_ERR_INVALID for events, or out, of size 0 or larger than
 *         this library's. */
CS_API int cs_sudden_losses(const double *t, const double *force, int n, double step, const cs_event *events,
                            int event_count, cs_sudden_loss *out, int capacity, cs_error *err);
/** An outcome's name in summary.json: "stopped", "breakthrough", "redirected", ... */
CS_API const char *cs_outcome_name(cs_outcome outcome);

/** A 64-bit FNV-1a hash of the state's numbers, for determinism tests. */
CS_API unsigned long long cs_state_hash(const cs_model *model, const cs_state *state);

#ifdef __cplusplus
}
#endif
#endif
