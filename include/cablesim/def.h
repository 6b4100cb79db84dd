/* SPDX-License-Identifier: MIT */
/** @file
 * Definition structs: plain data a caller fills (or a loader fills) and hands to cs_model_create().
 * Every quantity is SI (m, kg, s, N, Pa, J, rad). Each struct has a cs_default_*() that returns the
 * documented defaults (docs/assumptions.md); fields that are design data default to 0 and must be set.
 *
 * Each struct begins with its size, which its cs_default_*() sets: start every definition from it. A later
 * version of the library adds fields only at a struct's end, so a program built against an earlier one
 * keeps working: the library reads the size the program gave and takes the defaults for the fields it
 * does not have (an array's elements are read at the first one's size). The cs_default_*() are inline
 * here, compiled into the program at its own structs' sizes: a library function returning a struct by
 * value would write the library's larger struct into the program's smaller one. A struct of size 0 (not
 * started from its cs_default_*()), or larger than the library knows (a program built for a later version),
 * is refused with CS_ERR_INVALID. cs_cable_end_def, only ever a member of cs_cable_def, is covered by its
 * cable's size.
 *
 * Frame: x along the barrier, y the direction of attack (attack face at y = 0, protected side y > 0),
 * z up from grade. */
#ifndef CABLESIM_DEF_H
#define CABLESIM_DEF_H

#include <stddef.h>

#include "cablesim/export.h"
#include "cablesim/units.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The most points a vehicle's crush curve has. */
enum { CS_MAX_CRUSH_POINTS = 16 };

/** Wire rope material: the idealised law of the paper (Fig. 3). Tension T against strain e:
 *   T = EA e                      up to T = r_el * Fu            (elastic, slope EA)
 *   T = r_el Fu + r_2 EA (e - e1) up to T = Fu                   (secondary slope r_2 * EA)
 *   T = Fu                        up to e = breaking_strain      (plastic)
 *   broken                        beyond.
 * Unloading is elastic with slope EA; the plastic stretch stays. */
typedef struct cs_rope_def {
    size_t size; /**< the size of this struct in the program that filled it: set by cs_default_rope_def() */
    double area; /**< metallic area A, m^2 */
    double modulus;                 /**< apparent modulus E, Pa */
    double nominal_strength;        /**< Fu, N */
    double elastic_limit_ratio;     /**< r_el: end of the first slope as a fraction of Fu (paper: 0.6) */
    double secondary_modulus_ratio; /**< r_2: second slope as a fraction of E (paper: 0.6) */
    double breaking_strain;         /**< total strain at which the rope breaks (paper: 0.03) */
    double mass_per_length;         /**< kg/m: the spans sag under their own weight */
    double diameter;                /**< nominal diameter d, m (0: unknown) */
} cs_rope_def;

/** The strain at which a rope reaches its nominal strength on the law's two slopes,
 * r_el Fu / (EA) + (1 - r_el) Fu / (r_2 EA): its breaking strain must exceed it. */
CS_API double cs_rope_strain_at_strength(const cs_rope_def *rope);

/** How a rope's ends are made off at the anchors: each kind's published efficiency (its breaking strength
 * over the rope's) is in cs_termination_efficiency and docs/assumptions.md. */
typedef enum cs_termination {
    CS_TERMINATION_AS_CABLE = -1, /**< a cable end's only (cs_cable_end_def): the cable's kind */
    CS_TERMINATION_CLIPS = 0,     /**< wire rope clips (cable clamps): 80% below 1-in rope, 90% from 1 in */
    CS_TERMINATION_SWAGED,        /**< swaged socket or sleeve: 95% */
    CS_TERMINATION_SPELTER,       /**< poured (spelter) socket: 100% */
    CS_TERMINATION_WEDGE          /**< wedge socket: 75-95%, 85% taken */
} cs_termination;

/** The fitting at one end of a cable, where it differs from the cable's. */
typedef struct cs_cable_end_def {
    cs_termination termination;    /**< its kind (CS_TERMINATION_AS_CABLE: the cable's) */
    double termination_efficiency; /**< its strength over the rope's Fu (0: its kind's published value, or
                                      the cable's termination_efficiency where it takes the cable's kind) */
    double slip_load;              /**< end span tension at which the rope slips through it, N (0: the cable's
                                      slip_load where it takes the cable's kind, else none) */
    double slip_travel; /**< rope it lets slip before the rope runs out of it, m (0: the cable's) */
} cs_cable_end_def;

