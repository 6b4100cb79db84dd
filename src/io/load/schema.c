/* SPDX-License-Identifier: MIT */
#include "schema.h"

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define N(a) ((int)(sizeof(a) / sizeof((a)[0])))
/* Field builders: quantity, text, sub-table. */
#define QTY(key, q, flags, type, member, doc)                                                                \
    { key, CS_F_QTY, q, flags, (long)offsetof(type, member), NULL, NULL, doc }
#define QTY_ONLY(key, q, flags, doc)                                                                         \
    { key, CS_F_QTY, q, flags, -1, NULL, NULL, doc }
#define TEXT(key, flags, doc)                                                                                \
    { key, CS_F_TEXT, CS_Q_NUMBER, flags, -1, NULL, NULL, doc }
#define LIST(key, q, flags, doc)                                                                             \
    { key, CS_F_LIST, q, flags, -1, NULL, NULL, doc }
#define SUB(key, kind, flags, offset, table, doc)                                                            \
    { key, kind, CS_Q_NUMBER, flags, offset, &table, NULL, doc }

static const char *const attachment_words[] = {"through", "clamped", "slot", "hook",
                                               "keyway",  "bracket", NULL};
static const char *const face_words[] = {"attack", "protected", NULL};
static const char *const impact_at_words[] = {"centre", "corner", NULL};
static const char *const termination_words[] = {"clips", "swaged", "spelter", "wedge", NULL};
static const char *const width_scaling_words[] = {"wedge", "none", NULL};

const char *cs_width_scaling_word(cs_width_scaling kind) {
    return kind >= CS_WIDTH_WEDGE && kind <= CS_WIDTH_NONE ? width_scaling_words[kind] : "?";
}

const char *cs_face_word(cs_face face) {
    return face >= CS_FACE_ATTACK && face <= CS_FACE_PROTECTED ? face_words[face] : "?";
}

const char *cs_attachment_word(cs_attachment kind) {
    return kind >= CS_ATTACH_THROUGH && kind <= CS_ATTACH_BRACKET ? attachment_words[kind] : "?";
}

const char *cs_termination_word(cs_termination kind) {
    return kind >= CS_TERMINATION_CLIPS && kind <= CS_TERMINATION_WEDGE ? termination_words[kind] : "?";
}

#define NAMED_PART(what)                                                                                     \
    TEXT("name", 0, "the part's name, by which other parts and models use it (in a parts list: required)"),  \
        TEXT("description", 0, "what the part is and where its numbers come from"),                          \
        TEXT("part", 0, "start from the named " what " part; the fields given here replace its fields")

static const cs_field box_fields[] = {
    QTY_ONLY("length", CS_Q_LENGTH, CS_REQ | CS_POS, "box length (x, along travel)"),
    QTY_ONLY("width", CS_Q_LENGTH, CS_REQ | CS_POS, "box width (y)"),
    QTY_ONLY("height", CS_Q_LENGTH, CS_REQ | CS_POS, "box height (z)"),
};
const cs_table cs_table_box = {
    "inertia_box",
    "A uniform box of the vehicle's mass whose moments of inertia "
    "give each of roll/pitch/yaw_inertia not given on its own: roll m(W^2+H^2)/12, "
    "pitch m(L^2+H^2)/12, yaw m(L^2+W^2)/12.",
    CS_T_NONE, box_fields, N(box_fields)};

#define V(key, q, flags, member, doc) QTY(key, q, flags, cs_vehicle_def, member, doc)
static const cs_field vehicle_fields[] = {
    NAMED_PART("vehicle"),
    TEXT("file", 0, "take the vehicle of another model file (path relative to this file)"),
    V("mass", CS_Q_MASS, CS_REQ | CS_POS, mass, "total mass"),
    V("roll_inertia", CS_Q_INERTIA, CS_POS, inertia[0], "Ixx about the CG (or give inertia_box)"),
    V("pitch_inertia", CS_Q_INERTIA, CS_POS, inertia[1], "Iyy about the CG (or give inertia_box)"),
    V("yaw_inertia", CS_Q_INERTIA, CS_POS, inertia[2], "Izz about the CG (or give inertia_box)"),
    SUB("inertia_box", CS_F_MAP, 0, -1, cs_table_box,
        "inertia of a uniform box for any of the three above not given"),
    V("cg_height", CS_Q_LENGTH, CS_REQ | CS_POS, cg_height, "CG above grade at rest"),
    V("cg_to_front", CS_Q_LENGTH, CS_REQ | CS_POS, cg_to_front, "CG to the undeformed front face"),
    V("front_width", CS_Q_LENGTH, CS_REQ | CS_POS, front_width, "width of the front face"),
    V("face_bottom", CS_Q_LENGTH, CS_REQ | CS_NONNEG, face_bottom, "lowest point of the front face (bumper)"),
    V("face_top", CS_Q_LENGTH, CS_REQ | CS_POS, face_top, "top of the front face (hood edge)"),
    V("front_to_cargo_bed", CS_Q_LENGTH, CS_NONNEG, front_to_cargo_bed,
      "front face to the front of the cargo bed (penetration ratings)"),
    V("cg_to_rear", CS_Q_LENGTH, CS_REQ | CS_POS, cg_to_rear, "CG to the rear end of the body"),
    V("side_bottom", CS_Q_LENGTH, CS_REQ | CS_NONNEG, side_bottom,
      "lowest point of the sides a cable bears on (sill, rocker panel)"),
    V("side_top", CS_Q_LENGTH, CS_REQ | CS_POS, side_top, "top of the sides (bed rail, belt line)"),
    V("wheelbase", CS_Q_LENGTH, CS_REQ | CS_POS, wheelbase, "front axle to rear axle (group centre)"),
    V("cg_to_front_axle", CS_Q_LENGTH, CS_REQ | CS_POS, cg_to_front_axle, "CG behind the front axle"),
    V("track", CS_Q_LENGTH, CS_REQ | CS_POS, track, "distance between the left and right wheels"),
    V("tyre_static_deflection", CS_Q_LENGTH, CS_POS, tyre_static_deflection,
      "tyre deflection under the static load; sets the tyre stiffness"),
    V("wheel_radius", CS_Q_LENGTH, CS_POS, wheel_radius,
      "unloaded tyre radius; a front tyre takes a rope that passes under the bumper above its axle"),
    V("rim_radius", CS_Q_LENGTH, CS_NONNEG, rim_radius,
      "the wheel's rim, half the rim diameter of the tyre's size: a tyre pressed down by wheel_radius - "
      "rim_radius bottoms on its rim (0 or not given: no rim, the tyre takes any compression)"),
    V("tyre_damping_ratio", CS_Q_NUMBER, CS_NONNEG, tyre_damping_ratio, "tyre damping, fraction of critical"),
    V("rolling_resistance", CS_Q_NUMBER, CS_NONNEG, rolling_resistance, "rolling resistance coefficient"),
    V("tyre_friction", CS_Q_NUMBER, CS_NONNEG, tyre_friction, "tyre side (lateral) friction coefficient"),
    V("face_friction", CS_Q_NUMBER, CS_NONNEG, face_friction, "friction between cable and the body"),
    LIST("crush_deformation", CS_Q_LENGTH, CS_REQ | CS_NONNEG,
         "crush curve: deformations, increasing, first 0 (at most 16 points)"),
    LIST("crush_force", CS_Q_FORCE, CS_NONNEG, "crush curve: forces at those deformations, first 0"),
    LIST("crush_force_fraction", CS_Q_NUMBER, CS_NONNEG,
         "crush curve as fractions of Fmax, instead of crush_force; Fmax from crush_fit_speed"),
    QTY_ONLY("crush_fit_speed", CS_Q_SPEED, CS_POS,
             "with crush_force_fraction: Fmax makes the area under the curve up to crush_fit_depth equal the "
             "kinetic energy at this speed (rigid-wall test)"),
    QTY_ONLY("crush_fit_depth", CS_Q_LENGTH, CS_POS, "with crush_fit_speed: the deformation of that test"),
    V("crush_unload_stiffness", CS_Q_STIFFNESS, CS_POS, crush_unload_stiffness,
      "unloading slope of the crush curve (crush is permanent)"),
};
const cs_table cs_table_vehicle = {"vehicle", "A vehicle: rigid body with a crushable front face.",
                                   CS_T_VEHICLE, vehicle_fields, N(vehicle_fields)};

