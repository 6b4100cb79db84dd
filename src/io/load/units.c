/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "status.h"
#include "units_int.h"

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
const char *const cs_unit_aliases[][2] = {
    {"mph", "mile/hour"}, {"kph", "km/hour"}, {"psf", "lbf/ft^2"}, {"ksf", "1000 lbf/ft^2"},
    {"kips", "kip"},      {"deg", "degree"},  {"lbm", "lb"},       {"gee", "9.80665 m/s^2"},
};
const int cs_unit_alias_count = sizeof cs_unit_aliases / sizeof cs_unit_aliases[0];

const char *const cs_units_usual[] = {
    "m",      "mm",       "cm",     "km",  "in",   "ft",    "yd",     "mi",     "m2",    "mm2",     "cm2",
    "in2",    "ft2",      "m3",     "mm3", "cm3",  "in3",   "m4",     "mm4",    "cm4",   "in4",     "kg",
    "g",      "t",        "lb",     "lbm", "kg/m", "lb/ft", "lb/in",  "kg*m^2", "kg m2", "lb*ft^2", "s",
    "ms",     "min",      "h",      "m/s", "km/h", "kph",   "mph",    "ft/s",   "m/s2",  "m/s^2",   "ft/s2",
    "gee",    "N",        "kN",     "MN",  "lbf",  "kip",   "kips",   "N/m",    "kN/m",  "MN/m",    "lbf/in",
    "kip/in", "lbf/ft",   "kip/ft", "Pa",  "kPa",  "MPa",   "GPa",    "psi",    "ksi",   "psf",     "ksf",
    "rad",    "deg",      "degree", "J",   "kJ",   "MJ",    "ft*lbf", "Pa/m",   "kPa/m", "MPa/m",   "psf/ft",
    "psi/ft", "lbf/ft^3", "kN/m3",  "%",
};
const int cs_units_usual_count = sizeof cs_units_usual / sizeof cs_units_usual[0];

const cs_quantity_info *cs_quantity_get(cs_quantity q) {
    return &quantities[q];
}

void cs_units_free(cs_units *u) {
    if (u) u->ops->destroy(u);
}

static int convertible(cs_units *u, void *unit, cs_quantity q) {
    double si;
    return u->ops->convert(u, unit, q, 1.0, &si) == 0;
}

/* The quantity a unit measures: the first of a dimension that converts it (an angle's units are pure
 * numbers: not asked), else CS_Q_NUMBER for a pure number, else -1. */
static int quantity_of(cs_units *u, void *unit) {
    for (int q = CS_Q_LENGTH; q < CS_Q_COUNT; q++)
        if (q != CS_Q_ANGLE && convertible(u, unit, q)) return q;
    return convertible(u, unit, CS_Q_NUMBER) ? CS_Q_NUMBER : -1;
}

/* Name the kind of quantity a unit measures, for a message. */
static const char *kind_of(cs_units *u, void *unit) {
    int q = quantity_of(u, unit);
    return q < 0 ? NULL : q == CS_Q_NUMBER ? "pure number" : quantities[q].name;
}

/* The text of a unit's reciprocal as the messages ask a unit system for it: "1/(s/m)". */
static void reciprocal_text(const char *text, char *out, size_t size) {
    snprintf(out, size, "1/(%s)", text);
}

/* Name the kind of quantity a unit is the reciprocal of ("s/m": speed, "ft-2": area), for a message. */
static const char *reciprocal_kind_of(cs_units *u, const char *text) {
    char inverse[80];
    reciprocal_text(text, inverse, sizeof inverse);
    void *unit = u->ops->parse(u, inverse);
    const char *kind = unit ? kind_of(u, unit) : NULL;
    if (unit) u->ops->release(u, unit);
    return kind;
}

/* Whether a unit's text has a '-' before a digit: udunits2 reads "ft-2" as 1/ft^2. */
static int negative_power(const char *text) {
    for (const char *minus = strchr(text, '-'); minus; minus = strchr(minus + 1, '-'))
        if (isdigit((unsigned char)minus[1])) return 1;
    return 0;
}

/* Whether a unit's text holds a number or an origin of its own: udunits2 reads "2 kg" as a unit of 2 kg and
 * "s @ 3" as seconds from an origin, so "15 000.5 kg" would be 15 x 0.5 kg. A power's digits (in2, m^2,
 * m**2, m-1) and the 1 of 1/s are none. */