/** A cable: a wire rope at a height along the posts, tied to both anchors. */
typedef struct cs_cable_def {
    size_t size; /**< the size of this struct in the program that filled it: set by cs_default_cable_def() */
    double height;                 /**< z of the cable at the posts, m */
    double pretension;             /**< installed tension, N */
    double post_friction;          /**< mu between cable and post (capstan at a threaded post) */
    cs_termination termination;    /**< the fitting at both ends, unless an end has its own */
    double termination_efficiency; /**< its strength over the rope's Fu (0: the kind's published value);
                                      the rope breaks at an end when that end span's tension exceeds it */
    double slip_load;              /**< end span tension at which the rope slips through the fittings, N
                                      (0: none; they hold to their strength, as correctly made clips do) */
    double slip_travel;            /**< rope a fitting lets slip before the rope runs out of it (a clip's
                                      turn-back), m; needed with a slip_load */
    double hole_efficiency;        /**< its strength over the rope's Fu where it runs through a hole at a
                                      threaded post (0: the rope's own; docs/theory.md, APS1) */
    cs_cable_end_def ends[2];      /**< each end's own fitting: 0 at the start anchor (low x), 1 at the
                                      end anchor (cs_default_cable_def: both the cable's) */
    cs_rope_def rope;              /**< its rope */
} cs_cable_def;

/** The published efficiency of a fitting on a rope of diameter d (m; 0 unknown: the larger rope's); 0 for
 * CS_TERMINATION_AS_CABLE, which is no fitting of its own. */
CS_API double cs_termination_efficiency(cs_termination kind, double diameter);

/** The efficiency of the fitting at a cable's end (0 the start anchor's, 1 the end anchor's), as the engine
 * takes it; its kind in *kind (may be NULL). */
CS_API double cs_cable_end_efficiency(const cs_cable_def *cable, int end, cs_termination *kind);

/** The load at which the rope slips through the fitting at a cable's end (0 the start anchor's, 1 the end
 * anchor's), N, 0 where it does not slip; the travel it lets slip before the rope runs out, m, in *travel
 * (may be NULL). An end's own slip_load and slip_travel replace the cable's; an end with a kind of its own
 * (a swaged socket at one end of a clipped rope, say) does not take the cable's slip_load. */
CS_API double cs_cable_end_slip(const cs_cable_def *cable, int end, double *travel);

/** Steel post section. */
typedef struct cs_section_def {
    size_t
        size; /**< the size of this struct in the program that filled it: set by cs_default_section_def() */
    double plastic_modulus; /**< Zx, m^3 */
    double inertia;         /**< Ix, m^4 */
    double web_area;        /**< Aw for shear, m^2 */
    double yield_stress;    /**< Fy, Pa */
    double modulus;         /**< E, Pa */
    double mass_per_length; /**< kg/m: the post's swing (0: a massless post, the paper's) */
    double width;         /**< a rectangular tube's outer width across the bending axis, m (0: not a tube) */
    double depth;         /**< its outer depth in the plane of bending, m */
    double wall;          /**< its design wall thickness, m */
    double fill_strength; /**< f'c of the concrete filling the tube, Pa (0: hollow) */
} cs_section_def;

/** A post section's plastic moment about its strong axis, N m: Zx Fy, and for a tube filled with concrete
 * (fill_strength > 0) what the fill adds by the plastic stress distribution, the steel at Fy and the
 * concrete in compression at 0.85 f'c (AISC 360-16 I1.2a; docs/theory.md, "A tube filled with concrete").
 * A fill is taken as given: cs_model_create refuses one the method does not cover (no tube geometry, walls
 * that are not compact, f'c outside 3-10 ksi), naming the post. */
CS_API double cs_section_plastic_moment(const cs_section_def *section);

/** A post section's flexural rigidity about its strong axis, N m^2: E Ix, and for a filled tube the
 * cracked concrete's share C3 Ec Ic added (AISC 360-16 Eq. I2-15). */
