/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include "out/studyreport.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "out/html.h"
#include "out/sweepout.h"
#include "status.h"

/* ---- the study's numbers ---- */

typedef struct response_def {
    const char *column, *key, *title, *axis;
    double scale; /* shown = the column's value * scale */
} response_def;

static const response_def responses[CS_STUDY_RESPONSES] = {
    {"max_50ms_decel", "deceleration", "max 50-ms deceleration", "max 50-ms deceleration (g)", 1.0},
    {"max_dynamic_penetration", "penetration", "max dynamic penetration", "max dynamic penetration (m)", 1.0},
    {"max_barrier_deflection", "deflection", "max barrier deflection", "max barrier deflection (m)", 1.0},
    {"working_width", "working-width", "working width", "working width (m)", 1.0},
    {"max_cable_tension", "tension", "max cable tension", "max cable tension (kN)", 1e-3},
    {"penetration_beyond", "penetration-beyond", "penetration beyond (runs the barrier did not hold)",
     "penetration beyond (m)", 1.0},
    {"exit_speed", "exit-speed", "exit speed (runs that left the barrier)", "exit speed (m/s)", 1.0},
};

static const cs_outcome outcomes[] = {CS_STOPPED,    CS_BREAKTHROUGH,     CS_REDIRECTED,
                                      CS_OVERRIDE,   CS_UNDERRIDE,        CS_TIME_LIMIT,
                                      CS_NO_CONTACT, CS_DID_NOT_CONVERGE, CS_STEP_LIMIT};
enum { OUTCOMES = sizeof outcomes / sizeof outcomes[0] };

typedef struct study {
    long ok;                       /* runs that ran to their end */
    double *y[CS_STUDY_RESPONSES]; /* [ok], shown units; NaN: none */
    double *in;                    /* [var * ok + i]: each numeric input as used, SI */
    double *rho;                   /* [response * var]: Spearman over the runs with a value; NaN: none */
    int *outcome;                  /* [ok] index into outcomes */
    long count[OUTCOMES];
} study;

static void study_free(study *s) {
    for (int q = 0; q < CS_STUDY_RESPONSES; q++)
        free(s->y[q]);
    free(s->in), free(s->rho), free(s->outcome);
}

static int study_make(study *s, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                      long n) {
    memset(s, 0, sizeof *s);
    long m = 0;
    for (long i = 0; i < n; i++)
        m += r[i].status == CS_RUN_OK && !r[i].pending;
    int k = spec->var_count;
    size_t cells = (size_t)(m > 0 ? m : 1);
    for (int q = 0; q < CS_STUDY_RESPONSES; q++)
        s->y[q] = malloc(cells * sizeof *s->y[q]);
    s->in = malloc(cells * (size_t)(k > 0 ? k : 1) * sizeof *s->in);
    s->rho = malloc((size_t)CS_STUDY_RESPONSES * (size_t)(k > 0 ? k : 1) * sizeof *s->rho);
    s->outcome = malloc(cells * sizeof *s->outcome);
    double *a = malloc(cells * sizeof *a), *b = malloc(cells * sizeof *b);
    int ok = s->in && s->rho && s->outcome && a && b;
    for (int q = 0; q < CS_STUDY_RESPONSES; q++)
        ok = ok && s->y[q];
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int nc = cs_sweep_columns(cols), col[CS_STUDY_RESPONSES];
    for (int q = 0; q < CS_STUDY_RESPONSES; q++) {
        col[q] = -1;
        for (int c = 0; c < nc; c++)
            if (strcmp(cols[c].name, responses[q].column) == 0) col[q] = c;
        ok = ok && col[q] >= 0;
    }
    if (!ok) {
        free(a), free(b), study_free(s);
        return -1;
    }
    for (long i = 0; i < n; i++) {
        if (r[i].status != CS_RUN_OK || r[i].pending) continue; /* a partial sweep's runs not run yet */
        long j = s->ok++;
        for (int q = 0; q < CS_STUDY_RESPONSES; q++)
            s->y[q][j] = cs_sweep_column_number(&cols[col[q]], &r[i]) * responses[q].scale;
        for (int v = 0; v < k; v++)
            s->in[(size_t)v * cells + (size_t)j] =
                spec->vars[v].numeric ? cs_sweep_value_used(&spec->vars[v], x[i * k + v]) : NAN;
        s->outcome[j] = 0;
        for (int o = 0; o < OUTCOMES; o++)
            if (r[i].summary.outcome == outcomes[o]) s->outcome[j] = o;
        s->count[s->outcome[j]]++;
    }
    for (int q = 0; q < CS_STUDY_RESPONSES; q++)
        for (int v = 0; v < k; v++) {
            long m2 = 0;
            for (long i = 0; i < s->ok; i++)
                if (isfinite(s->y[q][i])) a[m2] = s->in[(size_t)v * cells + (size_t)i], b[m2++] = s->y[q][i];
            s->rho[q * k + v] = spec->vars[v].numeric ? cs_spearman(a, b, m2) : NAN;
        }
    free(a), free(b);
    return 0;
}