#define R(key, q, flags, member, doc) QTY(key, q, flags, cs_rope_def, member, doc)
static const cs_field rope_fields[] = {
    TEXT("name", 0, "the part's name, by which cables use it (in a parts list: required)"),
    TEXT("description", 0, "what the rope is and where its numbers come from"),
    TEXT("scale_from", 0,
         "start from the named rope and scale area, strength and mass per length by "
         "(diameter / its diameter)^2; fields given here replace the result"),
    QTY_ONLY("diameter", CS_Q_LENGTH, CS_POS,
             "nominal diameter d (needed by scale_from); sets the efficiency of clips at its ends"),
    R("area", CS_Q_AREA, CS_REQ | CS_POS, area, "metallic area A"),
    R("modulus", CS_Q_PRESSURE, CS_REQ | CS_POS, modulus, "apparent modulus of elasticity E"),
    R("nominal_strength", CS_Q_FORCE, CS_REQ | CS_POS, nominal_strength, "nominal (breaking) strength Fu"),
    R("elastic_limit_ratio", CS_Q_NUMBER, CS_POS | CS_MAX1, elastic_limit_ratio,
      "end of the first slope as a fraction of Fu"),
    R("secondary_modulus_ratio", CS_Q_NUMBER, CS_POS | CS_MAX1, secondary_modulus_ratio,
      "second slope as a fraction of E"),
    R("breaking_strain", CS_Q_NUMBER, CS_POS, breaking_strain, "total strain at which the rope breaks"),
    R("mass_per_length", CS_Q_MASS_PER_LENGTH, CS_NONNEG, mass_per_length,
      "mass per length: the spans sag under their own weight (0: weightless rope)"),
};
const cs_table cs_table_rope = {"rope", "A wire rope: the paper's tension-strain law.", CS_T_ROPE,
                                rope_fields, N(rope_fields)};

#define S(key, q, flags, member, doc) QTY(key, q, flags, cs_section_def, member, doc)
static const cs_field section_fields[] = {
    NAMED_PART("section"),
    S("plastic_modulus", CS_Q_SECTION_MODULUS, CS_REQ | CS_POS, plastic_modulus, "plastic modulus Zx"),
    S("inertia", CS_Q_SECOND_MOMENT, CS_REQ | CS_POS, inertia, "second moment of area Ix"),
    S("web_area", CS_Q_AREA, CS_REQ | CS_POS, web_area, "shear area Aw"),
    S("yield_stress", CS_Q_PRESSURE, CS_POS, yield_stress, "yield stress Fy"),
    S("modulus", CS_Q_PRESSURE, CS_POS, modulus, "Young's modulus E"),
    S("mass_per_length", CS_Q_MASS_PER_LENGTH, CS_NONNEG, mass_per_length,
      "mass per length: the post swings with it (0: a massless post)"),
    S("width", CS_Q_LENGTH, CS_POS | CS_NEW0, width,
      "a rectangular tube's outer width across the bending axis (a post may fill it: fill_strength)"),
    S("depth", CS_Q_LENGTH, CS_POS | CS_NEW0, depth,
      "a rectangular tube's outer depth in the plane of bending"),
    S("wall", CS_Q_LENGTH, CS_POS | CS_NEW0, wall, "a rectangular tube's design wall thickness"),
};
const cs_table cs_table_section = {"section", "A steel post section (strong axis).", CS_T_SECTION,
                                   section_fields, N(section_fields)};

#define RL(key, q, flags, member, doc) QTY(key, q, flags, cs_rail_def, member, doc)
#define RAIL_SECTION_FIELDS(req)                                                                             \
    RL("area", CS_Q_AREA, req | CS_POS, area, "steel area A"),                                               \
        RL("inertia", CS_Q_SECOND_MOMENT, req | CS_POS, inertia,                                             \
           "second moment of area about its weaker axis"),                                                   \
        RL("yield_stress", CS_Q_PRESSURE, req | CS_POS, yield_stress, "yield stress Fy"),                    \
        RL("modulus", CS_Q_PRESSURE, CS_POS, modulus, "Young's modulus E"),                                  \
        RL("mass_per_length", CS_Q_MASS_PER_LENGTH, CS_NONNEG, mass_per_length,                              \
           "mass per length: half of each span swings with each of its posts")
