/* SPDX-License-Identifier: MIT */
/* The unit system of the command and the library: udunits2's database with the field's aliases. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <udunits2.h>

#include "units_int.h"

/* udunits2 reads its XML database and parses unit strings through static parser state: every call
 * into it is serialised here. Each context still owns its own unit system. */
static pthread_mutex_t ut_lock = PTHREAD_MUTEX_INITIALIZER;

typedef struct ud_units {
    cs_units base;
    ut_system *system;
    ut_unit *si[CS_Q_COUNT];
} ud_units;

static void *ud_parse(cs_units *u, const char *text) {
    pthread_mutex_lock(&ut_lock);
    ut_unit *unit = ut_parse(((ud_units *)u)->system, text, UT_ASCII);
    pthread_mutex_unlock(&ut_lock);
    return unit;
}

static int ud_convert(cs_units *u, void *unit, cs_quantity q, double value, double *si) {
    pthread_mutex_lock(&ut_lock);
    cv_converter *cv = ut_get_converter(unit, ((ud_units *)u)->si[q]);
    if (cv) *si = cv_convert_double(cv, value);
    cv_free(cv);
    pthread_mutex_unlock(&ut_lock);
    return cv ? 0 : -1;
}

static void ud_release(cs_units *u, void *unit) {
    (void)u;
    pthread_mutex_lock(&ut_lock);
    ut_free(unit);
    pthread_mutex_unlock(&ut_lock);
}

static void ud_destroy(cs_units *base) {
    ud_units *u = (ud_units *)base;
    pthread_mutex_lock(&ut_lock);
    for (int q = 0; q < CS_Q_COUNT; q++)
        ut_free(u->si[q]);
    ut_free_system(u->system);
    pthread_mutex_unlock(&ut_lock);
    free(u);
}

static const cs_units_ops ud_ops = {ud_parse, ud_convert, ud_release, ud_destroy};

static int add_alias(ud_units *u, const char *symbol, const char *definition) {
    ut_unit *unit = ut_parse(u->system, definition, UT_ASCII);
    int ok = unit && ut_map_symbol_to_unit(symbol, UT_ASCII, unit) == UT_SUCCESS;
    ut_free(unit);
    return ok ? 0 : -1;
}

cs_units *cs_units_create(char *why, size_t why_size) {
    ud_units *u = calloc(1, sizeof *u);
    if (!u) {
        snprintf(why, why_size, "out of memory");
        return NULL;
    }
    u->base.ops = &ud_ops;
    pthread_mutex_lock(&ut_lock);
    ut_set_error_message_handler(ut_ignore);
    u->system = ut_read_xml(NULL);
    int ok = u->system != NULL;
    for (int i = 0; ok && i < cs_unit_alias_count; i++)
        ok = add_alias(u, cs_unit_aliases[i][0], cs_unit_aliases[i][1]) == 0;
    for (int q = 0; ok && q < CS_Q_COUNT; q++)
        ok = (u->si[q] = ut_parse(u->system, cs_quantity_get(q)->si, UT_ASCII)) != NULL;
    pthread_mutex_unlock(&ut_lock);
    if (!ok) {
        snprintf(why, why_size, "cannot load the udunits2 unit database (set UDUNITS2_XML_PATH)");
        cs_units_free(&u->base);
        return NULL;
    }
    return &u->base;
}
