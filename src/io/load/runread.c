/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include "load/runread.h"
#include "cablesim/units.h"
#include "load/confine.h"
#include "load/csvread.h"
#include "status.h"

#include <ctype.h>
#include <errno.h>
#include <json-c/json.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WINDOW 0.050 /* s, the 50-ms average */

/* ---- a CSV file in memory ---- */

/* A time history is read whole, as a regular file only (a FIFO or /dev/zero is refused at once), of at
 * most 1 GB: a 10-s run of 200 posts written every 0.5 ms is about 120 MB. */
#define CS_HISTORY_MAX ((size_t)1 << 30)

typedef struct csv_file {
    char *text;
    size_t size;
} csv_file;

/* The file at path in memory, NUL-terminated, without the byte order mark a spreadsheet may put before
 * UTF-8 ("CSV UTF-8"), and its number of lines (newlines) into *lines. */
static cs_status read_all(const char *path, csv_file *f, size_t *lines, cs_error *err) {
    cs_error input;
    int errnum;
    cs_status rc = cs_input_load(path, CS_HISTORY_MAX, &f->text, &f->size, &errnum, &input);
    if (rc != CS_OK) return cs_error_set(err, rc, "%s: %s", path, input.message);
    if (f->size >= 3 && memcmp(f->text, "\xEF\xBB\xBF", 3) == 0) { /* UTF-8's byte order mark: not text */
        memmove(f->text, f->text + 3, f->size - 3 + 1);
        f->size -= 3;
    }
    *lines = 0;
    for (size_t i = 0; i < f->size; i++)
        *lines += f->text[i] == '\n';
    return CS_OK;
}

/* Whether the row rows could not read failed for want of memory (csvread says "out of memory"), not for
 * its text (a quoted cell not closed, text after a closing quote). */
static int row_oom(const cs_csv *rows) {
    return strcmp(rows->why, "out of memory") == 0;
}

/* The problem of a row rows could not read, into err: CS_ERR_MEMORY, or CS_ERR_INVALID at its place. */
static cs_status row_problem(const cs_csv *rows, const char *path, cs_error *err) {
    if (row_oom(rows)) return cs_error_set(err, CS_ERR_MEMORY, "%s: out of memory", path);
    return cs_error_set(err, CS_ERR_INVALID, "%s:%ld:%d: %s", path, rows->why_line,
                        rows->why_col > 0 ? rows->why_col : 1, rows->why);
}

/* The next data row of rows, blank lines skipped, *more 1 for a row of the header's nh cells, 0 at the
 * end: CS_OK, or with err filled CS_ERR_MEMORY or CS_ERR_INVALID (at its place: a row that cannot be read,
 * or a row of another width). */
static cs_status next_row(cs_csv *rows, int nh, const char *path, int *more, cs_error *err) {
    int rc = cs_csv_next(rows);
    *more = rc > 0;
    if (rc < 0) return row_problem(rows, path, err);
    if (rc == 0 || rows->count == nh) return CS_OK;
    return cs_error_set(err, CS_ERR_INVALID, "%s:%ld:1: %d cells, the header has %d", path, rows->line,
                        rows->count, nh);
}

static int column_of(char *const *names, int n, const char *name) {
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], name) == 0) return i;
    return -1;
}

static int alloc_trace(cs_trace *tr, size_t rows) {
    tr->t = malloc((rows ? rows : 1) * sizeof *tr->t);
    int ok = tr->t != NULL;
    for (int k = 0; k < CS_TRACE_COUNT; k++) {
        tr->y[k] = malloc((rows ? rows : 1) * sizeof *tr->y[k]);
        ok = ok && tr->y[k];
        for (size_t i = 0; tr->y[k] && i < rows; i++)
            tr->y[k][i] = NAN;
    }
    return ok ? 0 : -1;
}

static void clear(cs_trace *tr, const char *label, int measured) {
    memset(tr, 0, sizeof *tr);
    snprintf(tr->label, sizeof tr->label, "%s", label);
    tr->measured = measured;
    tr->max_decel_50ms_g = tr->t_max_decel_50ms = tr->max_penetration = tr->final_speed = NAN;
    tr->max_tension = tr->t_end = tr->max_deflection = tr->working_width = tr->exit_speed = NAN;
    tr->penetration_beyond_m = NAN;
}