static const cs_field rail_part_fields[] = {NAMED_PART("rail"), RAIL_SECTION_FIELDS(CS_REQ)};
const cs_table cs_table_rail_part = {"rail_section",
                                     "A rail's section: the member that ties neighbouring posts.", CS_T_RAIL,
                                     rail_part_fields, N(rail_part_fields)};

static const cs_field parts_fields[] = {
    SUB("vehicles", CS_F_SEQ, 0, -1, cs_table_vehicle, "named vehicles"),
    SUB("ropes", CS_F_SEQ, 0, -1, cs_table_rope, "named wire ropes"),
    SUB("sections", CS_F_SEQ, 0, -1, cs_table_section, "named post sections"),
    SUB("rails", CS_F_SEQ, 0, -1, cs_table_rail_part, "named rail sections"),
};
const cs_table cs_table_parts = {"parts",
                                 "Named parts defined in this file, used by name like the library's "
                                 "(a name here hides the library's).",
                                 CS_T_NONE, parts_fields, N(parts_fields)};

#define FT(key, q, flags, member, doc) QTY(key, q, flags, cs_footing_def, member, doc)
#define SOIL_FIELDS                                                                                          \
    FT("soil_pressure", CS_Q_PRESSURE, CS_POS, soil_pressure,                                                \
       "S1 of Eq. 21: soil pressure above the point of rotation"),                                           \
        FT("soil_pressure_cap", CS_Q_PRESSURE, CS_POS, soil_pressure_cap, "upper limit of S1"),              \
        FT("coeff_depth", CS_Q_NUMBER, CS_POS, coeff_depth, "Eq. 21 coefficient of P D"),                    \
        FT("coeff_height", CS_Q_NUMBER, CS_POS, coeff_height, "Eq. 21 coefficient of P H"),                  \
        FT("dynamic_factor", CS_Q_NUMBER, CS_POS, dynamic_factor,                                            \
           "soil resistance under impact over Eq. 21's, 1 to 10 (calibrated on the bogie tests)"),           \
        FT("skin_friction", CS_Q_PRESSURE_GRADIENT, CS_POS, skin_friction,                                   \
           "shaft friction per depth; a footing without a pullout capacity pulls out at pi B D^2 / 2 times " \
           "it"),                                                                                            \
        FT("friction_angle", CS_Q_ANGLE, CS_POS | CS_MAX90, friction_angle,                                  \
           "the soil's angle of friction: scales the dynamic factor to a footing's width (passive wedge)"),  \
        FT("residual_friction_angle", CS_Q_ANGLE, CS_POS | CS_MAX90, residual_friction_angle,                \
           "the soil's critical-state angle of friction: the resistance an anchor keeps ploughing past its " \
           "peak"),                                                                                          \
        FT("unit_weight", CS_Q_PRESSURE_GRADIENT, CS_POS, unit_weight,                                       \
           "the soil's unit weight (weight per volume, e.g. 135 lbf/ft^3): the passive wedge a moving "      \
           "anchor carries"),                                                                                \
    {                                                                                                        \
        "width_scaling", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_footing_def, width_scaling), NULL,     \
            width_scaling_words,                                                                             \
            "how the dynamic factor carries to a footing's width: wedge (the passive wedge's width effect) " \
            "or "                                                                                            \
            "none (the bogie post's factor at any width)"                                                    \
    }
static const cs_field soil_fields[] = {SOIL_FIELDS};
const cs_table cs_table_soil = {"soil",
                                "Soil of every footing of the barrier (a footing may replace any of it).",
                                CS_T_FOOTING, soil_fields, N(soil_fields)};

static const cs_field footing_fields[] = {
    FT("diameter", CS_Q_LENGTH, CS_REQ | CS_POS, diameter,
       "B: width facing the soil (a round footing's diameter; a rectangular one's side facing the load)"),
    FT("depth", CS_Q_LENGTH, CS_REQ | CS_POS, depth, "D: embedment depth"),
    SOIL_FIELDS,
    FT("rotation_limit", CS_Q_ANGLE, CS_POS | CS_MAX90, rotation_limit,
       "footing rotation at which a post turning in the soil that the vehicle pushes over lets it ride over "
       "(a post carrying ropes folds on until its top reaches grade)"),
    FT("pullout_capacity", CS_Q_FORCE, CS_POS | CS_NONE_OK, pullout_capacity,
       "axial pull along the post that pulls it out (none: never; omitted: the skin friction's)"),
};
const cs_table cs_table_footing = {"footing", "A post's footing in the soil (Eq. 21 lateral capacity).",
                                   CS_T_FOOTING, footing_fields, N(footing_fields)};

#define TERMINATION_DOC                                                                                      \
    "clips (cable clamps; 80% of the rope's strength below 1 in, 90% from 1 in), swaged (95%), spelter "     \
    "(100%) or wedge (85%)"
static const cs_field cable_end_fields[] = {
    {"termination", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_cable_end_def, termination), NULL,
     termination_words, "the fitting at this end (not given: the cable's termination): " TERMINATION_DOC},
    QTY("termination_efficiency", CS_Q_NUMBER, CS_POS | CS_MAX1, cs_cable_end_def, termination_efficiency,
        "its strength over the rope's, replacing its kind's (not given: its kind's, or the cable's "
        "termination_efficiency where this end takes the cable's termination)"),
    QTY("slip_load", CS_Q_FORCE, CS_POS, cs_cable_end_def, slip_load,
        "end span tension at which the rope slips through this end's fitting (not given: the cable's "
        "where this end takes the cable's termination, else none)"),
    QTY("slip_travel", CS_Q_LENGTH, CS_POS, cs_cable_end_def, slip_travel,
        "rope this end's fitting lets slip before the rope runs out of it (not given: the cable's)"),
};
const cs_table cs_table_cable_end = {"cable_end",
                                     "The fitting at one end of a cable, where it is not the cable's own "
                                     "`termination`.",
                                     CS_T_NONE, cable_end_fields, N(cable_end_fields)};

