/* Physical quantities with units, read by udunits2. A unit system is loaded per context (no shared
 * state between two loaders), with the aliases the field uses that udunits2 lacks. */
#ifndef CS_UNITS_H
#define CS_UNITS_H

#include <stddef.h>

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

/* Load the udunits2 system database and the aliases. NULL with why filled on failure. */
cs_units *cs_units_create(char *why, size_t why_size);
void cs_units_free(cs_units *u);

/* Read "40 mph", "1.75in", "0.15" (a bare number is SI) as quantity q, in SI. Returns 0, or -1 with
 * why filled ("'40 kg' is a mass" ...). */
int cs_units_read(cs_units *u, const char *text, cs_quantity q, double *si, char *why, size_t why_size);

#endif