CS_API double cs_section_flexural_rigidity(const cs_section_def *section);

/** How a footing's dynamic factor carries to its own width and depth. */
typedef enum cs_width_scaling {
    CS_WIDTH_WEDGE, /**< by the passive wedge's width effect, R(B/D) over the bogie post's (the default) */
    CS_WIDTH_NONE   /**< not at all: the bogie post's factor at any width (validate's other reading) */
} cs_width_scaling;

/** Footing (or the post itself driven in soil) and the soil around it: lateral capacity by Eq. 21,
 *   S1 B D^2 - c_d P D - c_h P H = 0  =>  P = S1 B D^2 / (c_d D + c_h H),
 * dimensionally homogeneous, so evaluated in SI as written; see footing.c. */
typedef struct cs_footing_def {
    size_t
        size; /**< the size of this struct in the program that filled it: set by cs_default_footing_def() */
    double diameter;          /**< B, m (width facing the soil) */
    double depth;             /**< D, embedment, m */
    double soil_pressure;     /**< S1, average soil pressure above the point of rotation, Pa */
    double soil_pressure_cap; /**< the paper caps S1 at 8000 psf, Pa */
    double coeff_depth;       /**< c_d (paper 2.37; building code 2.34) */
    double coeff_height;      /**< c_h (paper 2.64; building code 2.55) */
    double rotation_limit;    /**< as the post's rotation_limit, where the footing turns in the soil, rad */
    double pullout_capacity;  /**< pull out of the ground that draws the footing out, N; 0: the embedment's
                                 skin friction (skin_friction pi B D^2 / 2) */
    double dynamic_factor;    /**< soil resistance under impact over Eq. 21's for a member of the bogie tests'
                                 post's proportions (calibrated, assumptions.md); scaled to a member's own
                                 width and depth as width_scaling says (footing.c) */
    double friction_angle;    /**< the soil's angle of internal friction, rad (the wedge's width effect) */
    double residual_friction_angle; /**< its critical-state angle, rad: sheared on at constant volume past
                                       the peak, the soil keeps the passive resistance of this angle (the
                                       residual an anchor ploughs on at; none below: friction_angle) */
    cs_width_scaling width_scaling; /**< how dynamic_factor carries to this member's width */
    double skin_friction; /**< shaft friction per metre of depth, Pa/m (uplift capacity, calibrated) */
    double unit_weight;   /**< the soil's unit weight, N/m^3: the mass of the passive wedge a moving
                             anchor carries with it (anchor.c) */
} cs_footing_def;

/** How the cables are held on a post. All but clamped slide along the barrier with capstan friction.
 * Slots, hooks, keyway bolts and brackets let a cable go (attachment.c) when its pull along the post,
 * toward the post's top, exceeds friction on the post (the cable's post_friction times its pull across
 * the post) plus what the retainer holds (release_force): a post bent over under the cables turns their
 * pull up along it. A keyway bolt or a bracket, bolted to one face of the post, also lets its cable go
 * when the cable pulls it off that face by more than its lateral_release_force. */
typedef enum cs_attachment {
    CS_ATTACH_THROUGH = 0, /**< cable threaded through the post */
    CS_ATTACH_CLAMPED = 1, /**< cable clamped to the post: no sliding */
    CS_ATTACH_SLOT = 2,   /**< cables stacked in a slot open at the top (spacers, strap and cap): they ride up
                             and out, the top one first */
    CS_ATTACH_HOOK = 3,   /**< each cable in a hook bolt on the post's face: the hook opens */
    CS_ATTACH_KEYWAY = 4, /**< each cable in a keyway bolt on the post's face (component tests: 35.6 kN off
                             the face, 4.45 kN along the post) */
    CS_ATTACH_BRACKET = 5 /**< each cable in a tabbed bracket on the post's face (component tests: 27.1 kN
                             off the face, 1.54 kN along the post) */
} cs_attachment;

/** The face of a post a keyway bolt or a bracket is fixed to: the attack face (toward y < 0, where the
 * vehicle comes from) or the protected one (toward y > 0). */
typedef enum cs_face { CS_FACE_ATTACK = 0, CS_FACE_PROTECTED = 1 } cs_face;