static const cs_field cable_fields[] = {
    TEXT("rope", CS_REQ, "name of a rope part"),
    QTY("height", CS_Q_LENGTH, CS_REQ | CS_POS, cs_cable_def, height, "height of the cable at the posts"),
    QTY("pretension", CS_Q_FORCE, CS_NONNEG, cs_cable_def, pretension, "installed tension"),
    QTY("post_friction", CS_Q_NUMBER, CS_NONNEG, cs_cable_def, post_friction,
        "friction between cable and post (capstan at a threaded post)"),
    {"termination", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_cable_def, termination), NULL,
     termination_words, "the fitting at both ends, unless start or end gives its own: " TERMINATION_DOC},
    QTY("termination_efficiency", CS_Q_NUMBER, CS_POS | CS_MAX1, cs_cable_def, termination_efficiency,
        "the fitting's strength over the rope's, replacing its kind's at the ends that take termination"),
    QTY("slip_load", CS_Q_FORCE, CS_POS, cs_cable_def, slip_load,
        "end span tension at which the rope slips through the fittings at the ends that take termination "
        "(clips, clamps; not given: they hold to their strength, as correctly made clips do); needs "
        "slip_travel"),
    QTY("slip_travel", CS_Q_LENGTH, CS_POS, cs_cable_def, slip_travel,
        "rope a fitting lets slip before the rope runs out of it (a clip's turn-back)"),
    QTY("hole_efficiency", CS_Q_NUMBER, CS_POS | CS_MAX1, cs_cable_def, hole_efficiency,
        "the rope's strength over its own where it runs through a hole at a threaded post: it breaks there "
        "when a span on the post passes it (not given: no loss at the holes)"),
    SUB("start", CS_F_MAP, CS_OWN, (long)offsetof(cs_cable_def, ends[0]), cs_table_cable_end,
        "the fitting at the start anchor (low x), where not the cable's"),
    SUB("end", CS_F_MAP, CS_OWN, (long)offsetof(cs_cable_def, ends[1]), cs_table_cable_end,
        "the fitting at the end anchor (high x), where not the cable's"),
    QTY("elastic_limit_ratio", CS_Q_NUMBER, CS_POS | CS_MAX1, cs_cable_def, rope.elastic_limit_ratio,
        "replaces the rope's"),
    QTY("secondary_modulus_ratio", CS_Q_NUMBER, CS_POS | CS_MAX1, cs_cable_def, rope.secondary_modulus_ratio,
        "replaces the rope's"),
    QTY("breaking_strain", CS_Q_NUMBER, CS_POS, cs_cable_def, rope.breaking_strain, "replaces the rope's"),
};
const cs_table cs_table_cable = {"cable",
                                 "One cable, from the start anchor to the end anchor through every post.",
                                 CS_T_CABLE, cable_fields, N(cable_fields)};

#define P(key, q, flags, member, doc) QTY(key, q, flags, cs_post_def, member, doc)
static const cs_field posts_fields[] = {
    TEXT("name", 0, "a label for the group (\"line posts\")"),
    LIST("x", CS_Q_LENGTH, 0, "posts one by one: their positions along the barrier"),
    QTY_ONLY("from", CS_Q_LENGTH, 0, "a run of posts: position of the first"),
    QTY_ONLY("to", CS_Q_LENGTH, 0, "a run: position of the last (or give up_to or count)"),
    QTY_ONLY(
        "up_to", CS_Q_LENGTH, 0,
        "a run: the last post at or before this position, as many spacings as fit (a study over spacing)"),
    QTY_ONLY("spacing", CS_Q_LENGTH, CS_POS, "a run: distance between posts"),
    {"count", CS_F_INT, CS_Q_NUMBER, CS_POS, -1, NULL, NULL, "a run: number of posts (or give to or up_to)"},
    LIST("except", CS_Q_LENGTH, 0, "a run: positions left out (other groups' posts stand there)"),
    P("height", CS_Q_LENGTH, CS_REQ | CS_POS, height, "top of the post above grade"),
    TEXT("section", CS_REQ, "name of a section part"),
    P("yield_stress", CS_Q_PRESSURE, CS_POS, section.yield_stress, "replaces the section's Fy"),
    P("modulus", CS_Q_PRESSURE, CS_POS, section.modulus, "replaces the section's E"),
    P("mass_per_length", CS_Q_MASS_PER_LENGTH, CS_NONNEG, section.mass_per_length,
      "replaces the section's mass per length (a filled tube: steel and fill)"),
    P("fill_strength", CS_Q_PRESSURE, CS_POS | CS_NEW0, section.fill_strength,
      "f'c of the concrete filling a tube section (3-10 ksi, compact walls): it adds to the plastic moment "
      "and the stiffness (AISC 360-16 I1.2a, Eq. I2-15)"),
    SUB("footing", CS_F_MAP, CS_REQ, (long)offsetof(cs_post_def, footing), cs_table_footing, "the footing"),
    {"attachment", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_post_def, attachment), NULL, attachment_words,
     "how the cables hold to the post: through (threaded, sliding with friction), clamped, slot (stacked in "
     "a slot open at the top, let go as the post bends over), hook (hook bolts that open), keyway (keyway "
     "bolts) or bracket (tabbed brackets): keyway bolts and brackets also let go when pulled off their face"},
    P("release_force", CS_Q_FORCE, CS_POS, release_force,
      "a slot's, hook's, keyway bolt's or bracket's retainer strength along the post (not given: the kind's "
      "documented value)"),
    P("rotation_limit", CS_Q_ANGLE, CS_POS | CS_MAX90, rotation_limit,
      "rotation past which a post hinged at grade that the vehicle pushes over lets it go (90 deg: none; it "
      "goes when its top comes down to the pushing edge; a post carrying ropes folds on until its top "
      "reaches "
      "grade)"),
    P("lateral_release_force", CS_Q_FORCE, CS_POS, lateral_release_force,
      "a keyway bolt's or bracket's strength against a pull off its face (not given: the kind's documented "
      "value; other kinds: left out)"),
    {"face", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_post_def, face), NULL, face_words,
     "the face of the post keyway bolts or brackets are fixed to: attack (the side the vehicle comes from, "
     "the default) or protected (other kinds: left out)"},
};
const cs_table cs_table_posts = {"posts",
                                 "A group of identical posts: one by one (x) or as a run (from, "
                                 "spacing, to or count).",
                                 CS_T_POST, posts_fields, N(posts_fields)};