void cs_trace_free(cs_trace *tr) {
    free(tr->t);
    for (int k = 0; k < CS_TRACE_COUNT; k++)
        free(tr->y[k]);
    memset(tr, 0, sizeof *tr);
}

/* y at time `when` (t[0] <= when), interpolated; *j, the row at or before it, only moves forward. */
static double value_at(const double *t, const double *y, size_t n, size_t *j, double when) {
    while (*j + 1 < n && t[*j + 1] <= when)
        (*j)++;
    if (*j + 1 >= n) return y[*j];
    return y[*j] + (when - t[*j]) / (t[*j + 1] - t[*j]) * (y[*j + 1] - y[*j]);
}

void cs_trace_average_50ms(const double *t, const double *decel, size_t n, double *avg) {
    /* I(t), the integral of the deceleration taken as linear between rows (the trapezoid rule, and
     * within a row's interval to t - W): avg(t) = (I(t) - I(t - W)) / W, exact for a piecewise-linear
     * history */
    double *in = malloc((n ? n : 1) * sizeof *in);
    size_t j = 0;
    for (size_t i = 0; in && i < n; i++)
        in[i] = i == 0 ? 0.0 : in[i - 1] + 0.5 * (decel[i] + decel[i - 1]) * (t[i] - t[i - 1]);
    for (size_t i = 0; i < n; i++) {
        double from = t[i] - WINDOW;
        if (!in || from < t[0] - 1e-12) {
            avg[i] = NAN;
            continue;
        }
        double d = value_at(t, decel, n, &j, from); /* the deceleration at t - W, and j its row */
        avg[i] = (in[i] - in[j] - 0.5 * (decel[j] + d) * (from - t[j])) / WINDOW;
    }
    free(in);
}

/* The same from a speed history, as the engine has it: (u(t - W) - u(t)) / W. */
static void average_from_speed(const double *t, const double *u, size_t n, double *avg) {
    size_t j = 0;
    for (size_t i = 0; i < n; i++)
        avg[i] = t[i] - WINDOW >= t[0] - 1e-12 ? (value_at(t, u, n, &j, t[i] - WINDOW) - u[i]) / WINDOW : NAN;
}

/* The parameters a trace gives of itself, where its source did not give them. */
static void derive(cs_trace *tr) {
    if (tr->n == 0) return;
    if (isnan(tr->t_end)) tr->t_end = tr->t[tr->n - 1];
    if (isnan(tr->max_decel_50ms_g) && tr->have[CS_TRACE_DECEL_50MS])
        for (size_t i = 0; i < tr->n; i++) {
            double g = tr->y[CS_TRACE_DECEL_50MS][i] / CS_G0;
            if (isfinite(g) && !(g <= tr->max_decel_50ms_g))
                tr->max_decel_50ms_g = g, tr->t_max_decel_50ms = tr->t[i];
        }
    if (isnan(tr->max_penetration) && isnan(tr->penetration_beyond_m) && tr->have[CS_TRACE_PENETRATION])
        for (size_t i = 0; i < tr->n; i++)
            if (isfinite(tr->y[CS_TRACE_PENETRATION][i]) &&
                !(tr->y[CS_TRACE_PENETRATION][i] <= tr->max_penetration))
                tr->max_penetration = tr->y[CS_TRACE_PENETRATION][i];
    if (isnan(tr->max_tension) && tr->have[CS_TRACE_TENSION])
        for (size_t i = 0; i < tr->n; i++)
            if (isfinite(tr->y[CS_TRACE_TENSION][i]) && !(tr->y[CS_TRACE_TENSION][i] <= tr->max_tension))
                tr->max_tension = tr->y[CS_TRACE_TENSION][i];
    if (tr->have[CS_TRACE_SPEED])
        for (size_t i = tr->n; i-- > 0;)
            if (isfinite(tr->y[CS_TRACE_SPEED][i])) {
                tr->final_speed = tr->y[CS_TRACE_SPEED][i];
                break;
            }
}

/* ---- a run's folder ---- */

