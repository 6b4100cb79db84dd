/* SPDX-License-Identifier: MIT */
/* The plots of a sweep (`plot:` in the spec, sweepout.h), drawn with the plotting layer (plot.h) from
 * runs.csv's own columns: a response against a varied value, a line per level of another varied value of
 * a grid joining its runs in order of x, or each run a point (Monte Carlo, Latin hypercube). A run that
 * got through (broke through, rode over or ran under the cables) is marked with a cross; a run that did not
 * run to the end, or has no value of the response, is left out, and the caption counts each. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/units.h"
#include "plot.h"
#include "status.h"
#include "sweepout.h"

static const double WIDTH = 1200, HEIGHT = 760, MARGIN = 8, CAPTION = 56, LEGEND_WIDTH = 260, NOTE = 14;
static const cs_rgb BLACK = {0.1, 0.1, 0.1};

/* ---- names and units ---- */

/* A unit as the run's figures show it: a value in SI times scale, in unit; where they add a US unit on
 * the right axis (feet beside metres, mph beside m/s, kip beside kN), us at SI times us_scale. */
typedef struct display {
    const char *si, *unit;
    double scale;
    const char *us;
    double us_scale;
} display;

static display display_of(const char *si) {
    static const display known[] = {
        {"m", "m", 1, "ft", 1 / CS_FT},       {"m/s", "m/s", 1, "mph", 1 / CS_MPH},
        {"N", "kN", 1e-3, "kip", 1 / CS_KIP}, {"J", "kJ", 1e-3, NULL, 0},
        {"Pa", "kPa", 1e-3, NULL, 0},         {"rad", "deg", 1 / CS_DEG, NULL, 0},
    };
    for (size_t i = 0; si && i < sizeof known / sizeof known[0]; i++)
        if (strcmp(si, known[i].si) == 0) return known[i];
    return (display){si, si && strcmp(si, "1") != 0 && si[0] ? si : NULL, 1, NULL, 0};
}

/* "what (unit)", or what alone where there is no unit. */
static void with_unit(char *buf, size_t size, const char *what, const char *unit) {
    snprintf(buf, size, "%s%s%s%s", what, unit ? " (" : "", unit ? unit : "", unit ? ")" : "");
}

/* A column name in words: "max_barrier_deflection": "max barrier deflection". */
static void words(const char *name, char *buf, size_t size) {
    snprintf(buf, size, "%s", name);
    for (char *c = buf; *c; c++)
        if (*c == '_') *c = ' ';
}

/* The last key of a path: "barrier.posts[0].spacing": "spacing". */
static const char *last_key(const char *path) {
    const char *dot = strrchr(path, '.');
    return dot ? dot + 1 : path;
}

/* The column of runs.csv named name into col; 0 if there is none. */
static int find_column(const char *name, cs_sweep_column *col) {
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int count = cs_sweep_columns(cols);
    for (int c = 0; c < count; c++)
        if (strcmp(cols[c].name, name) == 0) {
            *col = cols[c];
            return 1;
        }
    return 0;
}

void cs_sweep_plot_file(const cs_sweep_spec *spec, int k, char *buf, size_t size) {
    const cs_sweep_plot *p = &spec->plots[k];
    char x[128];
    cs_sweep_name(last_key(spec->vars[p->x].path), x, sizeof x);
    snprintf(buf, size, "plots/%s-vs-%s.%s", p->y, x, p->format);
}

int cs_sweep_plots_check(cs_sweep_spec *spec) {
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS], col;
    int count = cs_sweep_columns(cols), before = spec->error_count;
    char names[800] = "";
    for (int c = 0, used = 0; c < count; c++)
        if (cols[c].kind != CS_COLUMN_TEXT && strncmp(cols[c].name, "events_", 7) != 0)
            used += snprintf(names + used, sizeof names - (size_t)used, "%s, ", cols[c].name);
    for (int k = 0; k < spec->plot_count; k++) {
        const cs_sweep_plot *p = &spec->plots[k];
        if (!p->y) continue; /* reported by the reader */
        int known = find_column(p->y, &col);
        if (!known)
            cs_sweep_error(spec, p->y_line, p->y_col,
                           "plot: y: unknown response '%s' (expected a number column of runs.csv: %sor "
                           "events_TYPE, the count of a failure event type)",
                           p->y, names);
        else if (col.kind == CS_COLUMN_TEXT)
            cs_sweep_error(spec, p->y_line, p->y_col,
                           "plot: y: %s is text (expected a number column of runs.csv, e.g. "
                           "max_barrier_deflection)",
                           p->y);
        if (!known || col.kind == CS_COLUMN_TEXT || p->x < 0) continue;
        char file[256], other[256];
        cs_sweep_plot_file(spec, k, file, sizeof file);
        for (int j = 0; j < k; j++) {
            const cs_sweep_plot *q = &spec->plots[j];
            if (!q->y || q->x < 0) continue;
            cs_sweep_plot_file(spec, j, other, sizeof other);
            if (strcmp(file, other) == 0) {
                cs_sweep_error(spec, p->line, p->col,
                               "plot: %s is the file of the plot at %d:%d too (expected another y, x or "
                               "format)",
                               file, q->line, q->col);
                break;
            }
        }
    }
    return spec->error_count > before ? -1 : 0;
}