static const cs_field anchor_fields[] = {
    QTY("x", CS_Q_LENGTH, CS_REQ, cs_anchor_def, x, "position along the barrier"),
    QTY("z", CS_Q_LENGTH, CS_NONNEG, cs_anchor_def, z, "height where the cables are tied"),
    SUB("footing", CS_F_MAP, 0, (long)offsetof(cs_anchor_def, footing), cs_table_footing,
        "the dead-man in the soil: its width facing the pull (diameter) and depth; not given: a rigid "
        "anchor"),
    QTY("length", CS_Q_LENGTH, CS_POS, cs_anchor_def, length,
        "a block's plan size along the pull (footing.diameter is the face against it; not given: a round "
        "shaft)"),
    QTY("mass", CS_Q_MASS, CS_POS, cs_anchor_def, mass,
        "the footing's own (not given: its concrete); the soil's wedge moves with it too"),
    QTY("pullout_capacity", CS_Q_FORCE, CS_POS | CS_NONE_OK, cs_anchor_def, pullout_capacity,
        "uplift that pulls it out (none: never; not given: its weight and skin friction)"),
};
static const cs_field rail_fields[] = {
    TEXT("rail", CS_REQ, "name of a rail section part"),
    RL("height", CS_Q_LENGTH, CS_REQ | CS_POS, height, "height above grade"),
    RAIL_SECTION_FIELDS(0),
};
const cs_table cs_table_rail = {
    "rail",
    "A horizontal rail tying each pair of neighbouring posts at one height: an axial "
    "member over each span, yielding in tension and buckling in compression.",
    CS_T_RAIL, rail_fields, N(rail_fields)};

const cs_table cs_table_anchor = {
    "anchor",
    "A cable end anchor: a footing (dead-man) in the soil that resists the ropes' "
    "pull by Eq. 21 at their height, ploughs through the soil past it at a residual "
    "resistance, and pulls out only when the ropes lift it past its uplift capacity.",
    CS_T_ANCHOR, anchor_fields, N(anchor_fields)};

static const cs_field anchors_fields[] = {
    SUB("start", CS_F_MAP, CS_REQ, (long)offsetof(cs_barrier_def, start_anchor), cs_table_anchor,
        "the anchor at the low-x end"),
    SUB("end", CS_F_MAP, CS_REQ, (long)offsetof(cs_barrier_def, end_anchor), cs_table_anchor,
        "the anchor at the high-x end"),
};
const cs_table cs_table_anchors = {"anchors", "The two cable end anchors.", CS_T_BARRIER, anchors_fields,
                                   N(anchors_fields)};

static const cs_field barrier_fields[] = {
    TEXT("file", 0, "take the barrier of another model file; the fields given here replace its fields"),
    SUB("soil", CS_F_MAP, 0, -1, cs_table_soil, "soil of every footing"),
    SUB("cables", CS_F_SEQ, CS_REQ, -1, cs_table_cable, "the cables"),
    SUB("posts", CS_F_SEQ, CS_REQ, -1, cs_table_posts, "groups of posts"),
    SUB("rails", CS_F_SEQ, 0, -1, cs_table_rail,
        "rails tying neighbouring posts (none: posts free of each other)"),
    SUB("anchors", CS_F_MAP, CS_REQ, 0, cs_table_anchors, "the end anchors"),
};
const cs_table cs_table_barrier = {"barrier",
                                   "The cable barrier. Frame: x along the barrier, y the direction "
                                   "of attack, z up from grade.",
                                   CS_T_BARRIER, barrier_fields, N(barrier_fields)};

#define SC(key, q, flags, member, doc) QTY(key, q, flags, cs_scenario_def, member, doc)
static const cs_field scenario_fields[] = {
    TEXT("file", 0, "take the scenario of another model file; the fields given here replace its fields"),
    SC("speed", CS_Q_SPEED, CS_REQ | CS_POS, speed, "vehicle speed at first contact"),
    SC("angle", CS_Q_ANGLE, CS_POS | CS_MAX180, angle, "between barrier line and travel (90 deg: head-on)"),
    SC("impact_x", CS_Q_LENGTH, CS_REQ, impact_x,
       "where the centre of the front face meets the cable line (or the leading corner: impact_at)"),
    {"impact_at", CS_F_ENUM, CS_Q_NUMBER, 0, (long)offsetof(cs_scenario_def, impact_at_corner), NULL,
     impact_at_words,
     "what impact_x locates: centre (of the front face) or corner (the leading front corner, a test's impact "
     "point at an angle). Either way the leading corner must meet the cable line between the anchors: at a "
     "shallow angle a face aimed by its centre meets it (w / 2) / sin(angle) earlier (22.9 m at 3 deg for a "
     "2.4-m face), and a model whose corner would meet it past the barrier's end is refused"},
    SC("start_gap", CS_Q_LENGTH, CS_NONNEG, start_gap, "front face to the cable line at t = 0"),
    SC("dt", CS_Q_TIME, CS_POS, dt, "time step"),
    SC("t_end", CS_Q_TIME, CS_POS, t_end, "time limit"),
    SC("output_interval", CS_Q_TIME, CS_NONNEG, output_interval,
       "recording interval (0, or the default below dt: every step; if given, at least dt; at most a million "
       "frames to t_end)"),
    SC("crush_tolerance", CS_Q_NUMBER, CS_POS, crush_tolerance,
       "relative change that ends the crush iteration"),
    SC("solver_tolerance", CS_Q_NUMBER, CS_POS, solver_tolerance, "relative residual of the barrier solve"),
    SC("solve_budget", CS_Q_NUMBER, CS_POS, solve_budget,
       "barrier solves a run may make, per step to t_end on average (default 20), each worth 100 passes "
       "over the barrier's unknowns in work (docs/theory.md, Bounded work); past either the run ends "
       "did_not_converge"),
    SC("max_steps", CS_Q_NUMBER, CS_POS | CS_NEW0, max_steps,
       "steps a run may take (default 10 million, which no sensible run reaches); past them the run ends "
       "step_limit"),
    {"solver_max_sweeps", CS_F_INT, CS_Q_NUMBER, CS_POS, (long)offsetof(cs_scenario_def, solver_max_sweeps),
     NULL, NULL, "cap on the barrier solve's sweeps in one step"},
    SC("stop_speed", CS_Q_SPEED, CS_NONNEG, stop_speed,
       "forward speed below which the vehicle has stopped; at most a tenth of speed"),
    SC("gravity", CS_Q_ACCELERATION, CS_NONNEG, gravity, "acceleration of gravity"),
};
const cs_table cs_table_scenario = {"scenario", "The attack and how to integrate it.", CS_T_SCENARIO,
                                    scenario_fields, N(scenario_fields)};