/** The documented strength of a kind's retainer along the post, N (docs/assumptions.md): 0 for kinds that
 * never let go. */
CS_API double cs_attachment_release_force(cs_attachment kind);

/** The documented load that pulls a kind's fitting off the post's face, N (docs/assumptions.md): 0 for
 * kinds without one (held by the post itself, or never let go across it). */
CS_API double cs_attachment_lateral_release_force(cs_attachment kind);

/** A post: its steel section, its footing in the soil and how it holds the cables. */
typedef struct cs_post_def {
    size_t size;   /**< the size of this struct in the program that filled it: set by cs_default_post_def() */
    double x;      /**< position along the barrier, m */
    double height; /**< top of the post above grade, m */
    cs_section_def section;       /**< its steel */
    cs_footing_def footing;       /**< its footing (or itself driven) in the soil */
    cs_attachment attachment;     /**< how it holds the cables */
    double release_force;         /**< a retainer's strength along the post (slot, hook, keyway bolt,
                                     bracket), N (0: the kind's documented value, cs_attachment_release_force) */
    double rotation_limit;        /**< rotation from vertical past which a post hinged at grade that the
                                     vehicle pushes over lets it go, rad (90 deg: none; it goes when its top
                                     comes down to the pushing edge, which rides over it); a post carrying
                                     ropes folds on until its top reaches grade */
    double lateral_release_force; /**< a keyway bolt's or bracket's strength against a pull off its face, N
                                     (0: the kind's documented value, cs_attachment_lateral_release_force) */
    cs_face face;                 /**< the face a keyway bolt or bracket is fixed to */
} cs_post_def;

/** A post's retainer strength along it, N: its release_force, or its kind's documented value when that is 0.
 */
CS_API double cs_post_release_force(const cs_post_def *post);

/** A post's fitting's strength against a pull off its face, N: its lateral_release_force, or its kind's
 * documented value when that is 0 (0 for kinds without one). */
CS_API double cs_post_lateral_release_force(const cs_post_def *post);

/** A cable end anchor: a footing (dead-man) in the soil. Every cable is tied to the start anchor at one
 * end and the end anchor at the other, each rope by its own end at height z. The footing resists the
 * ropes' horizontal pull by Eq. 21 at that height (times the soil's dynamic factor for its width, as a
 * post's footing), ploughs on through the soil past it at a resistance falling to its residual (the
 * footing's residual_friction_angle) doing the soil's work, and pulls out, releasing the ropes, only when
 * the ropes lift it with more than its pullout capacity (its footing's rotation_limit is not used).
 * A footing of zero diameter is rigid: it never moves or pulls out (a rock anchor, a test's fixed end). */
typedef struct cs_anchor_def {
    size_t size; /**< the size of this struct in the program that filled it: set by cs_default_anchor_def() */
    double x;    /**< m */
    double z;    /**< height where the cables are tied, m */
    double pullout_capacity; /**< uplift that pulls it out, N; 0: its weight plus its skin friction
                              * (footing.skin_friction); HUGE_VAL: never */
    double length;           /**< plan size along the pull, m (0: a round shaft of the footing's diameter) */
    double mass;             /**< kg, the footing's own (0: its concrete, CS_CONCRETE_DENSITY): its weight
                              * holds it down; the soil's wedge moves with it too (footing.unit_weight) */
    cs_footing_def footing;  /**< its width facing the pull (diameter), depth and soil; diameter 0: rigid */
} cs_anchor_def;

#define CS_CONCRETE_DENSITY 2300.0 /**< kg/m^3, plain concrete */

/** A horizontal rail tying neighbouring posts at one height (the APS barriers' open trapezoidal rails):
 * between each pair of neighbouring posts an axial member, elastic (EA over the spacing), yielding at
 * A Fy in tension and buckling at the Euler load pi^2 E I / spacing^2 in compression, then holding that
 * force (rail.c). Half of each span's steel swings with each of its posts. */