/* Input v of run i in the unit the spec wrote it in (cs_sweep_var's shown_unit). */
static double input_at(const study *s, const cs_sweep_spec *spec, int v, long i) {
    double scale = spec->vars[v].shown_scale;
    return s->in[(size_t)v * (size_t)(s->ok > 0 ? s->ok : 1) + (size_t)i] / (scale > 0 ? scale : 1);
}

static const char *input_unit(const cs_sweep_var *v) {
    return v->shown_scale > 0 ? v->shown_unit : v->unit;
}

/* The input most correlated with response q (largest |rho|), or -1. */
static int strongest(const study *s, const cs_sweep_spec *spec, int q) {
    int best = -1;
    for (int v = 0; v < spec->var_count; v++) {
        double rho = s->rho[q * spec->var_count + v];
        if (isfinite(rho) && (best < 0 || fabs(rho) > fabs(s->rho[q * spec->var_count + best]))) best = v;
    }
    return best;
}

/* Whether response q has a value in any run. */
static int has_values(const study *s, int q) {
    for (long i = 0; i < s->ok; i++)
        if (isfinite(s->y[q][i])) return 1;
    return 0;
}

/* ---- the figures ---- */

int cs_study_figure_shown(int k, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                          long n) {
    study s;
    if (k == 0 || study_make(&s, spec, x, r, n) != 0) return 1; /* out of memory: the figure says so */
    int shown = has_values(&s, (k - 1) % CS_STUDY_RESPONSES);
    study_free(&s);
    return shown;
}

static const char *const kinds[] = {"histogram", "tornado", "scatter"};

void cs_study_figure_file(int k, char *buf, size_t size) {
    if (k == 0)
        snprintf(buf, size, "plots/study-outcomes.png");
    else
        snprintf(buf, size, "plots/study-%s-%s.png", kinds[(k - 1) / CS_STUDY_RESPONSES],
                 responses[(k - 1) % CS_STUDY_RESPONSES].key);
}

typedef struct figure_job {
    int k;
    const cs_sweep_spec *spec;
    const study *s;
} figure_job;

static cs_box whole(const cs_plot *p) {
    return (cs_box){8, 8, p->width - 16, p->height - 16};
}

static void bar(cs_plot *p, cs_axes *a, double x0, double x1, double y0, double y1, cs_rgb fill) {
    const double xs[] = {x0, x1, x1, x0}, ys[] = {y0, y0, y1, y1};
    cs_style edge = {{0.2, 0.2, 0.2}, 0.6, CS_SOLID, CS_MARK_NONE, 0};
    cs_plot_polygon(p, a, xs, ys, 4, &fill, &edge);
}

static void draw_outcomes(cs_plot *p, const study *s) {
    char title[96], names[OUTCOMES][48];
    const char *cats[OUTCOMES];
    snprintf(title, sizeof title, "outcomes of %ld runs, with 95%% Wilson intervals", s->ok);
    for (int o = 0; o < OUTCOMES; o++) {
        snprintf(names[o], sizeof names[o], "%s (%ld)", cs_outcome_name(outcomes[o]), s->count[o]);
        cats[o] = names[o];
    }
    cs_axes a;
    cs_axes_init(&a, title, NULL, "probability");
    a.xcat = cats, a.xcat_count = OUTCOMES;
    cs_axes_set_x(&a, -0.6, OUTCOMES - 0.4);
    cs_axes_set_y(&a, 0.0, 1.05);
    cs_axes_layout(p, &a, whole(p));
    cs_style whisker = {{0.1, 0.1, 0.1}, 1.4, CS_SOLID, CS_MARK_NONE, 0};
    for (int o = 0; o < OUTCOMES && s->ok > 0; o++) {
        cs_interval w = cs_wilson(s->count[o], s->ok, 1.959963984540054);
        bar(p, &a, o - 0.35, o + 0.35, 0.0, w.p, cs_plot_palette(o));
        cs_plot_segment(p, &a, o, w.lo, o, w.hi, &whisker);
    }
}