static const cs_field model_fields[] = {
    TEXT("name", 0,
         "the model's name, its output folder results/NAME (no '/', '..', leading '.' or control character); "
         "default: the file name"),
    TEXT("description", 0, "what the model is"),
    SUB("parts", CS_F_MAP, 0, -1, cs_table_parts, "named parts of this file"),
    SUB("barrier", CS_F_MAP, 0, -1, cs_table_barrier, "the barrier"),
    SUB("vehicle", CS_F_PART, 0, -1, cs_table_vehicle, "the vehicle: a part's name, or a mapping"),
    SUB("scenario", CS_F_MAP, 0, -1, cs_table_scenario, "the impact"),
};
const cs_table cs_table_model = {"model",
                                 "A model file. A file to run needs barrier, vehicle and scenario; "
                                 "a file of parts (like data/*.yaml) needs only parts.",
                                 CS_T_NONE, model_fields, N(model_fields)};

/* The ranges of docs/assumptions.md ("Ranges of the inputs"): each quantity's, then the fields whose kind
 * of value is narrower or wider than their quantity's. */
static const cs_range quantity_ranges[CS_Q_COUNT] = {
    [CS_Q_NUMBER] = {1e-6, 1e6,
                     "a coefficient, ratio or factor of a barrier or vehicle lies within 10^-6 to 10^6"},
    [CS_Q_LENGTH] =
        {1e-4, 1e4,
         "no part of a barrier or vehicle is thinner than 0.1 mm, and no barrier or run is longer than "
         "10 km"},
    [CS_Q_AREA] = {1e-8, 1.0,
                   "a steel area of a rope, post or rail: 0.01 mm^2 is a thread, 1 m^2 a bridge girder"},
    [CS_Q_SECTION_MODULUS] = {1e-9, 0.1,
                              "a post's section: 1 mm^3 is a wire, 0.1 m^3 five times the largest rolled "
                              "steel shape's"},
    [CS_Q_SECOND_MOMENT] = {1e-12, 0.1,
                            "a post's or rail's section: 1 mm^4 is a wire, 0.1 m^4 ten times the largest "
                            "rolled steel shape's"},
    [CS_Q_MASS] = {10.0, 5e5, "a vehicle or an anchor block: 10 kg to 500 t (a loaded road train is 200 t)"},
    [CS_Q_MASS_PER_LENGTH] = {1e-3, 1e4,
                              "a rope, post or rail: 1 g/m is a thread, 10 t/m ten times a rail's"},
    [CS_Q_INERTIA] = {1e-3, 1e8,
                      "a road vehicle's moment of inertia: 1e8 kg m^2 is a 1,000-t body 30 m long"},
    [CS_Q_TIME] =
        {1e-8, 1e4,
         "a step below 10 ns resolves nothing the model holds (a wave in steel crosses 0.05 mm in it), "
         "and a crash is over in seconds, not hours"},
    [CS_Q_SPEED] = {1e-3, 100.0, "a road vehicle: 1 mm/s to 100 m/s (224 mph), the engine's limit"},
    [CS_Q_ACCELERATION] = {1e-3, 100.0, "gravity: 0 (none) or up to 100 m/s^2, the engine's limit"},
    [CS_Q_FORCE] = {1.0, 1e8,
                    "a rope's, post's or anchor's force: 1 N to 100 MN (the strongest barrier rope "
                    "breaks near 1 MN)"},
    [CS_Q_STIFFNESS] = {1.0, 1e12,
                        "a vehicle's crush: 1 N/m to 1 TN/m (a solid steel block is about 1e10 N/m)"},
    [CS_Q_PRESSURE] = {1.0, 2e12,
                       "a soil's or steel's stress or modulus: 1 Pa to 2 TPa (diamond's modulus is 1.1 TPa)"},
    [CS_Q_ANGLE] = {1.7e-4, 2 * 3.14159265358979323846, "an angle of 0.01 deg to a turn"},
    [CS_Q_ENERGY] = {1e-3, 1e10, "1 mJ to 10 GJ (a 100-t body at 100 m/s is 0.5 GJ)"},
    [CS_Q_PRESSURE_GRADIENT] = {1.0, 1e9, "a soil's friction per depth: 1 Pa/m to 1 GPa/m"},
};

static const struct {
    const char *key;
    cs_range range;
} field_ranges[] = {
    {"pretension",
     {100.0, 1e7,
      "a rope taut between posts: 100 N (22 lbf, a rope pulled by hand) to 10 MN; less leaves "
      "it hanging in sags the rope's own weight sets, which the model is not for"}},
    {"solver_tolerance", {1e-15, 1e6, "a relative residual: 1e-15 is double precision's"}},
    {"crush_tolerance", {1e-15, 1e6, "a relative change: 1e-15 is double precision's"}},
    {"max_steps", {1.0, 1e9, "a billion steps take days"}},
    {"dynamic_factor", {1e-3, 1e3, "soil resistance under impact over Eq. 21's: measured 1 to 10"}},
};

const cs_range *cs_field_range(const cs_field *f) {
    for (size_t i = 0; i < sizeof field_ranges / sizeof field_ranges[0]; i++)
        if (strcmp(field_ranges[i].key, f->key) == 0) return &field_ranges[i].range;
    return &quantity_ranges[f->q];
}

int cs_field_unset(const cs_field *f, const void *at) {
    if (!(f->flags & CS_OWN)) return 0;
    for (int i = 0; i < f->sub->count; i++) {
        const cs_field *g = &f->sub->fields[i];
        const char *v = (const char *)at + g->offset;
        int k = -1;
        double d = 0.0;
        if (g->kind == CS_F_ENUM)
            memcpy(&k, v, sizeof k);
        else
            memcpy(&d, v, sizeof d);
        if (k >= 0 || d != 0.0) return 0;
    }
    return 1;
}

int cs_table_find(const cs_table *t, const char *key) {
    for (int i = 0; i < t->count; i++)
        if (strcmp(t->fields[i].key, key) == 0) return i;
    return -1;
}