/* A number of the summary: NAN where it is null or absent (a run that did not reach it); a key holding
 * anything else makes *bad that key (the first such). */
static double json_number(json_object *root, const char *key, const char **bad) {
    json_object *v;
    if (!json_object_object_get_ex(root, key, &v) || !v) return NAN;
    enum json_type t = json_object_get_type(v);
    if ((t == json_type_double || t == json_type_int) && isfinite(json_object_get_double(v)))
        return json_object_get_double(v);
    if (!*bad) *bad = key;
    return NAN;
}

static cs_status read_summary(const char *dir, cs_trace *tr, cs_error *err) {
    char path[1200];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    FILE *probe = fopen(path, "rb");
    if (!probe)
        return cs_error_set(err, CS_ERR_IO, "%s: %s (expected a folder written by cablesim run)", path,
                            strerror(errno));
    fclose(probe);
    csv_file f;
    size_t lines;
    cs_status rc = read_all(path, &f, &lines, err);
    if (rc != CS_OK) return rc;
    json_tokener *tok = json_tokener_new();
    if (!tok) {
        free(f.text);
        return cs_error_set(err, CS_ERR_MEMORY, "%s: out of memory", path);
    }
    json_object *root = json_tokener_parse_ex(tok, f.text, (int)f.size);
    enum json_tokener_error why = json_tokener_get_error(tok);
    if (root && why == json_tokener_success && !json_object_is_type(root, json_type_object))
        rc = cs_error_set(err, CS_ERR_INVALID,
                          "%s:1:1: a JSON %s (expected a summary written by cablesim run)", path,
                          json_type_to_name(json_object_get_type(root)));
    else if (!root || why != json_tokener_success) { /* where the text stops being JSON, as line:column */
        size_t at = json_tokener_get_parse_end(tok), line = 1, col = 1;
        for (size_t i = 0; i < at && i < f.size; i++)
            f.text[i] == '\n' ? (line++, col = 1) : col++;
        rc = cs_error_set(err, CS_ERR_INVALID,
                          "%s:%zu:%zu: not JSON: %s (expected a summary written by cablesim run)", path, line,
                          col,
                          why == json_tokener_continue ? "it ends too soon" : json_tokener_error_desc(why));
    }
    json_tokener_free(tok);
    free(f.text);
    if (rc != CS_OK) {
        json_object_put(root);
        return rc;
    }
    json_object *o;
    if (json_object_object_get_ex(root, "outcome", &o) && json_object_is_type(o, json_type_string))
        snprintf(tr->outcome, sizeof tr->outcome, "%s", json_object_get_string(o));
    const char *bad = NULL;
    tr->max_decel_50ms_g = json_number(root, "max_50ms_decel_g", &bad);
    tr->t_max_decel_50ms = json_number(root, "t_max_50ms_decel_s", &bad);
    tr->max_penetration = json_number(root, "max_dynamic_penetration_m", &bad);
    tr->penetration_beyond_m = json_number(root, "penetration_beyond_m", &bad); /* null: it stopped */
    tr->max_deflection = json_number(root, "max_barrier_deflection_m", &bad);
    tr->working_width = json_number(root, "working_width_m", &bad);
    tr->exit_speed = json_number(root, "exit_speed_mps", &bad);
    tr->max_tension = json_number(root, "max_cable_tension_n", &bad);
    tr->t_end = json_number(root, "t_end_s", &bad);
    char shown[64] = "";
    json_object *b;
    if (bad && json_object_object_get_ex(root, bad, &b))
        snprintf(shown, sizeof shown, "%s", json_object_to_json_string_ext(b, JSON_C_TO_STRING_PLAIN));
    json_object_put(root);
    if (bad)
        return cs_error_set(err, CS_ERR_INVALID,
                            "%s: %s is %s (expected a number, or null where the run did not reach it)", path,
                            bad, shown);
    if (!tr->outcome[0])
        return cs_error_set(err, CS_ERR_INVALID,
                            "%s: no outcome (expected a summary written by cablesim run)", path);
    return CS_OK;
}

enum { MAX_COLS = 4096 }; /* of a run's timeseries.csv */

/* How a history's CSV is cut, a run's and a measured one alike: cells quoted as spreadsheets write them
 * ("12.5", RFC 4180), and past the most cells read, the rest of the row in the last. */
