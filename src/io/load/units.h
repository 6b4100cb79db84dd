/* SPDX-License-Identifier: MIT */
/* Physical quantities with units. A unit system is loaded per context (no shared state between two
 * loaders): udunits2's database with the aliases the field uses that udunits2 lacks (cs_units_open),
 * or a table of factors written from one (cs_units_from_table: the designer page's, which has no
 * udunits2), which converts the units it lists to the same bits. */
#ifndef CS_UNITS_H
#define CS_UNITS_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/sim.h"

/* The kinds of quantity a model file holds; each has an SI unit and a name for messages. */
typedef enum cs_quantity {
    CS_Q_NUMBER = 0, /* dimensionless */
    CS_Q_LENGTH,
    CS_Q_AREA,
    CS_Q_SECTION_MODULUS, /* m^3 */
    CS_Q_SECOND_MOMENT,   /* m^4 */
    CS_Q_MASS,
    CS_Q_MASS_PER_LENGTH,
    CS_Q_INERTIA,
    CS_Q_TIME,
    CS_Q_SPEED,
    CS_Q_ACCELERATION,
    CS_Q_FORCE,
    CS_Q_STIFFNESS,
    CS_Q_PRESSURE,
    CS_Q_ANGLE,
    CS_Q_ENERGY,
    CS_Q_PRESSURE_GRADIENT, /* Pa/m: a pressure growing with depth */
    CS_Q_COUNT
} cs_quantity;

typedef struct cs_quantity_info {
    const char *name;    /* "speed" */
    const char *si;      /* SI unit as udunits2 reads it, "m/s" */
    const char *label;   /* SI unit as written in docs and output headers, "m/s" */
    const char *example; /* "40 mph" */
} cs_quantity_info;

const cs_quantity_info *cs_quantity_get(cs_quantity q);

typedef struct cs_units cs_units;

/* udunits2's system database with the aliases: the usual units from a table of its factors written at
 * build time, the database itself read when a text the table lacks is first met. NULL with err filled
 * when there is no database to read (CS_ERR_IO) or no memory (CS_ERR_MEMORY). */
cs_units *cs_units_open(cs_error *err);
void cs_units_free(cs_units *u);

/* The units of every quantity a designer page's table holds beside its model's own: metric and US. */
extern const char *const cs_units_usual[];
extern const int cs_units_usual_count;

/* The units named by texts[0..count) that u knows (each once; a text holding a tab or a newline is left
 * out) as a table for cs_units_from_table: a line each, "TEXT<tab>" then CS_Q_COUNT factors, one for each
 * quantity, the factor to its SI unit (%.17g: exact) or '-' where the unit is not one of that quantity
 * or u converts it otherwise than by a factor alone. With reciprocals, so that the table names a value
 * given in a reciprocal unit as u does ("'s/m' is a unit of 1/speed"; the designer page's table), it also
 * holds the reciprocals of the texts' units of a dimension as a value is written in them ("s/m" for "m/s";
 * "1/ft" and "ft-1" for "ft"; "1/in2") and the reciprocal "1/(X)" of each unit X of no quantity, where
 * that is one of a quantity. Returns the number of texts written (the reciprocals' lines not counted), or
 * -1 when out of memory. */
int cs_units_write_table(cs_units *u, const char *const *texts, int count, int reciprocals, FILE *f);
/* A unit system that knows the units of a table (cs_units_write_table's text) and converts each by its
 * factor: the same messages as any unit system, "unknown unit" for a unit it lacks. NULL with err
 * filled on a malformed table (CS_ERR_INVALID) or no memory (CS_ERR_MEMORY). */
cs_units *cs_units_from_table(const char *table, cs_error *err);

/* Read "40 mph", "1.75in", "0.15" (a pure number) as quantity q, in SI. The number is decimal (no "0x28",
 * "inf" or "nan"); a quantity of a unit needs its unit ("35" is refused for a speed: a bare number is
 * not read as SI), but for 0. CS_OK, or CS_ERR_INVALID with err filled ("'40 kg' is a mass" ...). */
cs_status cs_units_read(cs_units *u, const char *text, cs_quantity q, double *si, cs_error *err);
/* An SI value of quantity q in the unit of text (a value as the user gave it, "35 mph"): "15.66 mph"; in
 * SI where text has no unit u reads as one of q. */
void cs_units_show(cs_units *u, const char *text, cs_quantity q, double si, char *out, size_t size);

#endif