int cs_path_next(const char **p, char *key, size_t key_size, long *index) {
    const char *s = *p;
    if (*s == '\0') return 0;
    if (*s == '[') {
        char *end;
        errno = 0;
        long i = strtol(s + 1, &end, 10);
        if (end == s + 1 || *end != ']' || i < 0 || errno == ERANGE) return -1; /* past long: no list is */
        *index = i;
        *p = end + 1;
        if (**p == '.') ++*p;
        return 2;
    }
    size_t n = strcspn(s, ".[");
    if (n == 0 || n >= key_size) return -1;
    memcpy(key, s, n);
    key[n] = '\0';
    *p = s + n + (s[n] == '.');
    return 1;
}

void cs_schema_walk(const char *path, cs_schema_place *out) {
    memset(out, 0, sizeof *out);
    const cs_table *t = &cs_table_model;
    char key[64];
    long index;
    int rc;
    while ((rc = cs_path_next(&path, key, sizeof key, &index)) > 0) {
        out->last = *path == '\0';
        if (rc == 2) {
            if (!out->field || out->item || (out->field->kind != CS_F_SEQ && out->field->kind != CS_F_LIST)) {
                out->fault = CS_PATH_NO_LIST;
                out->index = index;
                return;
            }
            out->item = 1;
            continue;
        }
        int under_list = out->field && !out->item && out->field->kind == CS_F_SEQ;
        int i = t && !under_list ? cs_table_find(t, key) : -1;
        if (i < 0) {
            out->fault = under_list ? CS_PATH_NEEDS_INDEX : CS_PATH_UNKNOWN_KEY;
            out->table = under_list ? NULL : t;
            snprintf(out->key, sizeof out->key, "%s", key);
            return;
        }
        out->field = &t->fields[i];
        out->item = 0;
        t = out->field->sub;
        size_t n = strlen(out->skey);
        snprintf(out->skey + n, sizeof out->skey - n, "%s%s", n ? "." : "", key);
    }
    if (rc < 0) out->fault = CS_PATH_MALFORMED;
}

/* The defaults of a target struct (cs_default_*). */
static void target_defaults(cs_target t, cs_any_def *out) {
    memset(out, 0, sizeof *out);
    switch (t) {
    case CS_T_VEHICLE:
        out->vehicle = cs_default_vehicle_def();
        break;
    case CS_T_ROPE:
        out->rope = cs_default_rope_def();
        break;
    case CS_T_SECTION:
        out->section = cs_default_section_def();
        break;
    case CS_T_CABLE:
        out->cable = cs_default_cable_def();
        break;
    case CS_T_POST:
        out->post = cs_default_post_def();
        break;
    case CS_T_FOOTING:
        out->footing = cs_default_footing_def();
        break;
    case CS_T_ANCHOR:
        out->anchor = cs_default_anchor_def();
        break;
    case CS_T_RAIL:
        out->rail = cs_default_rail_def();
        break;
    case CS_T_BARRIER:
        out->barrier = cs_default_barrier_def();
        break;
    case CS_T_SCENARIO:
        out->scenario = cs_default_scenario_def();
        break;
    case CS_T_NONE:
        break;
    }
}

/* ---- the reference, docs/file-format.md ---- */

static const cs_table *const doc_tables[] = {
    &cs_table_model,   &cs_table_parts,    &cs_table_vehicle, &cs_table_box,       &cs_table_rope,
    &cs_table_section, &cs_table_barrier,  &cs_table_soil,    &cs_table_cable,     &cs_table_cable_end,
    &cs_table_posts,   &cs_table_footing,  &cs_table_rail,    &cs_table_rail_part, &cs_table_anchors,
    &cs_table_anchor,  &cs_table_scenario,
};

static void doc_type(FILE *out, const cs_field *f) {
    const cs_quantity_info *qi = cs_quantity_get(f->q);
    switch (f->kind) {
    case CS_F_QTY:
        if (f->q == CS_Q_NUMBER)
            fprintf(out, "number");
        else
            fprintf(out, "%s (%s)", qi->name, qi->label);
        if (f->flags & CS_NONE_OK) fprintf(out, " or `none`");
        break;
    case CS_F_INT:
        fprintf(out, "whole number");
        break;
    case CS_F_TEXT:
        fprintf(out, "text");
        break;
    case CS_F_ENUM:
        fprintf(out, "one of");
        for (int i = 0; f->words[i]; i++)
            fprintf(out, "%s `%s`", i ? "," : "", f->words[i]);
        break;
    case CS_F_LIST:
        fprintf(out, "list of %s (%s)", qi->name, qi->label);
        break;
    case CS_F_MAP:
        fprintf(out, "[%s](#%s)", f->sub->name, f->sub->name);
        break;
    case CS_F_SEQ:
        fprintf(out, "list of [%s](#%s)", f->sub->name, f->sub->name);
        break;
    case CS_F_PART:
        fprintf(out, "name, or [%s](#%s)", f->sub->name, f->sub->name);
        break;
    }
}

static void doc_default(FILE *out, const cs_table *t, const cs_field *f, const cs_any_def *defaults) {
    if (f->flags & CS_REQ) {
        fprintf(out, "required");
        return;
    }
    if (f->offset < 0 || t->target == CS_T_NONE || f->kind == CS_F_MAP) {
        fprintf(out, "-");
        return;
    }
    const char *at = (const char *)defaults + f->offset;
    int i;
    double d;
    switch (f->kind) {
    case CS_F_INT:
    case CS_F_ENUM:
        memcpy(&i, at, sizeof i);
        if (f->kind == CS_F_ENUM)
            fprintf(out, "`%s`", f->words[i]);
        else
            fprintf(out, "%d", i);
        break;
    default:
        memcpy(&d, at, sizeof d);
        if (isinf(d)) {
            fprintf(out, "`none`");
            break;
        }
        fprintf(out, "%.6g", d);
        if (f->q != CS_Q_NUMBER) fprintf(out, " %s", cs_quantity_get(f->q)->label);
        break;
    }
}