static int number_in_unit(const char *text) {
    for (const char *p = text; *p; p++) {
        if (*p == '@') return 1;
        if (!isdigit((unsigned char)*p) || (p > text && isdigit((unsigned char)p[-1])))
            continue; /* not the first digit of a number (after a power's digits, "m2.5" is m^2 x 5) */
        const char *before = p - (p > text && (p[-1] == '-' || p[-1] == '+'));
        int power = before > text && (isalpha((unsigned char)before[-1]) || before[-1] == '^' ||
                                      (before - text >= 2 && before[-1] == '*' && before[-2] == '*'));
        if (!power && !(p[0] == '1' && p[1] == '/')) return 1;
    }
    return 0;
}

/* The end of a decimal number at s ([+-]digits[.digits][e[+-]digits]), or NULL: strtod's hexadecimal,
 * "inf" and "nan" are not a model's numbers ("0x28 mph" is not 40 mph). */
static const char *decimal_end(const char *s) {
    const char *p = s + (*s == '+' || *s == '-'), *digits = p;
    while (isdigit((unsigned char)*p))
        p++;
    int whole = p > digits;
    if (*p == '.') {
        const char *frac = ++p;
        while (isdigit((unsigned char)*p))
            p++;
        if (!whole && p == frac) return NULL;
    } else if (!whole) {
        return NULL;
    }
    if (*p == 'e' || *p == 'E') {
        const char *e = p + 1 + (p[1] == '+' || p[1] == '-'), *exp = e;
        while (isdigit((unsigned char)*e))
            e++;
        if (e > exp) p = e;
    }
    return p;
}

/* The unit of a value's text: what follows its number, trimmed, in unit (empty: none). -1 if it has no
 * decimal number or the unit is too long. */
static int unit_of(const char *text, const char **number, char *unit, size_t size) {
    while (isspace((unsigned char)*text))
        text++;
    const char *end = decimal_end(text);
    *number = text;
    if (!end) return -1;
    while (isspace((unsigned char)*end))
        end++;
    size_t n = strlen(end);
    while (n > 0 && isspace((unsigned char)end[n - 1]))
        n--;
    if (n >= size) return -1;
    memcpy(unit, end, n);
    unit[n] = '\0';
    return 0;
}

/* Whether text with each pound (lb, of mass) read as a pound of force (lbf) is a unit of q: "ft-lb" for an
 * energy, "15000 lb" for a force. */
static int pound_of_force(cs_units *u, const char *text, cs_quantity q) {
    char force[128];
    size_t n = 0;
    for (const char *p = text; *p && n + 3 < sizeof force; p++) {
        force[n++] = *p;
        if (p[0] == 'l' && p[1] == 'b' && !(p > text && isalpha((unsigned char)p[-1])) &&
            !isalpha((unsigned char)p[2]))
            force[n++] = 'b', force[n++] = 'f', p++;
    }
    force[n] = '\0';
    void *unit = strcmp(force, text) != 0 ? u->ops->parse(u, force) : NULL;
    int is = unit && convertible(u, unit, q);
    if (unit) u->ops->release(u, unit);
    return is;
}

/* Why a unit that text names is not a unit of q. */
static cs_status not_of(cs_units *u, void *unit, const char *text, cs_quantity q, cs_error *err) {
    const char *kind = kind_of(u, unit), *inverse = kind ? NULL : reciprocal_kind_of(u, text);
    const char *pound = pound_of_force(u, text, q) ? " (lb is a pound of mass: a pound of force is lbf)" : "";
    if (kind)
        return cs_error_set(err, CS_ERR_INVALID, "'%s' is a unit of %s, not of %s%s", text, kind,
                            quantities[q].name, pound);
    if (inverse)
        return cs_error_set(err, CS_ERR_INVALID, "'%s' is a unit of 1/%s, not of %s%s", text, inverse,
                            quantities[q].name,
                            negative_power(text) ? " (a '-' before a digit is a negative power)" : "");
    return cs_error_set(err, CS_ERR_INVALID, "'%s' is not a unit of %s%s", text, quantities[q].name, pound);
}

/* The dot operator (U+22C5) as the middle dot (U+00B7), which udunits2 reads as a product ("kN·m"): the two
 * look alike. */
static void dot_operator_as_middle_dot(char *text) {
    for (char *dot; (dot = strstr(text, "\xE2\x8B\x85")) != NULL;) {
        dot[0] = '\xC2', dot[1] = '\xB7';
        memmove(dot + 2, dot + 3, strlen(dot + 3) + 1);
    }
}