enum { HISTORY_CSV = CS_CSV_REST | CS_CSV_QUOTED };

/* The columns of a run's timeseries.csv that a trace is made of. */
typedef struct run_columns {
    int t, vx, vy, ax, ay, speed, decel_50ms, penetration;
} run_columns;

/* Whether a header is a run's timeseries.csv's, with the columns a trace reads into *c. */
static int run_header(char *const *head, int nh, run_columns *c) {
    c->t = column_of(head, nh, "t [s]"), c->vx = column_of(head, nh, "vx [m/s]");
    c->vy = column_of(head, nh, "vy [m/s]"), c->ax = column_of(head, nh, "ax [m/s^2]");
    c->ay = column_of(head, nh, "ay [m/s^2]"), c->speed = column_of(head, nh, "forward_speed [m/s]");
    c->decel_50ms = column_of(head, nh, "decel_50ms [g]"),
    c->penetration = column_of(head, nh, "penetration [m]");
    return c->t == 0 && c->vx >= 0 && c->vy >= 0 && c->ax >= 0 && c->ay >= 0 && c->speed >= 0 &&
           c->decel_50ms >= 0 && c->penetration >= 0;
}

/* Whether text's first line is the header of a run's timeseries.csv: 1, 0 (a line that cannot be read
 * too: its reader says why), or -1 out of memory. */
static int is_run_series(const char *text) {
    cs_csv rows;
    cs_csv_open_text(&rows, text, HISTORY_CSV, MAX_COLS);
    run_columns c;
    int is = cs_csv_next(&rows) >= 0 ? run_header(rows.cell, rows.count, &c) : row_oom(&rows) ? -1 : 0;
    cs_csv_close(&rows);
    return is;
}

/* A cell as a message quotes it: the first 60 characters and "..." if it is longer, so that a long
 * cell leaves the message room for its reason. */
typedef struct {
    char text[64];
} brief_cell;
static const char *brief(const char *cell, brief_cell *b) {
    if (strlen(cell) <= 60) return cell;
    snprintf(b->text, sizeof b->text, "%.57s...", cell);
    return b->text;
}

/* Cell k of a history's row (a run's or a measured one) as a number: an empty cell is NAN, anything else a
 * finite number whole. */
static cs_status cell_number(const cs_csv *csv, int k, const char *path, double *x, cs_error *err) {
    const char *c = csv->cell[k];
    char *end;
    if (c[strspn(c, " ")] == '\0') {
        *x = NAN;
        return CS_OK;
    }
    *x = strtod(c, &end);
    while (*end == ' ')
        end++;
    if (*end == '\0' && isfinite(*x)) return CS_OK;
    brief_cell b;
    return cs_error_set(err, CS_ERR_INVALID,
                        "%s:%ld:%d: '%s' is not a number (expected a finite number, or an empty cell where "
                        "there is none)",
                        path, csv->cell_line[k], csv->cell_col[k], brief(c, &b));
}