int cs_schema_markdown(FILE *out) {
    fprintf(out,
            "# Model file format\n\n"
            "<!-- Generated by `cablesim schema`; tests/cli_schema.sh checks that this file matches. -->\n\n"
            "A model is a YAML file with up to three parts, `barrier`, `vehicle` and `scenario`, that may "
            "live in one file or come from others: `vehicle: M` names a part of the library (data/*.yaml) "
            "or of the file's own `parts`; `barrier: {file: other.yaml}` takes the barrier of another "
            "file, and any field given beside `file` or `part` replaces the one it brings.\n\n"
            "A `file` is found from the folder of the file that names it, and is read only from the "
            "folder of the file named on the command line (or one below it), the parts library's, or a "
            "folder that `--allow-path DIR` allows (a link is followed to where it leads, and judged "
            "there); a study's `model:` likewise from the spec's folder. Only a regular file of at most "
            "64 MB is read (a FIFO or a device is refused at once). A model file may be someone else's, "
            "so a named file that is not a model (its top is not a mapping of model keys) is reported at "
            "the place that names it, with its line and column, never with its text.\n\n"
            "Every dimensional value takes a unit: `\"8 ft\"`, `1.75 in`, `52 kip`, `8000 psf`, `40 mph`, "
            "`15000 lb` (mass), `52 kip` or `5 lbf` (force), `0.5 ms`, `45 deg`. A number without its unit "
            "is refused (`35` for a speed: give `35 mph`): it was read as SI, which "
            "made `angle: 90` 90 radians; 0 needs none, and a pure number (a ratio, a coefficient) is bare. "
            "Numbers are decimal (no `0x28`, `inf` or `nan`), each value lies within the range of its kind "
            "(docs/assumptions.md, Ranges of the inputs), and a YAML tag (`!!str`) is refused, not ignored. "
            "Units are read by udunits2, plus `mph`, `kph`, `psf`, `ksf`, `kips`, `deg`, `lbm` and `g` "
            "(standard gravity where an acceleration is expected). A product of units is written with a "
            "hyphen, a middle dot, `*`, `.` or a space, in either order (`ft-kip`, `kip·ft`, `kN·m`, "
            "`ft*lbf`: `lb` is a pound of mass, so `ft-lb` is no energy); a `-` before a digit is a "
            "negative power (`kg m-1`). A unit of the wrong kind is an error, and so is one of the "
            "reciprocal kind (`s/m` for a speed, `Hz` for a time), a number inside the unit (`15 000 kg`: "
            "write a number without spaces) and an origin (`s @ 3`).\n\n"
            "`cablesim run FILE --set PATH=VALUE` replaces any value by its path, e.g. "
            "`--set scenario.speed=\"35 mph\"` or `--set barrier.cables[0].pretension=\"8 kip\"`. "
            "`file` and `part` are followed when the file is read, so a `--set` of either is refused "
            "(the top-level `vehicle=NAME` is not: it names the vehicle).\n\n"
            "## Quantities\n\n| quantity | SI unit | example |\n| --- | --- | --- |\n");
    for (int q = 0; q < CS_Q_COUNT; q++) {
        const cs_quantity_info *qi = cs_quantity_get((cs_quantity)q);
        fprintf(out, "| %s | %s | `%s` |\n", qi->name, qi->label, qi->example);
    }
    for (size_t k = 0; k < sizeof doc_tables / sizeof doc_tables[0]; k++) {
        const cs_table *t = doc_tables[k];
        cs_any_def defaults;
        target_defaults(t->target, &defaults);
        fprintf(out, "\n## %s\n\n%s\n\n| key | type | default | meaning |\n| --- | --- | --- | --- |\n",
                t->name, t->doc);
        for (int i = 0; i < t->count; i++) {
            const cs_field *f = &t->fields[i];
            fprintf(out, "| `%s` | ", f->key);
            doc_type(out, f);
            fprintf(out, " | ");
            doc_default(out, t, f, &defaults);
            fprintf(out, " | %s |\n", f->doc);
        }
    }
    fputs(
        "\n## CSV files\n\n"
        "Every CSV file cablesim writes (a run's timeseries.csv and events.csv, a sweep's runs.csv, "
        "compare.csv, validation.csv) has one header line that names each column `name [unit]`, the unit "
        "SI as udunits2 writes it: `t [s]`, `forward_speed [m/s]`, `ax [m/s^2]`, `cable0_max_tension [N]`, "
        "`energy_balance_error [1]` (a fraction), and `decel_50ms [g]` (standard gravities) and "
        "`exit_angle [deg]` where the standards read them so. A column without a unit (a state, a type, an "
        "outcome, a count, an index) has its name alone: `cable0_state`, `type`, `posts_failed_left`. A "
        "column whose unit changes from row to row has it in the column beside it (events.csv's `value` "
        "and `value_unit`, compare.csv's `unit`). Cables, posts and anchors are numbered from 0, as the "
        "paths of `--set` count them (`cable1` is `barrier.cables[1]`), in every output; anchor 0 is "
        "`barrier.anchors.start` (the low-x end), anchor 1 `barrier.anchors.end`. `cablesim compare "
        "--measured FILE` reads a file of this convention (or `name (unit)`), a run's own timeseries.csv "
        "too, its cells quoted or not (RFC 4180, as spreadsheets write CSV: `\"12.5\"` is 12.5, `\"\"` "
        "inside quotes a quote; a quote only around a whole cell). Its first column is the time; every "
        "other is known by its name, case and punctuation aside, and its unit must be one of that "
        "quantity: a name with a word beginning `decel` a deceleration (g, m/s^2), `accel` an acceleration "
        "along the "
        "travel, negative as the vehicle slows, read as the deceleration with its sign turned (as a run's "
        "`ax` and `ay` along its first heading make its deceleration), `speed` or `velocity` the speed "
        "(mph, km/h, m/s), `penetration` the vehicle's penetration (ft, m), `tension` the rope tension "
        "(kip, kN); a word is a run of letters and digits, or starts at a capital after a lower-case letter "
        "or at a digit after a letter (`vehicleSpeed`, `decel50ms`; `extension` is no tension). A column "
        "whose name holds none of them (`post "
        "displacement [m]`; a deflection is the "
        "barrier's, not the vehicle's penetration), two of them, or one across the travel or averaged "
        "(`lateral`, `lat`, `transverse`, `vertical`, `vert`, the vehicle's axes across it `y` and `z` as "
        "crash-test channels name them, `Y Accel`, `accel_z`; `50ms` or `50 ms`, `average`, `avg`), one "
        "whose unit does not fit its name (`speed "
        "[m]`), one that names two units of its quantity (`speed [mph] (km/h)`, `speed [mph] [km/h]`: "
        "which its numbers are in cannot be told; a group in brackets that is no unit of it, `decel (CG) "
        "[g]`, is part of the name), and a second column of one quantity are refused at their line and "
        "column.\n",
        out);
    return ferror(out) ? -1 : 0;
}
