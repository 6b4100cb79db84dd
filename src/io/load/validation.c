/* SPDX-License-Identifier: MIT */
/* The files of data/validation/ (validation.h), read with the CSV reader (no quoting: no value holds a
 * comma), and the rows each file must have. */
#define _POSIX_C_SOURCE 200809L
#include "validation.h"
#include "load/csvread.h"
#include "status.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_COLS = 16, MAX_LINE = 510 }; /* values and characters of a line */

typedef struct csv {
    char path[1100];
    FILE *f;
    cs_csv rows;        /* its rows, the last read in rows.cell */
    int line;           /* of the row last read */
    int cols;           /* as the header names */
    int want[MAX_COLS]; /* the header's column of each column asked for */
    cs_error *err;      /* where a problem is said */
} csv;

static int fault(csv *c, int col, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Record a problem (CS_ERR_INVALID) at column col of the line last read (col 0: of the file). Returns -1. */
static int fault(csv *c, int col, const char *fmt, ...) {
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (col > 0)
        cs_error_set(c->err, CS_ERR_INVALID, "%s:%d:%d: %s", c->path, c->line, col, msg);
    else
        cs_error_set(c->err, CS_ERR_INVALID, "%s: %s", c->path, msg);
    return -1;
}

/* The next line that is not a comment or blank, cut into its values. 1, 0 at the end, or -1. */
static int next_line(csv *c, int *count) {
    int rc = cs_csv_next(&c->rows);
    c->line = (int)(rc < 0 ? c->rows.why_line : c->rows.line);
    if (rc < 0) return fault(c, c->rows.why_col, "%s", c->rows.why);
    *count = c->rows.count;
    return rc;
}

/* Open dir/name and read its header, which must name every column of columns (NULL-terminated). */
static int open_csv(csv *c, const char *dir, const char *name, const char *const *columns, cs_error *err) {
    memset(c, 0, sizeof *c);
    c->err = err;
    snprintf(c->path, sizeof c->path, "%s/%s", dir, name);
    if (!(c->f = fopen(c->path, "r"))) {
        cs_error_set(err, CS_ERR_IO,
                     "%s: cannot open the file: %s (expected the values cablesim validate compares with)",
                     c->path, strerror(errno));
        return -1;
    }
    cs_csv_open_file(&c->rows, c->f, CS_CSV_COMMENTS | CS_CSV_BLANKS | CS_CSV_CR_ENDS, MAX_COLS);
    c->rows.max_line = MAX_LINE;
    int rc = next_line(c, &c->cols);
    if (rc <= 0) return rc < 0 ? -1 : fault(c, 0, "no header line (expected the names of its columns)");
    for (int k = 0; columns[k]; k++) {
        c->want[k] = -1;
        for (int i = 0; i < c->cols; i++)
            if (strcmp(c->rows.cell[i], columns[k]) == 0) c->want[k] = i;
        if (c->want[k] >= 0) continue;
        char names[300] = "";
        for (int j = 0; columns[j]; j++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", j ? ", " : "", columns[j]);
        return fault(c, 1, "no column '%s' (expected a header naming %s)", columns[k], names);
    }
    return 0;
}

/* The next row: 1, 0 at the end, or -1. */
static int next_row(csv *c) {
    int count = 0, rc = next_line(c, &count);
    if (rc > 0 && count != c->cols)
        return fault(c, 1, "%d values (expected %d, as the header names)", count, c->cols);
    return rc;
}

/* The value of the k-th column asked for. */
static const char *text(const csv *c, int k) {
    return c->rows.cell[c->want[k]];
}

static int number(csv *c, int k, double *out) {
    const char *t = text(c, k);
    char *end;
    errno = 0;
    *out = strtod(t, &end);
    if (end == t || *end || errno || !isfinite(*out))
        return fault(c, c->rows.cell_col[c->want[k]], "'%s' is not a number (expected a plain number)", t);
    return 0;
}

/* Read the numbers of columns [from, to) of the row into out[0...]. */
static int numbers(csv *c, int from, int to, double *out) {
    for (int k = from; k < to; k++)
        if (number(c, k, &out[k - from]) != 0) return -1;
    return 0;
}

static int close_csv(csv *c, int rc) {
    if (c->f) fclose(c->f);
    cs_csv_close(&c->rows);
    return rc;
}

static int read_aps1(const char *dir, cs_validation_data *out, cs_error *err) {
    static const char *const columns[] = {
        "test", "source", "max_50ms_decel_g", "exit_speed_mph", "cable1_break_s", "cable2_break_s", NULL};
    static const char *const sources[2] = {"crash test", "paper simulation"};
    cs_crash_values *values[2] = {&out->aps1_test, &out->aps1_paper};
    int seen[2] = {0, 0}, rc;
    csv c;
    if (open_csv(&c, dir, "aps1-crash-test.csv", columns, err) != 0) return close_csv(&c, -1);
    while ((rc = next_row(&c)) > 0) {
        if (strcmp(text(&c, 0), "APS1") != 0) continue; /* another test's */
        int s = strcmp(text(&c, 1), sources[0]) == 0 ? 0 : strcmp(text(&c, 1), sources[1]) == 0 ? 1 : -1;
        if (s < 0)
            return close_csv(&c,
                             fault(&c, c.rows.cell_col[c.want[1]], "unknown source '%s' (expected %s or %s)",
                                   text(&c, 1), sources[0], sources[1]));
        if (seen[s]++)
            return close_csv(&c, fault(&c, 1, "APS1, %s: given twice (expected one row)", sources[s]));
        double v[4];
        if (numbers(&c, 2, 6, v) != 0) return close_csv(&c, -1);
        *values[s] = (cs_crash_values){v[0], v[1], {v[2], v[3]}};
    }
    for (int s = 0; rc == 0 && s < 2; s++)
        if (!seen[s]) rc = fault(&c, 0, "no row for APS1, %s (expected one)", sources[s]);
    return close_csv(&c, rc);
}

static int read_bogie(const char *dir, cs_validation_data *out, cs_error *err) {
    static const char *const columns[] = {"test",
                                          "impact_speed_mph",
                                          "embedment_mm",
                                          "total_deflection_mm",
                                          "total_energy_ftlb",
                                          "failure_mode",
                                          NULL};
    int n = 0, rc;
    csv c;
    if (open_csv(&c, dir, "post-bogie-tests.csv", columns, err) != 0) return close_csv(&c, -1);
    while ((rc = next_row(&c)) > 0) {
        if (n == CS_BOGIE_TESTS)
            return close_csv(&c, fault(&c, 1, "more than %d tests (expected the paper's %d)", CS_BOGIE_TESTS,
                                       CS_BOGIE_TESTS));
        cs_bogie_test *t = &out->bogie[n++];
        const char *mode = text(&c, 5);
        double v[4];
        if (strlen(text(&c, 0)) >= sizeof t->name)
            return close_csv(&c, fault(&c, 1, "a test name of %zu characters (expected fewer than %zu)",
                                       strlen(text(&c, 0)), sizeof t->name));
        if (numbers(&c, 1, 5, v) != 0) return close_csv(&c, -1);
        if (strcmp(mode, "pullout") != 0 && strcmp(mode, "rotation") != 0)
            return close_csv(&c, fault(&c, c.rows.cell_col[c.want[5]],
                                       "failure mode '%s' (expected pullout or rotation)", mode));
        snprintf(t->name, sizeof t->name, "%s", text(&c, 0));
        t->mph = v[0], t->embedment_mm = v[1], t->deflection_mm = v[2], t->energy_ftlb = v[3];
        t->pullout = strcmp(mode, "pullout") == 0;
    }
    if (rc == 0 && n < CS_BOGIE_TESTS)
        rc = fault(&c, 0, "%d tests (expected the paper's %d)", n, CS_BOGIE_TESTS);
    return close_csv(&c, rc);
}

static int read_rig(const char *dir, cs_validation_data *out, cs_error *err) {
    static const char *const columns[] = {"post_section",
                                          "flange_width_in",
                                          "bogie_mass_lb",
                                          "head_height_in",
                                          "head_diameter_in",
                                          "soil_pressure_psf",
                                          NULL};
    cs_bogie_rig *r = &out->rig;
    double v[5];
    int rc;
    csv c;
    if (open_csv(&c, dir, "bogie-rig.csv", columns, err) != 0) return close_csv(&c, -1);
    if ((rc = next_row(&c)) <= 0) return close_csv(&c, rc < 0 ? -1 : fault(&c, 0, "no row (expected one)"));
    if (strlen(text(&c, 0)) >= sizeof r->section)
        return close_csv(&c, fault(&c, c.rows.cell_col[c.want[0]],
                                   "a section name of %zu characters (expected fewer than %zu)",
                                   strlen(text(&c, 0)), sizeof r->section));
    if (numbers(&c, 1, 6, v) != 0) return close_csv(&c, -1);
    for (int k = 0; k < 5; k++)
        if (!(v[k] > 0.0))
            return close_csv(&c, fault(&c, c.rows.cell_col[c.want[k + 1]],
                                       "%s %g (expected a positive value)", columns[k + 1], v[k]));
    if (!(v[2] > 0.5 * v[3]))
        return close_csv(
            &c, fault(&c, c.rows.cell_col[c.want[3]],
                      "head height %g in with a head of %g in (expected the head clear of the ground)", v[2],
                      v[3]));
    snprintf(r->section, sizeof r->section, "%s", text(&c, 0));
    r->flange_in = v[0], r->mass_lb = v[1], r->head_height_in = v[2], r->head_diameter_in = v[3];
    r->soil_psf = v[4];
    if ((rc = next_row(&c)) != 0)
        return close_csv(&c, rc < 0 ? -1 : fault(&c, 1, "a second row (expected one)"));
    return close_csv(&c, 0);
}

static int read_eq21(const char *dir, cs_validation_data *out, cs_error *err) {
    static const char *const columns[] = {"footing_width_ft", "depth_ft",       "p_lb",
                                          "s1_psf",           "load_height_ft", NULL};
    int rc;
    csv c;
    out->eq21_count = 0;
    if (open_csv(&c, dir, "eq21-table4.csv", columns, err) != 0) return close_csv(&c, -1);
    while ((rc = next_row(&c)) > 0) {
        if (out->eq21_count == CS_EQ21_MAX)
            return close_csv(&c, fault(&c, 1, "more than %d rows", CS_EQ21_MAX));
        double v[5];
        if (numbers(&c, 0, 5, v) != 0) return close_csv(&c, -1);
        for (int k = 0; k < 5; k++)
            if (!(v[k] > 0.0 || (k == 4 && v[k] == 0.0)))
                return close_csv(&c,
                                 fault(&c, c.rows.cell_col[c.want[k]], "%s %g (expected a positive value%s)",
                                       columns[k], v[k], k == 4 ? " or 0" : ""));
        out->eq21[out->eq21_count++] = (cs_eq21_point){v[0], v[1], v[2], v[3], v[4]};
    }
    if (rc == 0 && out->eq21_count == 0) rc = fault(&c, 0, "no rows (expected at least one)");
    return close_csv(&c, rc);
}

cs_status cs_validation_read(const char *dir, cs_validation_data *out, cs_error *err) {
    cs_error local;
    if (!err) err = &local; /* the readers' status is err's */
    memset(out, 0, sizeof *out);
    if (read_aps1(dir, out, err) != 0 || read_bogie(dir, out, err) != 0 || read_rig(dir, out, err) != 0 ||
        read_eq21(dir, out, err) != 0)
        return err->status;
    return CS_OK;
}