typedef struct cs_rail_def {
    size_t size;   /**< the size of this struct in the program that filled it: set by cs_default_rail_def() */
    double height; /**< above grade, m */
    double area;   /**< A, m^2 */
    double inertia;         /**< I about its weaker axis, m^4 (the buckling load) */
    double yield_stress;    /**< Fy, Pa */
    double modulus;         /**< E, Pa */
    double mass_per_length; /**< kg/m */
} cs_rail_def;

/** A barrier: cables, posts, rails and the two anchors. The arrays belong to the caller. */
typedef struct cs_barrier_def {
    size_t
        size; /**< the size of this struct in the program that filled it: set by cs_default_barrier_def() */
    int cable_count;            /**< the number of cables */
    const cs_cable_def *cables; /**< [cable_count] */
    int post_count;             /**< the number of posts */
    const cs_post_def *posts;   /**< [post_count], in increasing x */
    int rail_count;             /**< the number of rails (0: none) */
    const cs_rail_def *rails;   /**< [rail_count] */
    cs_anchor_def start_anchor; /**< at the low-x end */
    cs_anchor_def end_anchor;   /**< at the high-x end */
} cs_barrier_def;

/** Vehicle: a rigid body with a crushable front face. Body frame: x forward, y left, z up, origin at
 * the centre of gravity. Heights are above grade with the vehicle at rest on its tyres. In plan the body
 * is a rectangle front_width wide from the front face to the rear: the cables bear on its four corners,
 * the front ones between the face's bottom and top, the rear ones between the sides' bottom and top, on
 * its rear tyres at the rear axle, from the ground up (a rope that passes under the rear overhang), and on
 * its front tyres at the front axle, from the axle's height up (a rope that passes under the bumper). */
typedef struct cs_vehicle_def {
    size_t
        size; /**< the size of this struct in the program that filled it: set by cs_default_vehicle_def() */
    double mass;                   /**< kg */
    double inertia[3];             /**< roll Ixx, pitch Iyy, yaw Izz about the CG, kg m^2 */
    double cg_height;              /**< m */
    double cg_to_front;            /**< CG to the undeformed front face, m */
    double front_width;            /**< width of the front face, m */
    double face_bottom;            /**< lowest point of the front face (bumper bottom), m */
    double face_top;               /**< top of the front face (hood edge), m */
    double front_to_cargo_bed;     /**< front face to the front of the cargo bed, m (ratings) */
    double cg_to_rear;             /**< CG to the rear end of the body, m */
    double side_bottom;            /**< lowest point of the sides a cable bears on (sill, rocker panel), m */
    double side_top;               /**< top of the sides (bed rail, belt line), m */
    double wheelbase;              /**< m */
    double cg_to_front_axle;       /**< m */
    double track;                  /**< m */
    double tyre_static_deflection; /**< m: sets the tyre stiffness from the static axle loads */
    double tyre_damping_ratio;     /**< fraction of critical, bounce mode */
    double rolling_resistance;     /**< coefficient of rolling resistance (free-rolling, unbraked) */
    double tyre_friction;          /**< lateral (side-slip) friction coefficient */
    double face_friction;          /**< mu between cable and the body (face, corners, sides) */
    int crush_point_count;         /**< points of the loading curve, deformation increasing, first (0,0) */
    double crush_deformation[CS_MAX_CRUSH_POINTS]; /**< m */
    double crush_force[CS_MAX_CRUSH_POINTS];       /**< N */
    double crush_unload_stiffness;                 /**< N/m; crush is permanent beyond elastic recovery */
    double wheel_radius; /**< unloaded tyre radius, m: a front tyre takes a rope above its axle */
    double rim_radius;   /**< the wheel's rim, m (half the rim diameter of the tyre's size): a tyre pressed
                            down by wheel_radius - rim_radius bottoms on its rim (0: none given, the tyre
                            takes any compression) */
} cs_vehicle_def;