static void draw_histogram(cs_plot *p, const study *s, int q) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    long m = 0;
    for (long i = 0; i < s->ok; i++)
        if (isfinite(s->y[q][i])) lo = fmin(lo, s->y[q][i]), hi = fmax(hi, s->y[q][i]), m++;
    char title[160];
    snprintf(title, sizeof title, "%s: %ld runs with a value", responses[q].title, m);
    cs_axes a;
    cs_axes_init(&a, title, responses[q].axis, "runs");
    int bins = (int)fmin(40.0, fmax(5.0, ceil(sqrt((double)m))));
    if (hi - lo < 1e-12 * fmax(1.0, fabs(hi))) lo -= 0.5, hi += 0.5; /* all alike: one bar in the middle */
    long *c = calloc((size_t)bins, sizeof *c), top = 0;
    if (!c) return;
    for (long i = 0; i < s->ok; i++)
        if (isfinite(s->y[q][i])) {
            int b = (int)((s->y[q][i] - lo) / (hi - lo) * bins);
            c[b >= bins ? bins - 1 : b]++;
        }
    for (int b = 0; b < bins; b++)
        top = c[b] > top ? c[b] : top;
    cs_axes_fit_point(&a, lo, 0.0), cs_axes_fit_point(&a, hi, (double)top);
    cs_axes_layout(p, &a, whole(p));
    for (int b = 0; b < bins; b++)
        if (c[b] > 0)
            bar(p, &a, lo + (hi - lo) * b / bins, lo + (hi - lo) * (b + 1) / bins, 0.0, (double)c[b],
                cs_plot_palette(0));
    free(c);
}

static void draw_tornado(cs_plot *p, const cs_sweep_spec *spec, const study *s, int q) {
    int k = spec->var_count, order[CS_SWEEP_MAX_VARS], m = 0;
    for (int v = 0; v < k; v++)
        if (isfinite(s->rho[q * k + v])) order[m++] = v;
    for (int i = 1; i < m; i++) /* by |rho|, largest on top */
        for (int j = i; j > 0 && fabs(s->rho[q * k + order[j]]) > fabs(s->rho[q * k + order[j - 1]]); j--) {
            int t = order[j];
            order[j] = order[j - 1], order[j - 1] = t;
        }
    char title[160];
    const char *names[CS_SWEEP_MAX_VARS]; /* the y axis: an input a row, the strongest on top */
    for (int i = 0; i < m; i++)
        names[m - 1 - i] = spec->vars[order[i]].path;
    snprintf(title, sizeof title, "%s: Spearman rank correlation of each input", responses[q].title);
    cs_axes a;
    cs_axes_init(&a, title, "rank correlation with the response", NULL);
    a.ycat = names, a.ycat_count = m;
    cs_axes_set_x(&a, -1.0, 1.0);
    cs_axes_set_y(&a, -0.5, m > 0 ? m - 0.5 : 0.5);
    cs_axes_layout(p, &a, whole(p));
    for (int i = 0; i < m; i++) {
        double rho = s->rho[q * k + order[i]], y = m - 1 - i;
        bar(p, &a, 0.0, rho, y - 0.35, y + 0.35, rho >= 0 ? cs_plot_palette(3) : cs_plot_palette(0));
        char label[16];
        snprintf(label, sizeof label, "%+.2f", rho);
        cs_plot_label(p, &a, rho >= 0 ? -0.02 : 0.02, y, 0, 0, rho >= 0 ? 1.0 : 0.0, label);
    }
    if (m == 0) cs_plot_label(p, &a, 0.0, 0.0, 0, 0, 0.5, "no numeric input varies with it");
}