/* A run's time history, timeseries.csv at path, into tr (cleared, its label and measured set). */
static cs_status read_run_series(const char *path, cs_trace *tr, cs_error *err) {
    csv_file f;
    size_t rows;
    cs_status rc = read_all(path, &f, &rows, err);
    if (rc != CS_OK) return rc;
    cs_csv csv;
    cs_csv_open_text(&csv, f.text, HISTORY_CSV, MAX_COLS);
    int *tension = NULL, nh = 0, more;
    if (alloc_trace(tr, rows) != 0 || !(tension = calloc(MAX_COLS, sizeof *tension))) {
        rc = cs_error_set(err, CS_ERR_MEMORY, "%s: out of memory", path);
        goto done;
    }
    if (cs_csv_next(&csv) < 0) {
        rc = row_problem(&csv, path, err);
        goto done;
    }
    nh = csv.count;
    run_columns c;
    if (!run_header(csv.cell, nh, &c)) {
        rc = cs_error_set(err, CS_ERR_INVALID,
                          "%s:1:1: not a run's time history (expected t [s], vx [m/s], ... penetration [m])",
                          path);
        goto done;
    }
    for (int k = 0; k < nh; k++) /* the ropes' columns */
        tension[k] = strncmp(csv.cell[k], "cable", 5) == 0 && strstr(csv.cell[k], "_max_tension [N]");
    int it = c.t, ivx = c.vx, ivy = c.vy, iax = c.ax, iay = c.ay, isp = c.speed, id50 = c.decel_50ms,
        ipen = c.penetration;
    double u0[2] = {0.0, 0.0};
    csv.flags |= CS_CSV_BLANKS;
    while ((rc = next_row(&csv, nh, path, &more, err)) == CS_OK && more) {
        const int cols[] = {it, ivx, ivy, iax, iay, id50, isp, ipen};
        double x[sizeof cols / sizeof cols[0]];
        for (size_t k = 0; rc == CS_OK && k < sizeof cols / sizeof cols[0]; k++)
            rc = cell_number(&csv, cols[k], path, &x[k], err);
        if (rc == CS_OK && isnan(x[0]))
            rc = cs_error_set(err, CS_ERR_INVALID, "%s:%ld:%d: no time (expected one in every row)", path,
                              csv.cell_line[it], csv.cell_col[it]);
        double tmax = NAN;
        for (int k = 0; rc == CS_OK && k < nh; k++) /* the tautest rope at this time */
            if (tension[k]) {
                double tk;
                rc = cell_number(&csv, k, path, &tk, err);
                if (!isnan(tk) && !(tk <= tmax)) tmax = tk;
            }
        if (rc != CS_OK) break;
        size_t i = tr->n++;
        tr->t[i] = x[0];
        double v = hypot(x[1], x[2]);
        if (i == 0 && v > 0.0) u0[0] = x[1] / v, u0[1] = x[2] / v; /* the initial heading */
        tr->y[CS_TRACE_DECEL][i] = -(x[3] * u0[0] + x[4] * u0[1]);
        tr->y[CS_TRACE_DECEL_50MS][i] = x[5] * CS_G0;
        tr->y[CS_TRACE_SPEED][i] = x[6];
        tr->y[CS_TRACE_PENETRATION][i] = x[7];
        tr->y[CS_TRACE_TENSION][i] = tmax;
    }
    if (rc != CS_OK) goto done;
    /* the column is 0 until a whole window has passed: the average is undefined there, as the average of
     * a measured trace is (cs_trace_average_50ms) */
    for (size_t i = 0; i < tr->n && tr->t[i] - WINDOW < tr->t[0] - 1e-12; i++)
        tr->y[CS_TRACE_DECEL_50MS][i] = NAN;
    for (int k = 0; k < CS_TRACE_COUNT; k++)
        tr->have[k] = 1;
    derive(tr);
    rc = CS_OK;
done:
    free(tension), free(f.text);
    cs_csv_close(&csv);
    if (rc != CS_OK) cs_trace_free(tr);
    return rc;
}

cs_status cs_trace_load_run(const char *dir, cs_trace *tr, cs_error *err) {
    clear(tr, dir, 0);
    cs_status rc = read_summary(dir, tr, err);
    if (rc != CS_OK) return rc;
    char path[1200];
    snprintf(path, sizeof path, "%s/timeseries.csv", dir);
    return read_run_series(path, tr, err);
}

/* ---- a measured history ---- */

/* The unit of a header cell "name [unit]" or "name (unit)" into unit; the name's length, or -1. */
static int header_unit(const char *cell, char *unit, size_t size) {
    const char *open = strrchr(cell, '['), *close = strrchr(cell, ']');
    if (!open || !close || close < open) open = strrchr(cell, '('), close = strrchr(cell, ')');
    if (!open || !close || close < open + 1) return -1;
    snprintf(unit, size, "%.*s", (int)(close - open - 1), open + 1);
    return (int)(open - cell);
}

/* A unit of q named by a bracketed group of a header cell other than its unit's, which opens at unit_open: in
 * "speed [mph] (km/h)" which of the two the column's numbers are in cannot be told. A group that names no
 * unit of q is part of the name ("decel (CG) [g]", "speed (CFC 60) [mph]"). Into other; where its group
 * opens, or NULL if there is none. */