cs_status cs_units_read(cs_units *u, const char *text, cs_quantity q, double *si, cs_error *err) {
    char unit_text[64];
    const char *number;
    if (unit_of(text, &number, unit_text, sizeof unit_text) != 0) {
        if (decimal_end(number))
            return cs_error_set(err, CS_ERR_INVALID, "unit '%.20s...' is too long", number);
        return cs_error_set(err, CS_ERR_INVALID, "'%s' is not a number with a unit", number);
    }
    if (strspn(number, "+-") < 2 && strncasecmp(number + strspn(number, "+-"), "0x", 2) == 0)
        return cs_error_set(err, CS_ERR_INVALID, "'%s' is not a decimal number", number);
    double value = strtod(number, NULL);
    if (!isfinite(value)) return cs_error_set(err, CS_ERR_INVALID, "'%s' is out of range", number);
    if (!unit_text[0]) { /* a pure number; a quantity's 0 is 0 in any unit */
        if (q != CS_Q_NUMBER && value != 0) {
            const char *example = strchr(quantities[q].example, ' ');
            return cs_error_set(err, CS_ERR_INVALID, "'%s' has no unit: give one, e.g. %.*s%s", number,
                                (int)strcspn(number, " \t"), number, example ? example : "");
        }
        *si = value;
        return CS_OK;
    }
    if (number_in_unit(unit_text))
        return cs_error_set(err, CS_ERR_INVALID,
                            "'%s' has a number in its unit '%s' (expected one number, then its unit, e.g. "
                            "\"15000 lb\": no space within the number)",
                            number, unit_text);
    dot_operator_as_middle_dot(unit_text);
    const char *lookup = (q == CS_Q_ACCELERATION && strcmp(unit_text, "g") == 0) ? "gee" : unit_text;
    cs_status rc = CS_OK;
    void *unit = u->ops->parse(u, lookup);
    if (!unit) {
        rc = cs_error_set(err, CS_ERR_INVALID, "unknown unit '%s'", unit_text);
    } else if (u->ops->convert(u, unit, q, value, si) != 0) {
        rc = not_of(u, unit, unit_text, q, err);
    }
    if (unit) u->ops->release(u, unit);
    if (rc == CS_OK && !isfinite(*si)) rc = cs_error_set(err, CS_ERR_INVALID, "'%s' is out of range", number);
    return rc;
}

void cs_units_show(cs_units *u, const char *text, cs_quantity q, double si, char *out, size_t size) {
    char unit[64], one[80];
    const char *number;
    double factor = 0;
    if (unit_of(text, &number, unit, sizeof unit) == 0 && unit[0]) {
        snprintf(one, sizeof one, "1 %s", unit);
        if (cs_units_read(u, one, q, &factor, NULL) != CS_OK || !(factor > 0)) factor = 0;
    }
    if (factor > 0)
        snprintf(out, size, "%.4g %s", si / factor, unit);
    else
        snprintf(out, size, "%.4g%s%s", si, q == CS_Q_NUMBER ? "" : " ",
                 q == CS_Q_NUMBER ? "" : quantities[q].label);
}

/* A unit system from a table: each unit's factor to every quantity's SI unit (NAN: not a unit of it). */
typedef struct table_unit {
    char *text;
    double factor[CS_Q_COUNT];
} table_unit;

typedef struct table_units {
    cs_units base;
    table_unit *units;
    int count;
} table_units;

static void *table_parse(cs_units *u, const char *text) {
    table_units *t = (table_units *)u;
    for (int i = 0; i < t->count; i++)
        if (strcmp(t->units[i].text, text) == 0) return &t->units[i];
    return NULL;
}

static int table_convert(cs_units *u, void *unit, cs_quantity q, double value, double *si) {
    (void)u;
    const table_unit *tu = unit;
    if (isnan(tu->factor[q])) return -1;
    *si = value * tu->factor[q];
    return 0;
}

static void table_release(cs_units *u, void *unit) {
    (void)u, (void)unit;
}

static void table_destroy(cs_units *u) {
    table_units *t = (table_units *)u;
    for (int i = 0; i < t->count; i++)
        free(t->units[i].text);
    free(t->units);
    free(t);
}

static const cs_units_ops table_ops = {table_parse, table_convert, table_release, table_destroy};

/* One line of a table into tu: 0, or -1. */
static int table_line(const char *line, size_t len, table_unit *tu) {
    const char *tab = memchr(line, '\t', len);
    if (!tab || tab == line) return -1;
    if (!(tu->text = malloc((size_t)(tab - line) + 1))) return -1;
    memcpy(tu->text, line, (size_t)(tab - line));
    tu->text[tab - line] = '\0';
    const char *p = tab + 1, *stop = line + len;
    for (int q = 0; q < CS_Q_COUNT; q++) {
        while (p < stop && *p == ' ')
            p++;
        if (p < stop && *p == '-') {
            tu->factor[q] = NAN;
            p++;
            continue;
        }
        char *end;
        tu->factor[q] = strtod(p, &end);
        if (end == p || end > stop || !isfinite(tu->factor[q])) return -1;
        p = end;
    }
    return p == stop ? 0 : -1;
}