static void draw_scatter(cs_plot *p, const cs_sweep_spec *spec, const study *s, int q) {
    int v = strongest(s, spec, q);
    char title[320], xlabel[300];
    if (v >= 0)
        snprintf(title, sizeof title, "%s against the input most correlated with it (rho %+.2f)",
                 responses[q].title, s->rho[q * spec->var_count + v]);
    else
        snprintf(title, sizeof title, "%s: no numeric input varies with it", responses[q].title);
    snprintf(xlabel, sizeof xlabel, "%s (%s)", v >= 0 ? spec->vars[v].path : "-",
             v >= 0 ? input_unit(&spec->vars[v]) : "");
    cs_axes a;
    cs_axes_init(&a, title, xlabel, responses[q].axis);
    for (long i = 0; v >= 0 && i < s->ok; i++)
        if (isfinite(s->y[q][i])) cs_axes_fit_point(&a, input_at(s, spec, v, i), s->y[q][i]);
    if (v < 0) cs_axes_set_x(&a, 0.0, 1.0), cs_axes_set_y(&a, 0.0, 1.0);
    cs_axes_layout(p, &a, whole(p));
    for (int o = 0; v >= 0 && o < OUTCOMES; o++) { /* one series per outcome, so the legend names them */
        if (s->count[o] == 0) continue;
        cs_style dot = {cs_plot_palette(o), 0, CS_SOLID, CS_MARK_CIRCLE, 4};
        int shown = 0;
        for (long i = 0; i < s->ok; i++) {
            if (s->outcome[i] != o || !isfinite(s->y[q][i])) continue;
            double px = input_at(s, spec, v, i), py = s->y[q][i];
            cs_plot_line(p, &a, &px, &py, 1, &dot, shown ? NULL : cs_outcome_name(outcomes[o]));
            shown = 1;
        }
    }
    if (v >= 0) cs_plot_legend(p, &a, CS_LEGEND_TOP_RIGHT);
}

static cs_status draw(cs_plot *p, const void *user, cs_error *err) {
    const figure_job *job = user;
    (void)err;
    int k = job->k;
    if (k == 0)
        draw_outcomes(p, job->s);
    else if (k <= CS_STUDY_RESPONSES)
        draw_histogram(p, job->s, k - 1);
    else if (k <= 2 * CS_STUDY_RESPONSES)
        draw_tornado(p, job->spec, job->s, k - 1 - CS_STUDY_RESPONSES);
    else
        draw_scatter(p, job->spec, job->s, k - 1 - 2 * CS_STUDY_RESPONSES);
    return CS_OK;
}

enum { WIDTH = 900, HEIGHT = 480 };

cs_status cs_study_write_figure(FILE *f, cs_plot_format format, int k, const cs_sweep_spec *spec,
                                const double *x, const cs_sweep_result *r, long n, cs_error *err) {
    study s;
    if (study_make(&s, spec, x, r, n) != 0)
        return cs_error_set(err, CS_ERR_MEMORY, "out of memory for the study's figures");
    figure_job job = {k, spec, &s};
    cs_status rc = cs_plot_write(f, format, WIDTH, HEIGHT, draw, &job, err);
    study_free(&s);
    return rc;
}

/* ---- the page ---- */