/* ---- what a plot shows ---- */

/* "y against x, a line per lines" (a grid), or "..., each run a point". */
static void plot_what(const cs_sweep_spec *spec, int k, char *buf, size_t size) {
    const cs_sweep_plot *p = &spec->plots[k];
    snprintf(buf, size, "%s against %s%s%s", p->y, spec->vars[p->x].path,
             p->lines >= 0                   ? ", a line per "
             : spec->method != CS_SWEEP_GRID ? ", each run a point"
                                             : "",
             p->lines >= 0 ? spec->vars[p->lines].path : "");
}

/* How many runs plot k shows, marks and leaves out, in words. */
static void plot_counts(const cs_sweep_spec *spec, int k, const cs_sweep_result *r, long n, char *buf,
                        size_t size) {
    const cs_sweep_plot *p = &spec->plots[k];
    cs_sweep_column col;
    long shown = 0, broke = 0, failed = 0, missing = 0, pending = 0;
    if (!find_column(p->y, &col)) {
        snprintf(buf, size, "runs.csv has no column %s", p->y);
        return;
    }
    for (long i = 0; i < n; i++) {
        if (r[i].pending)
            pending++;
        else if (r[i].status != CS_RUN_OK)
            failed++;
        else if (!isfinite(cs_sweep_column_number(&col, &r[i])))
            missing++;
        else
            shown++, broke += cs_outcome_through(r[i].summary.outcome);
    }
    /* each count with its noun, and none of 0: "left out: 0 that ..." reads as run 0 */
    int used = snprintf(buf, size, "%ld of %ld runs shown, %ld broke through (marked with a cross); ", shown,
                        n, broke);
    const long left[] = {failed, missing, pending};
    const char *const why[] = {"that did not run to the end", "with no ", "not run yet (a partial sweep)"};
    for (int k = 0, listed = 0; k < 3; k++)
        if (left[k] > 0 && used > 0 && (size_t)used < size)
            used += snprintf(buf + used, size - (size_t)used, "%s%ld run%s %s%s",
                             listed++ ? ", " : "left out: ", left[k], left[k] == 1 ? "" : "s", why[k],
                             k == 1 ? p->y : "");
    if (failed + missing + pending == 0 && used > 0 && (size_t)used < size)
        snprintf(buf + used, size - (size_t)used, "none left out");
}

void cs_sweep_plot_caption(const cs_sweep_spec *spec, int k, const cs_sweep_result *r, long n, char *buf,
                           size_t size) {
    char what[600], counts[300];
    plot_what(spec, k, what, sizeof what);
    plot_counts(spec, k, r, n, counts, sizeof counts);
    snprintf(buf, size, "%s: %s", what, counts);
}

/* ---- drawing ---- */

/* A run as a point of the plot, in the units shown; group: its line (the level of lines). */
typedef struct point {
    double x, y;
    int group, broke;
} point;

static int by_line_then_x(const void *a, const void *b) {
    const point *p = a, *q = b;
    if (p->group != q->group) return p->group < q->group ? -1 : 1;
    return (p->x > q->x) - (p->x < q->x);
}

/* Level l of a varied value as the legend shows it: "diameter = 50 mm", the value as the spec writes it,
 * or in the units shown where the spec gives a bare number (a range's levels). */
static void level_label(const cs_sweep_var *v, int l, char *buf, size_t size) {
    const char *text = v->texts[l];
    char *end;
    strtod(text, &end);
    while (*end == ' ')
        end++;
    if (v->numeric && end != text && *end == '\0') {
        display d = display_of(v->unit);
        snprintf(buf, size, "%s = %.4g%s%s", last_key(v->path), v->levels[l] * d.scale, d.unit ? " " : "",
                 d.unit ? d.unit : "");
    } else {
        snprintf(buf, size, "%s = %s", last_key(v->path), text);
    }
}

typedef struct plot_job {
    const cs_sweep_spec *spec;
    int k;
    const double *x;
    const cs_sweep_result *r;
    long n;
} plot_job;

/* The axes of plot k, laid out, with its title and labels (kept in text, which the axes point into). */
typedef struct plot_text {
    char title[200], xlabel[300], ylabel[120], y2label[120];
} plot_text;