cs_units *cs_units_from_table(const char *table, cs_error *err) {
    table_units *t = calloc(1, sizeof *t);
    int lines = 0;
    for (const char *c = table; *c; c++)
        lines += *c == '\n';
    if (!t || !(t->units = calloc((size_t)lines + 1, sizeof *t->units))) {
        free(t);
        cs_out_of_memory(err);
        return NULL;
    }
    t->base.ops = &table_ops;
    for (const char *line = table; *line;) {
        const char *nl = strchr(line, '\n');
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        if (len > 0 && table_line(line, len, &t->units[t->count++]) != 0) {
            cs_error_set(err, CS_ERR_INVALID, "unit table, line %d: not UNIT<tab>%d factors", t->count,
                         CS_Q_COUNT);
            cs_units_free(&t->base);
            return NULL;
        }
        line += len + (nl != NULL);
    }
    return &t->base;
}

/* Whether value * factor is exactly what u converts value in unit to (a conversion by a factor alone). */
static int by_factor(cs_units *u, void *unit, cs_quantity q, double factor) {
    static const double samples[] = {0, 0.1, 0.15, 3, 7.25, 35, 1234.5, 1e-3, -2.5};
    for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
        double si;
        if (u->ops->convert(u, unit, q, samples[i], &si) != 0 || si != samples[i] * factor) return 0;
    }
    return 1;
}

/* The ways a value's reciprocal unit is written, for a unit of text: "s/m" for "m/s"; "1/ft" and "ft-1" for
 * "ft"; "1/in2" for "in2". Each into spelt[n] (size 80); the count, at most 2. */
static int reciprocal_spellings(const char *text, char (*spelt)[80]) {
    const char *slash = strchr(text, '/');
    int n = 0;
    if (strpbrk(text, " *()") || strlen(text) >= 60) return 0;
    if (!slash) {
        snprintf(spelt[n++], 80, "1/%s", text);
        if (strspn(text, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") == strlen(text))
            snprintf(spelt[n++], 80, "%s-1", text);
    } else if (slash > text && slash[1] && !strchr(slash + 1, '/') && strncmp(text, "1/", 2) != 0) {
        snprintf(spelt[n++], 80, "%s/%.*s", slash + 1, (int)(slash - text), text);
    }
    return n;
}

/* One unit's line of a table: its text, then its factor to each quantity's SI unit. */
static void write_line(cs_units *u, void *unit, const char *text, FILE *f) {
    fprintf(f, "%s\t", text);
    for (int q = 0; q < CS_Q_COUNT; q++) {
        double factor;
        if (u->ops->convert(u, unit, q, 1.0, &factor) == 0 && isfinite(factor) &&
            by_factor(u, unit, q, factor))
            fprintf(f, " %.17g", factor);
        else
            fprintf(f, " -");
    }
    fputc('\n', f);
}

int cs_units_write_table(cs_units *u, const char *const *texts, int count, int reciprocals, FILE *f) {
    /* the texts; with reciprocals, the reciprocal spellings of those of a dimension and "1/(X)" of each X
     * of no quantity where that is of one: what a message asks of a unit system to name a reciprocal unit */
    enum { TEXT, SPELLING, INVERSE };
    struct entry {
        const char *text;
        int kind;
        char made[80];
    } *e = calloc((size_t)count * 6 + 1, sizeof *e);
    if (!e) return -1;
    int n = 0, written = 0;
    for (; n < count; n++)
        e[n].text = texts[n];
    for (int i = 0; i < n; i++) {
        int seen = 0;
        for (int j = 0; j < i && !seen; j++)
            seen = strcmp(e[i].text, e[j].text) == 0;
        void *unit = seen || strpbrk(e[i].text, "\t\n") ? NULL : u->ops->parse(u, e[i].text);
        if (!unit) continue;
        int q = quantity_of(u, unit);
        if (e[i].kind != INVERSE || q > CS_Q_NUMBER) write_line(u, unit, e[i].text, f);
        u->ops->release(u, unit);
        written += e[i].kind == TEXT;
        char spelt[2][80];
        int more =
            reciprocals && q > CS_Q_NUMBER && e[i].kind == TEXT ? reciprocal_spellings(e[i].text, spelt) : 0;
        for (int k = 0; k < more; k++, n++) {
            memcpy(e[n].made, spelt[k], sizeof e[n].made);
            e[n].text = e[n].made, e[n].kind = SPELLING;
        }
        if (reciprocals && q < 0 && e[i].kind != INVERSE) {
            reciprocal_text(e[i].text, e[n].made, sizeof e[n].made);
            e[n].text = e[n].made, e[n++].kind = INVERSE;
        }
    }
    free(e);
    return written;
}
