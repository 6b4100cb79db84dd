/* SPDX-License-Identifier: MIT */
/* Failure and end-of-run events: what, when, which element. */
#include "core/core.h"

static const char *const event_names[CS_EVENT_TYPE_COUNT] = {
    "cable_break",       "termination_break", "post_hinge",     "post_rotation_limit", "post_shear",
    "post_pullout",      "footing_rotation",  "anchor_pullout", "anchor_yield",        "override",
    "underride",         "stopped",           "breakthrough",   "redirected",          "cable_release",
    "termination_slip",  "post_withdrawal",   "post_down",      "cable_pulled_off",    "termination_at_post",
    "anchor_withdrawal", "cable_struck_off"};

/* The value each type carries (sim.h) */
static const char *const event_units[CS_EVENT_TYPE_COUNT] = {
    "N", "N",   "N m", "rad", "N", "N", "N m", "N", "N", "s", "s",
    "m", "m/s", "m/s", "N",   "N", "N", "rad", "N", "m", "N", "N"};

const char *cs_event_type_name(cs_event_type type) {
    return (type >= 0 && type < CS_EVENT_TYPE_COUNT) ? event_names[type] : "unknown";
}

const char *cs_event_value_unit(cs_event_type type) {
    return (type >= 0 && type < CS_EVENT_TYPE_COUNT) ? event_units[type] : "";
}

const char *cs_element_kind_name(cs_element_kind kind) {
    switch (kind) {
    case CS_ELEMENT_CABLE:
        return "cable";
    case CS_ELEMENT_POST:
        return "post";
    case CS_ELEMENT_ANCHOR:
        return "anchor";
    case CS_ELEMENT_VEHICLE:
        return "vehicle";
    }
    return "unknown";
}

const char *cs_event_cable_end_name(const cs_event *e) {
    return e->cable_end == 0 ? "start" : e->cable_end == 1 ? "end" : "";
}

/* The capacity covers every element failing once plus the end event, so nothing is dropped. */
cs_event *cs_event_add(const cs_model *model, cs_state *s, cs_event_type type, cs_element_kind kind,
                       int element, double value) {
    if (s->event_count >= model->event_capacity) return NULL;
    cs_event *e = &s->events[s->event_count++];
    e->size = sizeof *e;
    e->t = s->t;
    e->type = type;
    e->element_kind = kind;
    e->element = element;
    e->value = value;
    e->cable_end = -1;
    e->cable = -1;
    e->post = -1;
    return e;
}

int cs_state_event_count(const cs_state *s) {
    return s->event_count;
}