cs_status cs_study_write_page(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                              long n, cs_error *err) {
    study s;
    if (study_make(&s, spec, x, r, n) != 0)
        return cs_error_set(err, CS_ERR_MEMORY, "out of memory for the study's page");
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>cablesim study: ", f);
    cs_html_text(f, spec->file);
    fputs("</title>\n<style>body{font-family:sans-serif;margin:1.5em;max-width:1000px}table{border-collapse:"
          "collapse;margin:0.5em 0}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}"
          "td:first-child,th:first-child,#inputs td:nth-child(-n+3),#inputs "
          "th:nth-child(-n+3){text-align:left}svg{max-width:100%;height:auto}"
          "@media print{svg{page-break-inside:avoid}}</style></head><body>\n<h1>Study: ",
          f);
    cs_html_text(f, spec->file);
    fprintf(f, "</h1>\n<p>%s of %ld runs of ", cs_sweep_method_name(spec->method), n);
    cs_html_text(f, spec->model);
    fprintf(f, "; %ld ran to their end (the others are counted in summary.md).</p>\n", s.ok);
    fputs("<h2>Inputs</h2>\n<p>Each varied value as the spec gives it, and the values its runs used, in "
          "the spec's unit.</p>\n<table id=\"inputs\"><tr><th>input</th><th>varied as</th><th>unit</th>"
          "<th>min</th><th>median</th><th>max</th></tr>\n",
          f);
    double *sorted = malloc((size_t)(s.ok > 0 ? s.ok : 1) * sizeof *sorted);
    for (int v = 0; v < spec->var_count; v++) {
        const cs_sweep_var *var = &spec->vars[v];
        fputs("<tr><td>", f);
        cs_html_text(f, var->path);
        fputs("</td><td>", f);
        cs_html_text(f, var->desc);
        fputs("</td><td>", f);
        cs_html_text(f, var->numeric ? input_unit(var) : "");
        long m = 0;
        for (long i = 0; sorted && var->numeric && i < s.ok; i++)
            sorted[m++] = input_at(&s, spec, v, i);
        cs_sweep_sort(sorted, m);
        if (m == 0)
            fputs("</td><td>-</td><td>-</td><td>-</td></tr>\n", f);
        else
            fprintf(f, "</td><td>%.6g</td><td>%.6g</td><td>%.6g</td></tr>\n", sorted[0],
                    cs_sweep_quantile(sorted, m, 0.5), sorted[m - 1]);
    }
    fputs("</table>\n<h2>Outcomes</h2>\n<table><tr><th>outcome</th><th>runs</th><th>probability</th>"
          "<th>95% interval</th></tr>\n",
          f);
    for (int o = 0; o < OUTCOMES; o++) {
        cs_interval w = cs_wilson(s.count[o], s.ok, 1.959963984540054);
        fprintf(f, "<tr><td>%s</td><td>%ld</td><td>%.3f</td><td>%.3f-%.3f</td></tr>\n",
                cs_outcome_name(outcomes[o]), s.count[o], s.ok ? w.p : NAN, s.ok ? w.lo : NAN,
                s.ok ? w.hi : NAN);
    }
    fputs("</table>\n<h2>Responses</h2>\n<table><tr><th>response</th><th>runs</th><th>mean</th><th>min</th>"
          "<th>5%</th><th>median</th><th>95%</th><th>max</th></tr>\n",
          f);
    for (int q = 0; sorted && q < CS_STUDY_RESPONSES; q++) {
        long m = 0;
        double sum = 0.0;
        for (long i = 0; i < s.ok; i++)
            if (isfinite(s.y[q][i])) sorted[m++] = s.y[q][i], sum += s.y[q][i];
        cs_sweep_sort(sorted, m);
        fprintf(f, "<tr><td>%s</td><td>%ld</td>", responses[q].axis, m);
        if (m == 0) {
            fputs("<td>-</td><td>-</td><td>-</td><td>-</td><td>-</td><td>-</td></tr>\n", f);
            continue;
        }
        const double at[] = {0.0, 0.05, 0.5, 0.95, 1.0};
        fprintf(f, "<td>%.4g</td>", sum / (double)m);
        for (int i = 0; i < 5; i++)
            fprintf(f, "<td>%.4g</td>", cs_sweep_quantile(sorted, m, at[i]));
        fputs("</tr>\n", f);
    }
    free(sorted);
    fputs("</table>\n", f);
    int none = 0; /* the responses no run has a value of, named once */
    for (int q = 0; q < CS_STUDY_RESPONSES; q++)
        if (!has_values(&s, q)) {
            fputs(none++ ? ", " : "<p>No run has a value of ", f);
            cs_html_text(f, responses[q].title);
        }
    if (none > 0) fputs(": their figures are left out.</p>\n", f);
    cs_status rc = cs_status_set(err, CS_OK, "");
    for (int k = 0; k < CS_STUDY_FIGURES && rc == CS_OK; k++) {
        if (k > 0 && !has_values(&s, (k - 1) % CS_STUDY_RESPONSES)) continue;
        char id[16];
        snprintf(id, sizeof id, "f%d", k);
        figure_job job = {k, spec, &s};
        fputs("<div>", f);
        rc = cs_html_figure(f, id, WIDTH, HEIGHT, draw, &job, err);
        fputs("</div>\n", f);
    }
    fputs("</body></html>\n", f);
    study_free(&s);
    return rc;
}