static const char *second_unit(cs_units *units, const char *cell, const char *unit_open, cs_quantity q,
                               char *other, size_t size) {
    for (const char *p = cell; (p = strpbrk(p, "[(")) != NULL; p++) {
        const char *close = strchr(p, *p == '[' ? ']' : ')');
        if (!close) break;
        char text[64];
        double si;
        int len = (int)(close - p - 1);
        snprintf(text, sizeof text, "1 %.*s", len, p + 1);
        if (p != unit_open && len > 0 && len < 60 && cs_units_read(units, text, q, &si, NULL) == CS_OK) {
            snprintf(other, size, "%.*s", len, p + 1);
            return p;
        }
        p = close;
    }
    return NULL;
}

/* The quantities a measured column is read as, each known by a word of its name that begins so (case
 * aside; words are runs of letters and digits, split where a capital follows a lower-case letter or a
 * digit a letter: "Vehicle_Speed" and "vehicleSpeed" hold "speed", "decel50ms" "50ms", "extension" no
 * "tension"), its unit then checked against it. An acceleration is the vehicle's along its travel,
 * negative as it slows: read as a deceleration with its sign turned, as a run's ax and ay along its
 * initial heading become its deceleration. A deflection is not a penetration: cablesim's is the
 * barrier's (max_barrier_deflection_m), not the vehicle's. */
static const struct measured_name {
    const char *word;  /* held by the name */
    const char *what;  /* "a speed" */
    int trace;         /* CS_TRACE_... */
    double sign;       /* the trace is sign times the column */
    cs_quantity q;     /* of the unit */
    const char *units; /* "mph, km/h or m/s" */
} measured_names[] = {
    {"decel", "a deceleration", CS_TRACE_DECEL, 1.0, CS_Q_ACCELERATION, "g or m/s^2"},
    {"accel", "an acceleration", CS_TRACE_DECEL, -1.0, CS_Q_ACCELERATION, "g or m/s^2"},
    {"speed", "a speed", CS_TRACE_SPEED, 1.0, CS_Q_SPEED, "mph, km/h or m/s"},
    {"velocity", "a speed", CS_TRACE_SPEED, 1.0, CS_Q_SPEED, "mph, km/h or m/s"},
    {"penetration", "a penetration", CS_TRACE_PENETRATION, 1.0, CS_Q_LENGTH, "ft or m"},
    {"tension", "a rope tension", CS_TRACE_TENSION, 1.0, CS_Q_FORCE, "kip or kN"},
};

/* Words that make a name that holds one of those another quantity than compare's (a word beginning so; one
 * ending in a space a whole word, and "50 ms" two): its traces are along the vehicle's travel and not
 * averaged (it averages over 50 ms itself). The vehicle's axes are x along it, y across and z up, as
 * crash-test instruments name their channels ("Y Accel", "accel_z"); x is taken as along the travel. */
static const char *const measured_other[][2] = {
    {"lateral", "across the travel"},  {"lat ", "across the travel"},  {"transverse", "across the travel"},
    {"vertical", "across the travel"}, {"vert ", "across the travel"}, {"y ", "across the travel"},
    {"z ", "across the travel"},       {"50ms", "averaged over time"}, {"50 ms", "averaged over time"},
    {"average", "averaged over time"}, {"avg", "averaged over time"},
};

/* Whether words (each after a space, and a space at the end) has one beginning with start. */
static int has_word(const char *words, const char *start) {
    size_t n = strlen(start);
    for (const char *w = strchr(words, ' '); w; w = strchr(w + 1, ' '))
        if (strncmp(w + 1, start, n) == 0) return 1;
    return 0;
}

/* The quantity named by cell's first len characters, as measured_names; NULL with err filled (at col, in
 * path) where it names none, two, or one across the travel or averaged. */
