/* SPDX-License-Identifier: MIT */
/* The unit system of the command and the library: udunits2's database with the field's aliases. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <udunits2.h>
#include <unistd.h>

#include "status.h"
#include "units_int.h"

/* udunits2 reads its XML database and parses unit strings through static parser state: every call
 * into it is serialised here. Each context still owns its own unit system. */
static pthread_mutex_t ut_lock = PTHREAD_MUTEX_INITIALIZER;

/* The usual units (cs_units_usual) as udunits2's database converts them, in cs_units_write_table's form:
 * written at build time by cmake/units_table.c from this same database, whose XML costs more to read
 * than a whole run spends outside its engine on loading. A unit the table lists is converted by its
 * factors, to the same bits; any other text reads the database, once, when first met. */
extern const char cs_units_usual_table[];

typedef struct ud_units {
    cs_units base;
    cs_units *table;   /* the usual units (NULL: an empty table) */
    int read;          /* the database: 0 not yet read, 1 read, -1 unreadable */
    ut_system *system; /* the database with the aliases, once read */
    ut_unit *si[CS_Q_COUNT];
} ud_units;

/* A unit a text names: one of the table's, or the database's. */
typedef struct ud_handle {
    int in_table;
    void *unit;
} ud_handle;

static int add_alias(ud_units *u, const char *symbol, const char *definition) {
    ut_unit *unit = ut_parse(u->system, definition, UT_ASCII);
    int ok = unit && ut_map_symbol_to_unit(symbol, UT_ASCII, unit) == UT_SUCCESS;
    ut_free(unit);
    return ok ? 0 : -1;
}

/* Read the database, the aliases and each quantity's SI unit, under ut_lock: 0, or -1. */
static int read_database(ud_units *u) {
    if (u->read) return u->read > 0 ? 0 : -1;
    ut_set_error_message_handler(ut_ignore);
    u->system = ut_read_xml(NULL);
    int ok = u->system != NULL;
    for (int i = 0; ok && i < cs_unit_alias_count; i++)
        ok = add_alias(u, cs_unit_aliases[i][0], cs_unit_aliases[i][1]) == 0;
    for (int q = 0; ok && q < CS_Q_COUNT; q++)
        ok = (u->si[q] = ut_parse(u->system, cs_quantity_get(q)->si, UT_ASCII)) != NULL;
    u->read = ok ? 1 : -1;
    return ok ? 0 : -1;
}

static void *ud_parse(cs_units *base, const char *text) {
    ud_units *u = (ud_units *)base;
    ud_handle *h = malloc(sizeof *h);
    if (!h) return NULL;
    h->in_table = u->table != NULL && (h->unit = u->table->ops->parse(u->table, text)) != NULL;
    if (!h->in_table) {
        pthread_mutex_lock(&ut_lock);
        h->unit = read_database(u) == 0 ? ut_parse(u->system, text, UT_ASCII) : NULL;
        pthread_mutex_unlock(&ut_lock);
    }
    if (!h->unit) {
        free(h);
        return NULL;
    }
    return h;
}

static int ud_convert(cs_units *base, void *unit, cs_quantity q, double value, double *si) {
    ud_units *u = (ud_units *)base;
    ud_handle *h = unit;
    if (h->in_table) return u->table->ops->convert(u->table, h->unit, q, value, si);
    pthread_mutex_lock(&ut_lock);
    /* udunits2 also converts between a unit and one of the reciprocal dimension, by 1/x ("2 s/m" to
     * 0.5 m/s, "0.5 ft-1" to 2 ft): a value is never meant so, so only a unit of q's own dimension is */
    ut_unit *ratio = ut_divide(h->unit, u->si[q]);
    cv_converter *cv = ratio && ut_is_dimensionless(ratio) ? ut_get_converter(h->unit, u->si[q]) : NULL;
    ut_free(ratio);
    if (cv) *si = cv_convert_double(cv, value);
    cv_free(cv);
    pthread_mutex_unlock(&ut_lock);
    return cv ? 0 : -1;
}

static void ud_release(cs_units *base, void *unit) {
    ud_units *u = (ud_units *)base;
    ud_handle *h = unit;
    if (h->in_table) {
        u->table->ops->release(u->table, h->unit);
    } else {
        pthread_mutex_lock(&ut_lock);
        ut_free(h->unit);
        pthread_mutex_unlock(&ut_lock);
    }
    free(h);
}

static void ud_destroy(cs_units *base) {
    ud_units *u = (ud_units *)base;
    cs_units_free(u->table);
    pthread_mutex_lock(&ut_lock);
    for (int q = 0; q < CS_Q_COUNT; q++)
        ut_free(u->si[q]);
    ut_free_system(u->system);
    pthread_mutex_unlock(&ut_lock);
    free(u);
}

static const cs_units_ops ud_ops = {ud_parse, ud_convert, ud_release, ud_destroy};

cs_units *cs_units_open(cs_error *err) {
    ud_units *u = calloc(1, sizeof *u);
    if (!u) {
        cs_out_of_memory(err);
        return NULL;
    }
    u->base.ops = &ud_ops;
    if (cs_units_usual_table[0] && !(u->table = cs_units_from_table(cs_units_usual_table, err))) {
        free(u);
        return NULL;
    }
    /* the database is read when a text the table lacks needs it; whether it can be is known now */
    pthread_mutex_lock(&ut_lock);
    ut_status status;
    const char *path = ut_get_path_xml(NULL, &status);
    int readable = path && access(path, R_OK) == 0;
    pthread_mutex_unlock(&ut_lock);
    if (!readable) {
        cs_error_set(err, CS_ERR_IO, "cannot load the udunits2 unit database (set UDUNITS2_XML_PATH)");
        cs_units_free(&u->base);
        return NULL;
    }
    return &u->base;
}
