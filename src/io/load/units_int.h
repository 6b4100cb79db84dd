/* SPDX-License-Identifier: MIT */
/* Inside a unit system (units.h): what each kind of system does with a unit's text. units.c reads a
 * quantity's text and words every message once, over either kind: udunits2's database
 * (units_udunits.c, cs_units_open) or a table of factors (units.c, cs_units_from_table). */
#ifndef CS_UNITS_INT_H
#define CS_UNITS_INT_H

#include "units.h"

typedef struct cs_units_ops {
    /* The unit a text names (a handle for convert and release), or NULL when it names none. */
    void *(*parse)(cs_units *u, const char *text);
    /* value in unit as q's SI unit into *si: 0, or -1 when unit is not a unit of q. */
    int (*convert)(cs_units *u, void *unit, cs_quantity q, double value, double *si);
    void (*release)(cs_units *u, void *unit);
    void (*destroy)(cs_units *u);
} cs_units_ops;

/* Every kind of unit system begins with this. */
struct cs_units {
    const cs_units_ops *ops;
};

/* Units the field writes that udunits2's database lacks or reads otherwise: {symbol, definition}. */
extern const char *const cs_unit_aliases[][2];
extern const int cs_unit_alias_count;

#endif