static const struct measured_name *measured_name(const char *path, int col, const char *cell, int len,
                                                 cs_error *err) {
    char key[1024]; /* its words, lower-cased, each after a space, a space at the end: " vehicle speed " */
    size_t n = 0;
    for (int i = 0; i < len && n + 3 < sizeof key; i++) {
        unsigned char c = (unsigned char)cell[i], before = i > 0 ? (unsigned char)cell[i - 1] : ' ';
        if (!isalnum(c)) continue;
        if (!isalnum(before) || (isupper(c) && islower(before)) || (isdigit(c) && isalpha(before)))
            key[n++] = ' '; /* a word starts: "vehicleSpeed", "decel50ms", "accel_y" */
        key[n++] = (char)tolower(c);
    }
    key[n++] = ' ';
    key[n] = '\0';
    brief_cell b;
    const char *shown = brief(cell, &b);
    const struct measured_name *found = NULL;
    for (size_t k = 0; k < sizeof measured_names / sizeof measured_names[0]; k++) {
        const struct measured_name *m = &measured_names[k];
        if (!has_word(key, m->word)) continue;
        if (found && (found->trace != m->trace || found->sign != m->sign)) {
            cs_error_set(err, CS_ERR_INVALID,
                         "%s:1:%d: '%s' names both %s and %s (expected one quantity a column)", path, col,
                         shown, found->what, m->what);
            return NULL;
        }
        found = m;
    }
    if (!found) {
        cs_error_set(err, CS_ERR_INVALID,
                     "%s:1:%d: '%s' names no quantity compared (expected a name holding decel, accel, speed, "
                     "velocity, penetration or tension, e.g. \"speed [mph]\")",
                     path, col, shown);
        return NULL;
    }
    for (size_t k = 0; k < sizeof measured_other / sizeof measured_other[0]; k++)
        if (has_word(key, measured_other[k][0])) {
            cs_error_set(err, CS_ERR_INVALID,
                         "%s:1:%d: '%s' names %s %s (expected the vehicle's along its travel, not averaged)",
                         path, col, shown, found->what, measured_other[k][1]);
            return NULL;
        }
    return found;
}