/** The attack and how to integrate it. */
typedef struct cs_scenario_def {
    size_t
        size; /**< the size of this struct in the program that filled it: set by cs_default_scenario_def() */
    double speed;            /**< m/s at first contact */
    double angle;            /**< between barrier line and travel direction, rad (pi/2 = head-on) */
    double impact_x;         /**< where the centre of the front face meets the cable line, m; with
                                impact_at_corner, where the leading front corner does */
    int impact_at_corner;    /**< 1: impact_x is the leading corner's (a test's impact point at an angle) */
    double start_gap;        /**< distance from the front face to the cable line at t = 0, m */
    double dt;               /**< time step, s */
    double t_end;            /**< time limit, s */
    double output_interval;  /**< recording interval, s (0: every step) */
    double crush_tolerance;  /**< relative change of face force that ends the crush iteration (paper: 0.05) */
    double solver_tolerance; /**< relative residual of the quasi-static barrier solve */
    int solver_max_sweeps;   /**< cap on Gauss-Seidel sweeps of the barrier solve in one step */
    double solve_budget;     /**< barrier solves a run may make, per step to t_end on average (0: 20), and
                                their work (100 passes over the barrier's unknowns a solve); past either
                                the run ends "did not converge" with what it has */
    double stop_speed;       /**< forward speed below which the vehicle counts as stopped, m/s: at most
                                CS_STOP_SPEED_SHARE of speed */
    double gravity;          /**< m/s^2 */
    double max_steps; /**< steps a run may take (0: CS_MAX_STEPS_DEFAULT, 10 million); past them the run
                         ends "step_limit" */
} cs_scenario_def;

/** Where a vehicle whose front face is front_width wide meets the cable line (y = 0) at the scenario's angle
 * (between 0 and pi): the x of the face's centre in *centre and of its leading front corner in *corner, m
 * (impact_x is one or the other, as impact_at_corner says; they lie (w/2) / sin(angle) apart along the line).
 * Either pointer may be NULL. */
CS_API void cs_scenario_impact_points(const cs_scenario_def *scenario, double front_width, double *centre,
                                      double *corner);

/** The largest stop speed against the impact speed: a vehicle at a tenth of its speed keeps 1% of its kinetic
 * energy, where a larger threshold would call a vehicle still moving stopped. */
#define CS_STOP_SPEED_SHARE 0.1

/** The steps a run may take when scenario.max_steps is 0. */
#define CS_MAX_STEPS_DEFAULT 1.0e7

/** An empty initialiser that zeroes a whole struct in C and in C++ alike, without a warning in either. */
/* clang-format off */
#ifdef __cplusplus
#define CS_ZERO_INIT {}
#else
#define CS_ZERO_INIT {0}
#endif
/* clang-format on */

/** The post-in-soil model's two calibrated values (docs/assumptions.md, docs/theory.md): fitted on the odd
 * bogie tests (NPGB-1, 3, 5, 7, 9), checked on the even ones. They may be set when building, for a
 * calibration study: the library built so gives them to the models it loads, a program's
 * cs_default_footing_def() the values it was compiled with. */
#ifndef CS_SOIL_DYNAMIC_FACTOR
#define CS_SOIL_DYNAMIC_FACTOR 2.740
#endif
#ifndef CS_SOIL_SKIN_FRICTION
#define CS_SOIL_SKIN_FRICTION 177.5e3 /**< Pa/m */
#endif
/** The unit weight of a compacted crushed-stone base, 135 pcf (docs/assumptions.md), N/m^3. */
#define CS_SOIL_UNIT_WEIGHT (135.0 * CS_LBF / (CS_FT * CS_FT * CS_FT))

/** A rope with the paper's law (Fig. 3) and no size: area, modulus and strength are design data. */
static inline cs_rope_def cs_default_rope_def(void) {
    cs_rope_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.elastic_limit_ratio = 0.6;     /* paper: the modulus drops at 60% of nominal strength */
    d.secondary_modulus_ratio = 0.6; /* paper: "reduced by 40%" */
    d.breaking_strain = 0.03;        /* paper's 0.03 read as a strain (model-notes.md) */
    return d;
}
/** A cable with the documented defaults (friction, clips) and cs_default_rope_def's rope. */
static inline cs_cable_def cs_default_cable_def(void) {
    cs_cable_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.post_friction = 0.15;               /* steel rope in a steel hole, docs/assumptions.md */
    d.termination = CS_TERMINATION_CLIPS; /* cable clamps, as APS3's: docs/assumptions.md */
    d.ends[0].termination = d.ends[1].termination = CS_TERMINATION_AS_CABLE;
    d.rope = cs_default_rope_def();
    return d;
}
/** A section with steel's modulus and no size. */
static inline cs_section_def cs_default_section_def(void) {
    cs_section_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.modulus = 200e9;
    return d;
}
/** A footing with Eq. 21's coefficients, the 8000-psf cap on the soil pressure, the calibrated soil factors
 * and a 45-degree rotation limit (docs/assumptions.md); its size and soil pressure are design data. */