static void plot_axes(cs_plot *p, cs_axes *a, plot_text *t, const cs_sweep_spec *spec, int k,
                      const char *y_unit, const point *pt, long m) {
    const cs_sweep_plot *pl = &spec->plots[k];
    const cs_sweep_var *vx = &spec->vars[pl->x];
    display dx = display_of(vx->unit), dy = display_of(y_unit);
    char y[64];
    words(pl->y, y, sizeof y);
    snprintf(t->title, sizeof t->title, "%s against %s", y, last_key(vx->path));
    with_unit(t->xlabel, sizeof t->xlabel, vx->path, dx.unit);
    with_unit(t->ylabel, sizeof t->ylabel, y, dy.unit);
    with_unit(t->y2label, sizeof t->y2label, y, dy.us);
    cs_axes_init(a, t->title, t->xlabel, t->ylabel);
    if (dy.us) a->y2label = t->y2label, a->y2_scale = dy.us_scale / dy.scale;
    a->legend_width = LEGEND_WIDTH;
    for (long i = 0; i < m; i++)
        cs_axes_fit_point(a, pt[i].x, pt[i].y);
    cs_axes_fit_point(a, NAN, 0);
    cs_axes_layout(p, a, (cs_box){MARGIN, MARGIN, p->width - 2 * MARGIN, p->height - 2 * MARGIN - CAPTION});
}

/* cs_plot_draw_fn: the runs with a value as points, a line per level of lines (or one, or none), the
 * crosses of the runs that broke through, the legend and the caption. */
static cs_status draw_plot(cs_plot *p, const void *user, cs_error *err) {
    char message[CS_MESSAGE_SIZE];
    const plot_job *job = user;
    const cs_sweep_spec *s = job->spec;
    const cs_sweep_plot *pl = &s->plots[job->k];
    const cs_sweep_var *vx = &s->vars[pl->x], *vl = pl->lines >= 0 ? &s->vars[pl->lines] : NULL;
    cs_sweep_column col;
    if (!find_column(pl->y, &col)) {
        snprintf(message, sizeof message, "plot: runs.csv has no column %s", pl->y);
        return cs_status_set(err, CS_ERR_INVALID, message);
    }
    size_t room = (size_t)(job->n > 0 ? job->n : 1);
    point *pt = malloc(room * sizeof *pt);
    double *xs = malloc(2 * room * sizeof *xs), *ys = xs ? xs + room : NULL;
    if (!pt || !xs) {
        free(pt), free(xs);
        snprintf(message, sizeof message, "out of memory while drawing plots/%s", pl->y);
        return cs_status_set(err, CS_ERR_MEMORY, message);
    }
    display dx = display_of(vx->unit), dy = display_of(col.unit);
    long m = 0;
    for (long i = 0; i < job->n; i++) {
        double y = cs_sweep_column_number(&col, &job->r[i]); /* NaN for a run that did not run to the end */
        if (!isfinite(y)) continue;
        pt[m++] = (point){cs_sweep_value_used(vx, job->x[i * s->var_count + pl->x]) * dx.scale, y * dy.scale,
                          vl ? cs_sweep_grid_level(s, i, pl->lines) : 0,
                          cs_outcome_through(job->r[i].summary.outcome)};
    }
    qsort(pt, (size_t)m, sizeof *pt, by_line_then_x);
    cs_axes a;
    plot_text text;
    plot_axes(p, &a, &text, s, job->k, col.unit, pt, m);
    int joined = s->method == CS_SWEEP_GRID;
    for (long i = 0, g = 0; g < (vl ? vl->level_count : 1); g++) {
        long start = i;
        for (; i < m && pt[i].group == g; i++)
            xs[i - start] = pt[i].x, ys[i - start] = pt[i].y;
        char label[CS_LABEL_SIZE] = "runs";
        if (vl) level_label(vl, (int)g, label, sizeof label);
        cs_style st = {cs_plot_palette((int)g), joined ? 2.5 : 0, CS_SOLID, CS_MARK_CIRCLE, 9};
        cs_plot_line(p, &a, xs, ys, (int)(i - start), &st, label);
    }
    long broke = 0;
    for (long i = 0; i < m; i++)
        if (pt[i].broke) xs[broke] = pt[i].x, ys[broke++] = pt[i].y;
    cs_style cross = {BLACK, 0, CS_SOLID, CS_MARK_CROSS, 16};
    cs_plot_line(p, &a, xs, ys, (int)broke, &cross, broke ? "broke through" : NULL);
    cs_plot_legend(p, &a, CS_LEGEND_OUTSIDE_RIGHT);
    char what[600], line[800], counts[300];
    plot_what(s, job->k, what, sizeof what);
    snprintf(line, sizeof line, "%s: %s", s->file, what);
    plot_counts(s, job->k, job->r, job->n, counts, sizeof counts);
    cs_plot_text(p, MARGIN + 10, p->height - MARGIN - 0.7 * CAPTION, NOTE, 0, 0, line);
    cs_plot_text(p, MARGIN + 10, p->height - MARGIN - 0.25 * CAPTION, NOTE, 0, 0, counts);
    free(pt), free(xs);
    return CS_OK;
}

cs_status cs_sweep_write_plot(FILE *f, const cs_sweep_spec *spec, int k, const double *x,
                              const cs_sweep_result *r, long n, cs_error *err) {
    char file[256];
    cs_sweep_plot_file(spec, k, file, sizeof file);
    plot_job job = {spec, k, x, r, n};
    return cs_plot_write(f, cs_plot_format_of(file), WIDTH, HEIGHT, draw_plot, &job, err);
}
