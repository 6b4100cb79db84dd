/* SPDX-License-Identifier: MIT */
/* A sweep spec's varied values (`vary:` entries): a grid's levels (a list, or from/to/step|count) and a
 * distribution's parameters, each read in its unit and checked, each error at its line:column. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"
#include "sweepspec.h"
#include "sweepspec_int.h"

/* The unit after the number in text, as v's shown unit, if v has none yet: a unit udunits2 reads as a
 * multiple of the SI one (0 of it is 0). A bare number (0, or a pure number), or any other: the SI label. */
static void shown_unit(cs_units *u, cs_sweep_var *v, const char *text) {
    if (v->shown_scale > 0) return;
    snprintf(v->shown_unit, sizeof v->shown_unit, "%s", v->unit);
    v->shown_scale = 1;
    char *rest, probe[64];
    strtod(text, &rest);
    while (*rest == ' ')
        rest++;
    size_t n = strlen(rest);
    while (n > 0 && rest[n - 1] == ' ')
        n--;
    double one, zero;
    if (v->integer || n == 0 || n >= sizeof v->shown_unit) return;
    snprintf(probe, sizeof probe, "1 %.*s", (int)n, rest);
    if (cs_units_read(u, probe, v->q, &one, NULL) != CS_OK || !(one > 0)) return;
    snprintf(probe, sizeof probe, "0 %.*s", (int)n, rest);
    if (cs_units_read(u, probe, v->q, &zero, NULL) != CS_OK || zero != 0) return;
    snprintf(v->shown_unit, sizeof v->shown_unit, "%.*s", (int)n, rest);
    v->shown_scale = one;
}

static int read_value(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const char *text, int line, int col,
                      const char *what, double *out) {
    cs_error err;
    if (v->integer) {
        char *end;
        errno = 0;
        long n = strtol(text, &end, 10);
        while (*end == ' ')
            end++;
        if (end == text || *end || errno) {
            cs_sweep_error(s, line, col, "vary: %s: %s '%s' is not a whole number", v->path, what, text);
            return -1;
        }
        *out = (double)n;
        return 0;
    }
    if (cs_units_read(u, text, v->q, out, &err) != CS_OK) {
        cs_sweep_error(s, line, col, "vary: %s: %s: %s (expected a %s, e.g. \"%s\")", v->path, what,
                       err.message, cs_quantity_get(v->q)->name, cs_quantity_get(v->q)->example);
        return -1;
    }
    shown_unit(u, v, text);
    return 0;
}

static int add_level(cs_sweep_var *v, double x, const char *text, int line, int col) {
    int n = v->level_count;
    if (cs_grow_one(&v->levels, n, sizeof *v->levels) != 0 ||
        cs_grow_one(&v->texts, n, sizeof *v->texts) != 0 ||
        cs_grow_one(&v->level_line, n, sizeof *v->level_line) != 0 ||
        cs_grow_one(&v->level_col, n, sizeof *v->level_col) != 0 || !(v->texts[n] = strdup(text)))
        return -1;
    v->levels[n] = x, v->level_line[n] = line, v->level_col[n] = col;
    v->level_count++;
    return 0;
}

enum { MAX_LEVELS = 100000 };

/* A grid entry: a list of values, or {from, to, step | count}. */
void cs_sweep_read_grid(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const cs_ynode *e) {
    if (e->kind == CS_Y_SEQ) {
        size_t used = (size_t)snprintf(v->desc, sizeof v->desc, "levels:");
        for (int k = 0; k < e->count && used < sizeof v->desc; k++)
            used += (size_t)snprintf(v->desc + used, sizeof v->desc - used, "%s %s", k ? "," : "",
                                     e->kids[k]->text);
        if (e->count == 0)
            cs_sweep_error(s, e->line, e->col, "vary: %s: no values (expected a list of values)", v->path);
        for (int k = 0; k < e->count; k++) {
            const cs_ynode *it = e->kids[k];
            double x = 0;
            if (v->numeric && read_value(s, u, v, it->text, it->line, it->col, "value", &x) != 0) continue;
            if (add_level(v, x, it->text, it->line, it->col) != 0) return;
        }
        return;
    }
    const cs_ynode *from = cs_ynode_get(e, "from"), *to = cs_ynode_get(e, "to"),
                   *step = cs_ynode_get(e, "step"), *count = cs_ynode_get(e, "count");
    for (int p = P_DIST; p <= P_MAX; p++) {
        const cs_ynode *bad = cs_ynode_get(e, param_keys[p]);
        if (bad)
            cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: '%s' does not go with from/to", v->path,
                           bad->key);
    }
    if (!v->numeric) {
        cs_sweep_error(s, e->line, e->col, "vary: %s is text (expected a list of its values)", v->path);
        return;
    }
    if (!from || !to || (!step) == (!count)) {
        cs_sweep_error(s, e->line, e->col, "vary: %s: a range needs from, to and one of step or count",
                       v->path);
        return;
    }
    double a, b, h = 0;
    long n = 0;
    int ok = read_value(s, u, v, text(from), from->line, from->col, "from", &a) == 0;
    ok &= read_value(s, u, v, text(to), to->line, to->col, "to", &b) == 0;
    if (step) {
        ok &= read_value(s, u, v, text(step), step->line, step->col, "step", &h) == 0;
        if (ok && !(h > 0)) {
            cs_sweep_error(s, step->line, step->col, "vary: %s: step must be above zero", v->path);
            ok = 0;
        }
        if (ok && b < a) {
            cs_sweep_error(s, to->line, to->col, "vary: %s: to is below from (expected from <= to)", v->path);
            ok = 0;
        }
        if (ok) {
            double span = (b - a) / h;
            if (span > MAX_LEVELS) {
                cs_sweep_error(s, step->line, step->col, "vary: %s: more than %d levels", v->path,
                               MAX_LEVELS);
                ok = 0;
            }
            n = ok ? (long)floor(span * (1 + 1e-12) + 1e-9) + 1 : 0;
        }
    } else {
        char *end;
        n = strtol(text(count), &end, 10);
        if (*end || n < 1 || n > MAX_LEVELS) {
            cs_sweep_error(s, count->line, count->col, "vary: %s: count must be a whole number from 1 to %d",
                           v->path, MAX_LEVELS);
            ok = 0;
        }
    }
    snprintf(v->desc, sizeof v->desc, "from %s to %s, %s %s", text(from), text(to), step ? "step" : "count",
             text(step ? step : count));
    for (long k = 0; ok && k < n; k++) {
        double x = step ? a + (double)k * h : n == 1 ? a : a + (b - a) * (double)k / (double)(n - 1);
        if (v->integer) x = round(x);
        char text[64];
        snprintf(text, sizeof text, "%.12g", x);
        if (add_level(v, x, text, from->line, from->col) != 0) return;
    }
}