static inline cs_footing_def cs_default_footing_def(void) {
    cs_footing_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.soil_pressure_cap = 8000.0 * CS_PSF; /* paper: S1 at most 8000 psf under dynamic load */
    d.coeff_depth = 2.37;                  /* paper's Eq. 21 */
    d.coeff_height = 2.64;
    d.rotation_limit = CS_PI / 4.0;
    d.dynamic_factor = CS_SOIL_DYNAMIC_FACTOR; /* calibrated on the bogie tests: docs/assumptions.md */
    d.friction_angle = 42.0 * CS_PI / 180.0;   /* compacted crushed-stone base (AASHTO M147 B): 40-45 deg */
    d.residual_friction_angle = 33.0 * CS_PI / 180.0; /* critical state of quartz sand (Bolton 1986) */
    d.skin_friction = CS_SOIL_SKIN_FRICTION;          /* same */
    d.unit_weight = CS_SOIL_UNIT_WEIGHT;              /* compacted crushed-stone base: 135 pcf */
    return d;
}
/** A post threaded by the cables, struck over until its top comes down to the pushing edge (no rotation
 * limit of its own), its section and footing the defaults. */
static inline cs_post_def cs_default_post_def(void) {
    cs_post_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.section = cs_default_section_def();
    d.footing = cs_default_footing_def();
    d.attachment = CS_ATTACH_THROUGH;
    d.rotation_limit = CS_PI / 2.0; /* none: the edge rides over its top (docs/theory.md, "Struck posts") */
    return d;
}
/** An anchor with cs_default_footing_def's footing, of diameter 0: rigid until its footing is given. */
static inline cs_anchor_def cs_default_anchor_def(void) {
    cs_anchor_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.footing = cs_default_footing_def();
    return d;
}
/** A rail with steel's modulus and no size. */
static inline cs_rail_def cs_default_rail_def(void) {
    cs_rail_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.modulus = 200e9;
    return d;
}
/** An empty barrier: no cables, posts or rails, default anchors. */
static inline cs_barrier_def cs_default_barrier_def(void) {
    cs_barrier_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.start_anchor = cs_default_anchor_def();
    d.end_anchor = cs_default_anchor_def();
    return d;
}
/** A vehicle with the documented tyre, friction and crush-unloading defaults; its mass, sizes and crush
 * curve are design data. */
static inline cs_vehicle_def cs_default_vehicle_def(void) {
    cs_vehicle_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.tyre_static_deflection = 0.05;
    d.tyre_damping_ratio = 0.3;
    d.rolling_resistance = 0.01;
    d.tyre_friction = 0.7;
    d.face_friction = 0.3;
    d.crush_unload_stiffness = 2.0e7;
    d.wheel_radius = 0.4;
    return d;
}
/** Where the vehicle's wheels touch the ground when it stands level, in its own axes from the CG (x
 * forward, y to its left, z up), m: front left, front right, rear left, rear right. */
CS_API void cs_vehicle_wheel_points(const cs_vehicle_def *vehicle, double wheel[4][3]);
/** A head-on attack from 0.05 m before the cables with a 0.5-ms step to 3 s, outputs every 1 ms, the
 * documented tolerances and standard gravity; its speed and impact point are design data. */
static inline cs_scenario_def cs_default_scenario_def(void) {
    cs_scenario_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.angle = CS_PI / 2.0;
    d.start_gap = 0.05;
    d.dt = 0.5e-3;
    d.t_end = 3.0;
    d.output_interval = 1e-3;
    d.crush_tolerance = 0.05;
    d.solver_tolerance = 1e-4;
    d.solver_max_sweeps = 300;
    d.stop_speed = 0.05;
    d.gravity = CS_G0;
    return d;
}

#ifdef __cplusplus
}
#endif
#endif
