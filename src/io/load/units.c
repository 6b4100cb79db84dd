#define _POSIX_C_SOURCE 200809L
#include "units.h"

#include <ctype.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <udunits2.h>

/* udunits2 reads its XML database and parses unit strings through static parser state: every call
 * into it is serialised here. Each context still owns its own unit system. */
static pthread_mutex_t ut_lock = PTHREAD_MUTEX_INITIALIZER;

static const cs_quantity_info quantities[CS_Q_COUNT] = {
    [CS_Q_NUMBER] = {"number", "1", "1", "0.15"},
    [CS_Q_LENGTH] = {"length", "m", "m", "8 ft"},
    [CS_Q_AREA] = {"area", "m^2", "m^2", "0.471 in2"},
    [CS_Q_SECTION_MODULUS] = {"section modulus", "m^3", "m^3", "1.29 in3"},
    [CS_Q_SECOND_MOMENT] = {"second moment of area", "m^4", "m^4", "2.19 in4"},
    [CS_Q_MASS] = {"mass", "kg", "kg", "15000 lb"},
    [CS_Q_MASS_PER_LENGTH] = {"mass per length", "kg/m", "kg/m", "1.67 lb/ft"},
    [CS_Q_INERTIA] = {"moment of inertia", "kg*m^2", "kg m^2", "35000 kg m2"},
    [CS_Q_TIME] = {"time", "s", "s", "0.5 ms"},
    [CS_Q_SPEED] = {"speed", "m/s", "m/s", "40 mph"},
    [CS_Q_ACCELERATION] = {"acceleration", "m/s^2", "m/s^2", "9.81 m/s2"},
    [CS_Q_FORCE] = {"force", "N", "N", "52 kip"},
    [CS_Q_STIFFNESS] = {"stiffness", "N/m", "N/m", "20 MN/m"},
    [CS_Q_PRESSURE] = {"pressure", "Pa", "Pa", "8000 psf"},
    [CS_Q_ANGLE] = {"angle", "rad", "rad", "45 deg"},
    [CS_Q_ENERGY] = {"energy", "J", "J", "1000 ft*lbf"},
    [CS_Q_PRESSURE_GRADIENT] = {"pressure per depth", "Pa/m", "Pa/m", "1000 psf/ft"},
};

/* Units the field writes that the udunits2 database lacks or reads otherwise ("mph" would be
 * milli-phot-hours). "g" is gravity only where an acceleration is expected (else gram). */
static const char *const aliases[][2] = {
    {"mph", "mile/hour"}, {"kph", "km/hour"}, {"psf", "lbf/ft^2"}, {"ksf", "1000 lbf/ft^2"},
    {"kips", "kip"},      {"deg", "degree"},  {"lbm", "lb"},       {"gee", "9.80665 m/s^2"},
};

struct cs_units {
    ut_system *system;
    ut_unit *si[CS_Q_COUNT];
};

const cs_quantity_info *cs_quantity_get(cs_quantity q) {
    return &quantities[q];
}

void cs_units_free(cs_units *u) {
    if (!u) return;
    pthread_mutex_lock(&ut_lock);
    for (int q = 0; q < CS_Q_COUNT; q++)
        ut_free(u->si[q]);
    ut_free_system(u->system);
    pthread_mutex_unlock(&ut_lock);
    free(u);
}

static int add_alias(cs_units *u, const char *symbol, const char *definition) {
    ut_unit *unit = ut_parse(u->system, definition, UT_ASCII);
    int ok = unit && ut_map_symbol_to_unit(symbol, UT_ASCII, unit) == UT_SUCCESS;
    ut_free(unit);
    return ok ? 0 : -1;
}

cs_units *cs_units_create(char *why, size_t why_size) {
    cs_units *u = calloc(1, sizeof *u);
    if (!u) {
        snprintf(why, why_size, "out of memory");
        return NULL;
    }
    pthread_mutex_lock(&ut_lock);
    ut_set_error_message_handler(ut_ignore);
    u->system = ut_read_xml(NULL);
    int ok = u->system != NULL;
    for (size_t i = 0; ok && i < sizeof aliases / sizeof aliases[0]; i++)
        ok = add_alias(u, aliases[i][0], aliases[i][1]) == 0;
    for (int q = 0; ok && q < CS_Q_COUNT; q++)
        ok = (u->si[q] = ut_parse(u->system, quantities[q].si, UT_ASCII)) != NULL;
    pthread_mutex_unlock(&ut_lock);
    if (!ok) {
        snprintf(why, why_size, "cannot load the udunits2 unit database (set UDUNITS2_XML_PATH)");
        cs_units_free(u);
        return NULL;
    }
    return u;
}

/* Name the kind of quantity a unit measures, for a message. Called with the lock held. */
static const char *kind_of(const cs_units *u, const ut_unit *unit) {
    for (int q = CS_Q_LENGTH; q < CS_Q_COUNT; q++)
        if (q != CS_Q_ANGLE && ut_are_convertible(unit, u->si[q])) return quantities[q].name;
    return ut_are_convertible(unit, u->si[CS_Q_NUMBER]) ? "pure number" : NULL;
}

int cs_units_read(cs_units *u, const char *text, cs_quantity q, double *si, char *why, size_t why_size) {
    char *end;
    while (isspace((unsigned char)*text))
        text++;
    double value = strtod(text, &end);
    if (end == text || !isfinite(value)) {
        snprintf(why, why_size, "'%s' is not a number with a unit", text);
        return -1;
    }
    char unit_text[64];
    while (isspace((unsigned char)*end))
        end++;
    size_t n = strlen(end);
    while (n > 0 && isspace((unsigned char)end[n - 1]))
        n--;
    if (n == 0) { /* a bare number is SI */
        *si = value;
        return 0;
    }
    if (n >= sizeof unit_text) {
        snprintf(why, why_size, "unit '%.*s...' is too long", 20, end);
        return -1;
    }
    memcpy(unit_text, end, n);
    unit_text[n] = '\0';
    const char *lookup = (q == CS_Q_ACCELERATION && strcmp(unit_text, "g") == 0) ? "gee" : unit_text;
    int rc = 0;
    pthread_mutex_lock(&ut_lock);
    ut_unit *unit = ut_parse(u->system, lookup, UT_ASCII);
    cv_converter *cv = NULL;
    if (!unit) {
        snprintf(why, why_size, "unknown unit '%s'", unit_text);
        rc = -1;
    } else if (!(cv = ut_get_converter(unit, u->si[q]))) {
        const char *kind = kind_of(u, unit);
        if (kind)
            snprintf(why, why_size, "'%s' is a unit of %s, not of %s", unit_text, kind, quantities[q].name);
        else
            snprintf(why, why_size, "'%s' is not a unit of %s", unit_text, quantities[q].name);
        rc = -1;
    } else {
        *si = cv_convert_double(cv, value);
    }
    cv_free(cv);
    ut_free(unit);
    pthread_mutex_unlock(&ut_lock);
    if (rc == 0 && !isfinite(*si)) {
        snprintf(why, why_size, "'%s' is out of range", text);
        rc = -1;
    }
    return rc;
}