/* A distribution entry {dist, mean, sd, min, max}. */
void cs_sweep_read_dist(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const cs_ynode *e) {
    const cs_ynode *dn = cs_ynode_get(e, "dist");
    for (int p = P_FROM; p < P_N; p++) {
        const cs_ynode *bad = cs_ynode_get(e, param_keys[p]);
        if (bad)
            cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: '%s' does not go with dist", v->path,
                           bad->key);
    }
    if (!v->numeric || v->integer) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s is %s (a distribution needs a quantity)", v->path,
                       v->integer ? "a whole number" : "text");
        return;
    }
    const char *name = text(dn);
    int truncated = strcmp(name, "truncated_normal") == 0;
    cs_dist *t = &v->dist;
    if (strcmp(name, "uniform") == 0)
        t->kind = CS_DIST_UNIFORM;
    else if (strcmp(name, "normal") == 0 || truncated)
        t->kind = CS_DIST_NORMAL;
    else if (strcmp(name, "lognormal") == 0)
        t->kind = CS_DIST_LOGNORMAL;
    else {
        cs_sweep_error(
            s, dn->line, dn->col,
            "vary: %s: unknown dist '%s' (expected uniform, normal, lognormal or truncated_normal)", v->path,
            name);
        return;
    }
    double val[P_N];
    int given[P_N] = {0}, ok = 1;
    size_t used = (size_t)snprintf(v->desc, sizeof v->desc, "%s", name);
    for (int p = P_MEAN; p <= P_MAX; p++) {
        const cs_ynode *pn = cs_ynode_get(e, param_keys[p]);
        if (!pn) continue;
        if (used < sizeof v->desc)
            used += (size_t)snprintf(v->desc + used, sizeof v->desc - used, "%s %s %s",
                                     used > strlen(name) ? "," : ":", param_keys[p], pn->text);
        given[p] = 1;
        if (read_value(s, u, v, pn->text, pn->line, pn->col, param_keys[p], &val[p]) != 0) ok = 0;
    }
    static const char *const needs[] = {"min and max", "mean and sd", "mean and sd"};
    int need_ab = t->kind == CS_DIST_UNIFORM ? given[P_MIN] && given[P_MAX] : given[P_MEAN] && given[P_SD];
    if (!need_ab) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s: dist %s needs %s", v->path, name, needs[t->kind]);
        return;
    }
    if (t->kind == CS_DIST_UNIFORM && (given[P_MEAN] || given[P_SD])) {
        const cs_ynode *bad = cs_ynode_get(e, given[P_MEAN] ? "mean" : "sd");
        cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: dist uniform takes min and max only",
                       v->path);
        return;
    }
    if (truncated && !given[P_MIN] && !given[P_MAX]) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s: dist truncated_normal needs min, max or both",
                       v->path);
        return;
    }
    if (!ok) return;
    t->lo = given[P_MIN] ? val[P_MIN] : -HUGE_VAL;
    t->hi = given[P_MAX] ? val[P_MAX] : HUGE_VAL;
    const cs_ynode *at = cs_ynode_get(e, given[P_MAX] ? "max" : "dist");
    if (t->kind == CS_DIST_UNIFORM) {
        t->a = val[P_MIN], t->b = val[P_MAX];
    } else if (!(val[P_SD] > 0)) {
        at = cs_ynode_get(e, "sd");
        cs_sweep_error(s, at->line, at->col, "vary: %s: sd must be above zero", v->path);
        return;
    } else if (t->kind == CS_DIST_NORMAL) {
        t->a = val[P_MEAN], t->b = val[P_SD];
    } else {
        if (!(val[P_MEAN] > 0)) {
            at = cs_ynode_get(e, "mean");
            cs_sweep_error(s, at->line, at->col, "vary: %s: a lognormal mean must be above zero", v->path);
            return;
        }
        double cv = val[P_SD] / val[P_MEAN], s2 = log1p(cv * cv);
        t->b = sqrt(s2);
        t->a = log(val[P_MEAN]) - 0.5 * s2;
    }
    if (!(t->lo < t->hi)) {
        cs_sweep_error(s, at->line, at->col, "vary: %s: max must be above min", v->path);
        return;
    }
    if (cs_dist_prepare(t) != 0)
        cs_sweep_error(s, at->line, at->col, "vary: %s: min and max leave no probability of the distribution",
                       v->path);
}