cs_status cs_trace_load_measured(const char *path, cs_units *units, cs_trace *tr, cs_error *err) {
    clear(tr, path, 1);
    csv_file f;
    size_t rows;
    cs_status rc = read_all(path, &f, &rows, err);
    if (rc != CS_OK) return rc;
    enum { MEASURED_COLS = 16 };
    char unit[64], text[96];
    int target[MEASURED_COLS], more;
    double factor[MEASURED_COLS];
    int is_run = is_run_series(f.text);
    if (is_run != 0) { /* a run's own timeseries.csv, read as a run's (or out of memory) */
        free(f.text);
        return is_run < 0 ? cs_error_set(err, CS_ERR_MEMORY, "%s: out of memory", path)
                          : read_run_series(path, tr, err);
    }
    cs_csv csv;
    cs_csv_open_text(&csv, f.text, HISTORY_CSV, MEASURED_COLS);
    if (alloc_trace(tr, rows + 1) != 0) {
        rc = cs_error_set(err, CS_ERR_MEMORY, "%s: out of memory", path);
        goto done;
    }
    if (cs_csv_next(&csv) < 0) {
        rc = row_problem(&csv, path, err);
        goto done;
    }
    int nh = csv.count, *hcol = csv.cell_col;
    char **head = csv.cell;
    if (nh < 2) {
        rc = cs_error_set(err, CS_ERR_INVALID,
                          "%s:1:1: a header of a time column and at least one more (expected e.g. "
                          "\"time [s],deceleration [g]\")",
                          path);
        goto done;
    }
    for (int j = 0; j < nh; j++) {
        cs_error unit_err;
        brief_cell b, b2;
        int name_len = header_unit(head[j], unit, sizeof unit);
        if (name_len < 0) {
            rc = cs_error_set(err, CS_ERR_INVALID,
                              "%s:1:%d: '%s' has no unit (expected \"name [unit]\" or \"name (unit)\")", path,
                              hcol[j], brief(head[j], &b));
            goto done;
        }
        snprintf(text, sizeof text, "1 %s", unit);
        target[j] = -1;
        const struct measured_name *m = NULL;
        if (j == 0) {
            if (cs_units_read(units, text, CS_Q_TIME, &factor[0], &unit_err) != CS_OK) {
                rc = cs_error_set(err, CS_ERR_INVALID, "%s:1:%d: the first column is the time: %s", path,
                                  hcol[0], unit_err.message);
                goto done;
            }
        } else if (!(m = measured_name(path, hcol[j], head[j], name_len, err))) {
            rc = CS_ERR_INVALID;
            goto done;
        } else if (cs_units_read(units, text, m->q, &factor[j], &unit_err) != CS_OK) {
            rc = cs_error_set(err, CS_ERR_INVALID, "%s:1:%d: '%s' names %s: %s (expected %s)", path, hcol[j],
                              brief(head[j], &b), m->what, unit_err.message, m->units);
            goto done;
        }
        char other[64];
        const char *at =
            second_unit(units, head[j], head[j] + name_len, m ? m->q : CS_Q_TIME, other, sizeof other);
        if (at) {
            int first = at < head[j] + name_len;
            rc = cs_error_set(err, CS_ERR_INVALID,
                              "%s:1:%d: '%s' names two units of %s, '%s' and '%s' (expected one, as "
                              "\"name [unit]\" or \"name (unit)\")",
                              path, hcol[j], brief(head[j], &b), m ? m->what : "the time",
                              first ? other : unit, first ? unit : other);
            goto done;
        }
        if (j == 0) continue;
        target[j] = m->trace, factor[j] *= m->sign;
        for (int i = 1; i < j; i++)
            if (target[i] == target[j]) {
                rc = cs_error_set(err, CS_ERR_INVALID,
                                  "%s:1:%d: '%s' is a second column of the quantity of '%s' (the header's "
                                  "column %d, at 1:%d) (expected one column of each)",
                                  path, hcol[j], brief(csv.cell[j], &b), brief(csv.cell[i], &b2), i + 1,
                                  hcol[i]);
                goto done;
            }
        tr->have[target[j]] = 1;
    }
    csv.flags |= CS_CSV_BLANKS;
    while ((rc = next_row(&csv, nh, path, &more, err)) == CS_OK && more) {
        char **cells = csv.cell;
        int *col = csv.cell_col;
        long line = csv.line;
        size_t i = tr->n;
        for (int j = 0; j < nh; j++) {
            double x;
            if ((rc = cell_number(&csv, j, path, &x, err)) != CS_OK) goto done;
            if (j == 0 && isnan(x)) {
                rc = cs_error_set(err, CS_ERR_INVALID, "%s:%ld:%d: no time (expected one in every row)", path,
                                  line, col[j]);
                goto done;
            }
            if (fabs(x * factor[j]) > 1e12) { /* squared by the metrics, and beyond any crash history */
                rc = cs_error_set(
                    err, CS_ERR_INVALID,
                    "%s:%ld:%d: '%s' is too large (expected at most 1e12 in SI units, far beyond "
                    "any crash history)",
                    path, line, col[j], brief(cells[j], &(brief_cell){0}));
                goto done;
            }
            if (j == 0)
                tr->t[i] = x * factor[0];
            else
                tr->y[target[j]][i] = x * factor[j];
        }
        if (i > 0 && !(tr->t[i] > tr->t[i - 1])) {
            rc = cs_error_set(err, CS_ERR_INVALID,
                              "%s:%ld:%d: the time goes back or stands (expected it to grow row by row)",
                              path, line, col[0]);
            goto done;
        }
        tr->n++;
    }
    if (rc != CS_OK) goto done;
    if (tr->n < 2) {
        rc = cs_error_set(err, CS_ERR_INVALID, "%s:2:1: fewer than two rows of data", path);
        goto done;
    }
    /* the 50-ms average as the engine takes it: from the speed if given, else from the deceleration */
    if (tr->have[CS_TRACE_SPEED]) {
        average_from_speed(tr->t, tr->y[CS_TRACE_SPEED], tr->n, tr->y[CS_TRACE_DECEL_50MS]);
        tr->have[CS_TRACE_DECEL_50MS] = 1;
    } else if (tr->have[CS_TRACE_DECEL]) {
        cs_trace_average_50ms(tr->t, tr->y[CS_TRACE_DECEL], tr->n, tr->y[CS_TRACE_DECEL_50MS]);
        tr->have[CS_TRACE_DECEL_50MS] = 1;
    }
    derive(tr);
    rc = CS_OK;
done:
    free(f.text);
    cs_csv_close(&csv);
    if (rc != CS_OK) cs_trace_free(tr);
    return rc;
}
