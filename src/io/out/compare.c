/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include "out/compare.h"
#include "cablesim/units.h"
#include "out/htmltext.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "out/html.h"
#include "out/numtext.h"
#include "out/plot.h"
#include "status.h"
#include "study/metrics.h"

/* ---- the plots ---- */

typedef struct figure {
    const char *name, *title, *ylabel, *y2label;
    int trace;
    double scale, y2_scale; /* y shown = SI value / scale; the right axis shows that times y2_scale */
} figure;

static const figure figures[CS_COMPARE_PLOTS] = {
    {"compare-deceleration", "deceleration along the initial heading", "deceleration (g)", NULL,
     CS_TRACE_DECEL, CS_G0, 0},
    {"compare-deceleration-50ms", "50-ms average deceleration", "deceleration (g)", NULL, CS_TRACE_DECEL_50MS,
     CS_G0, 0},
    {"compare-speed", "speed along the initial heading", "speed (m/s)", "speed (mph)", CS_TRACE_SPEED, 1.0,
     1.0 / CS_MPH},
    {"compare-penetration", "penetration past the cable line", "penetration (m)", "penetration (ft)",
     CS_TRACE_PENETRATION, 1.0, 1.0 / CS_FT},
    {"compare-tension", "largest rope tension", "tension (kN)", "tension (kip)", CS_TRACE_TENSION, 1e3,
     1e3 / CS_KIP},
};
enum { WIDTH = 960, HEIGHT = 520 };

typedef struct plot_job {
    const figure *fig;
    const cs_trace *traces;
    int count, reference;
} plot_job;

static cs_status draw(cs_plot *p, const void *user, cs_error *err) {
    const plot_job *job = user;
    const figure *f = job->fig;
    cs_axes a;
    cs_axes_init(&a, f->title, "time (s)", f->ylabel);
    a.y2label = f->y2label;
    a.y2_scale = f->y2_scale;
    size_t most = 0;
    for (int k = 0; k < job->count; k++)
        if (job->traces[k].n > most) most = job->traces[k].n;
    double *y = malloc((most ? most : 1) * sizeof *y);
    if (!y) return cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    double t0 = 0.0, t1 = -HUGE_VAL;       /* the time axis: from 0 (or an earlier start) to the last end */
    for (int pass = 0; pass < 2; pass++) { /* fit every trace, lay the axes out, then draw them */
        for (int k = 0; k < job->count; k++) {
            const cs_trace *tr = &job->traces[k];
            if (!tr->have[f->trace]) continue;
            for (size_t i = 0; i < tr->n; i++)
                y[i] = tr->y[f->trace][i] / f->scale;
            if (pass == 0) {
                cs_axes_fit(&a, tr->t, y, (int)tr->n);
                if (tr->n > 0) t0 = fmin(t0, tr->t[0]), t1 = fmax(t1, tr->t[tr->n - 1]);
                continue;
            }
            cs_style s = {tr->measured ? (cs_rgb){0.1, 0.1, 0.1} : cs_plot_palette(k),
                          tr->measured ? 2.0 : 1.6, tr->measured ? CS_DASHED : CS_SOLID, CS_MARK_NONE, 0};
            char label[CS_LABEL_SIZE];
            snprintf(label, sizeof label, "%.80s%s", tr->label, tr->measured ? " (measured)" : "");
            cs_plot_line(p, &a, tr->t, y, (int)tr->n, &s, label);
        }
        if (pass == 0) {
            if (t1 > t0) cs_axes_set_x(&a, t0, t1);
            cs_axes_fit_point(&a, NAN, 0.0);
            cs_axes_layout(p, &a, (cs_box){8, 8, p->width - 16, p->height - 16});
        }
    }
    cs_plot_legend(p, &a, CS_LEGEND_TOP_RIGHT);
    free(y);
    return CS_OK;
}

cs_status cs_compare_trace(int k, const cs_trace *traces, int count, int reference, cs_plot_log *log,
                           cs_error *err) {
    plot_job job = {&figures[k], traces, count, reference};
    return cs_plot_trace(WIDTH, HEIGHT, draw, &job, log, err);
}

/* ---- the table ---- */

typedef struct param {
    const char *name, *unit, *us_unit;
    double us_scale; /* the US value is SI / us_scale (0: none) */
    size_t offset;   /* of the double in cs_trace */
} param;

#define P(name, unit, us, scale, member)                                                                     \
    { name, unit, us, scale, offsetof(cs_trace, member) }
static const param params[] = {
    P("max 50-ms deceleration", "g", NULL, 0, max_decel_50ms_g),
    P("time of the max 50-ms deceleration", "s", NULL, 0, t_max_decel_50ms),
    P("max dynamic penetration", "m", "ft", CS_FT, max_penetration),
    P("penetration beyond", "m", "ft", CS_FT, penetration_beyond_m),
    P("max barrier deflection", "m", "ft", CS_FT, max_deflection),
    P("working width", "m", "ft", CS_FT, working_width),
    P("speed at the end along the initial heading", "m/s", "mph", CS_MPH, final_speed),
    P("exit speed", "m/s", "mph", CS_MPH, exit_speed),
    P("max cable tension", "N", "kip", CS_KIP, max_tension),
    P("end of the record", "s", NULL, 0, t_end),
};
enum { PARAMS = sizeof params / sizeof params[0] };

static double value(const cs_trace *tr, int k) {
    return *(const double *)((const char *)tr + params[k].offset);
}

/* Whether parameter k is a lower bound: how far a run that got through had got (summary.json's
 * penetration_beyond_m; its max_dynamic_penetration_m is null, and so is the table's). */
static int beyond(int k) {
    return params[k].offset == offsetof(cs_trace, penetration_beyond_m);
}

/* The difference from the reference in per cent, NAN where either is not given, is a lower bound, or
 * the reference is 0. */
static double difference(const cs_trace *tr, const cs_trace *ref, int k) {
    if (beyond(k)) return NAN; /* a lower bound is not compared */
    double x = value(tr, k), r = value(ref, k);
    return isfinite(x) && isfinite(r) && r != 0.0 ? 100.0 * (x - r) / fabs(r) : NAN;
}

int cs_compare_param_count(void) {
    return PARAMS;
}

const char *cs_compare_param_name(int k) {
    return k >= 0 && k < PARAMS ? params[k].name : NULL;
}

const char *cs_compare_param_unit(int k) {
    return k >= 0 && k < PARAMS ? params[k].unit : NULL;
}

double cs_compare_param_value(const cs_trace *tr, int k) {
    return k >= 0 && k < PARAMS ? value(tr, k) : NAN;
}

double cs_compare_param_difference(const cs_trace *tr, const cs_trace *ref, int k) {
    return k >= 0 && k < PARAMS ? difference(tr, ref, k) : NAN;
}

static void csv_text(FILE *f, const char *s) {
    cs_csv_text(f, s, 1);
}

static void write_csv(FILE *f, const cs_trace *tr, int count, int reference) {
    fputs("parameter,unit", f);
    for (int j = 0; j < count; j++)
        fputc(',', f), csv_text(f, tr[j].label);
    for (int j = 0; j < count; j++)
        if (j != reference) {
            char head[400];
            snprintf(head, sizeof head, "%s against %s [%%]", tr[j].label, tr[reference].label);
            fputc(',', f), csv_text(f, head);
        }
    fputs("\noutcome,", f);
    for (int j = 0; j < count; j++)
        fprintf(f, ",%s", tr[j].measured ? "" : tr[j].outcome);
    for (int j = 0; j < count; j++)
        if (j != reference) fputc(',', f);
    fputc('\n', f);
    for (int k = 0; k < PARAMS; k++) {
        fprintf(f, "%s,%s", params[k].name, params[k].unit);
        for (int j = 0; j < count; j++)
            isfinite(value(&tr[j], k)) ? fprintf(f, ",%.10g", value(&tr[j], k)) : fputs(",", f);
        for (int j = 0; j < count; j++) {
            if (j == reference) continue;
            double d = difference(&tr[j], &tr[reference], k);
            isfinite(d) ? fprintf(f, ",%.4g", d) : fputs(",", f);
        }
        fputc('\n', f);
    }
}

/* One cell of the readable table: "4.12 m (13.5 ft)", then "+3.1%" against the reference. */
static void cell(char *buf, size_t size, const cs_trace *tr, const cs_trace *ref, int k, int is_ref) {
    double x = value(tr, k), d = difference(tr, ref, k);
    if (!isfinite(x)) {
        snprintf(buf, size, "-");
        return;
    }
    const char *at_least = beyond(k) ? "beyond " : "";
    char t[CS_TIME_TEXT_SIZE];
    int n;
    if (strcmp(params[k].unit, "N") == 0) /* tensions in kN */
        n = snprintf(buf, size, "%.1f kN (%.1f kip)", x / 1e3, x / params[k].us_scale);
    else if (strcmp(params[k].unit, "s") == 0) /* a run's times as its other outputs give them */
        n = snprintf(buf, size, "%s%s s", at_least, cs_time_text(x, t));
    else if (params[k].us_scale > 0.0)
        n = snprintf(buf, size, "%s%.3f %s (%.2f %s)", at_least, x, params[k].unit, x / params[k].us_scale,
                     params[k].us_unit);
    else
        n = snprintf(buf, size, "%s%.3f %s", at_least, x, params[k].unit);
    if (!is_ref && isfinite(d) && n > 0 && (size_t)n < size)
        snprintf(buf + n, size - (size_t)n, ", %+.1f%%", d);
}

/* The table as Markdown (html 0) or as an HTML table (html 1). */
static void write_table(FILE *f, const cs_trace *tr, int count, int reference, int html) {
    char buf[160];
    const char *row = html ? "<tr>" : "|", *sep = html ? "" : " |", *end = html ? "</tr>\n" : "\n";
    fputs(row, f);
    fputs(html ? "<th>parameter</th>" : " parameter |", f);
    for (int j = 0; j < count; j++) {
        fputs(html ? "<th>" : " ", f);
        html ? cs_html_text(f, tr[j].label) : (void)fputs(tr[j].label, f);
        fprintf(f, "%s%s%s", tr[j].measured ? " (measured)" : "", j == reference ? " (reference)" : "",
                html ? "</th>" : sep);
    }
    fputs(end, f);
    if (!html) {
        fputs("| ---", f);
        for (int j = 0; j < count; j++)
            fputs(" | ---", f);
        fputs(" |\n", f);
    }
    fputs(row, f);
    fputs(html ? "<td>outcome</td>" : " outcome |", f);
    for (int j = 0; j < count; j++)
        fprintf(f, "%s%s%s", html ? "<td>" : " ", tr[j].measured ? "-" : tr[j].outcome, html ? "</td>" : sep);
    fputs(end, f);
    for (int k = 0; k < PARAMS; k++) {
        fprintf(f, "%s%s%s%s", row, html ? "<td>" : " ", params[k].name, html ? "</td>" : sep);
        for (int j = 0; j < count; j++) {
            cell(buf, sizeof buf, &tr[j], &tr[reference], k, j == reference);
            fprintf(f, "%s%s%s", html ? "<td>" : " ", buf, html ? "</td>" : sep);
        }
        fputs(end, f);
    }
}

/* ---- the validation metrics (NCHRP W179) against a measured history ---- */

static const struct {
    int trace;
    const char *name;
} metric_responses[] = {{CS_TRACE_DECEL, "deceleration"},
                        {CS_TRACE_SPEED, "speed"},
                        {CS_TRACE_PENETRATION, "penetration"},
                        {CS_TRACE_TENSION, "rope tension"}};
enum { METRIC_RESPONSES = sizeof metric_responses / sizeof metric_responses[0] };

/* The metrics of trace j's response r against the reference's, at the reference's times. Returns 0, or
 * -1 if either lacks the response or they share fewer than 2 samples or no magnitude. */
static int metrics_of(const cs_trace *tr, int j, int reference, int r, cs_validation_metrics *v) {
    const cs_trace *c = &tr[j], *m = &tr[reference];
    int k = metric_responses[r].trace;
    if (!c->have[k] || !m->have[k] || m->n < 2) return -1;
    double *buf = malloc(2 * m->n * sizeof *buf);
    if (!buf) return -1;
    size_t n = cs_validation_pair(m->t, m->y[k], m->n, c->t, c->y[k], c->n, buf, buf + m->n);
    int rc = cs_validation_metrics_of(buf, buf + m->n, n, v);
    free(buf);
    return rc;
}

/* Every run's metrics against the measured history: metrics.csv (format 0), a Markdown table (1), an HTML
 * table (2) or the terminal's lines (3). Nothing if the reference is not measured. */
static void write_metrics(FILE *f, const cs_trace *tr, int count, int reference, int format) {
    if (!tr[reference].measured) return;
    if (format == 0)
        fputs(
            "run,response,samples,sprague_geers_m [1],sprague_geers_p [1],sprague_geers_c [1],anova_mean [1],"
            "anova_std [1],w179\n",
            f);
    else if (format == 1)
        fputs(
            "\n## Validation metrics (NCHRP W179)\n\nEach run against the measured history at its times "
            "(M, P, C: Sprague-Geers; mean and std: the residuals over the measured peak; W179 accepts |M|, "
            "|P| <= 40%, |mean| <= 5%, std <= 35%).\n\n| run | response | M | P | C | mean | std | W179 "
            "|\n| --- | --- | --- | --- | --- | --- | --- | --- |\n",
            f);
    else if (format == 2)
        fputs(
            "<h2>Validation metrics (NCHRP W179)</h2>\n<p>Each run against the measured history at its "
            "times (M, P, C: Sprague-Geers; mean and std: the residuals over the measured peak; W179 accepts "
            "|M|, |P| &le; 40%, |mean| &le; 5%, std &le; 35%).</p>\n<table>\n<tr><th>run</th><th>response"
            "</th><th>M</th><th>P</th><th>C</th><th>mean</th><th>std</th><th>W179</th></tr>\n",
            f);
    for (int j = 0; j < count; j++)
        for (int r = 0; j != reference && r < METRIC_RESPONSES; r++) {
            cs_validation_metrics v;
            if (metrics_of(tr, j, reference, r, &v) != 0) continue;
            const char *verdict = cs_validation_metrics_pass(&v) ? "pass" : "FAIL";
            if (format == 0) {
                csv_text(f, tr[j].label);
                fprintf(f, ",%s,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%s\n", metric_responses[r].name, v.n, v.m, v.p,
                        v.c, v.mean, v.std, verdict);
                continue;
            }
            if (format == 2) {
                fputs("<tr><td>", f);
                cs_html_text(f, tr[j].label);
                fputs("</td>", f);
            } else {
                fprintf(f, format == 1 ? "| %s" : "  %-24s", tr[j].label);
            }
            const char *sep = format == 2 ? "</td><td>" : format == 1 ? " | " : "  ";
            fprintf(f, "%s%s%sM %+.1f%%%sP %.1f%%%sC %.1f%%%smean %+.1f%%%sstd %.1f%%%s%s%s\n",
                    format == 2 ? "<td>" : sep, metric_responses[r].name, sep, 100 * v.m, sep, 100 * v.p, sep,
                    100 * v.c, sep, 100 * v.mean, sep, 100 * v.std, sep, verdict,
                    format == 2   ? "</td></tr>"
                    : format == 1 ? " |"
                                  : "");
        }
    if (format == 2) fputs("</table>\n", f);
}

void cs_compare_print_trace_metrics(FILE *f, const cs_trace *traces, int count, int reference) {
    if (!traces[reference].measured) return;
    fputs("validation metrics (NCHRP W179) against the measured history:\n", f);
    write_metrics(f, traces, count, reference, 3);
}

/* ---- the files ---- */

cs_status cs_compare_write_traces(cs_outdir *out, const cs_trace *traces, int count, int reference,
                                  cs_error *err) {
    FILE *f = cs_out_begin(out, "compare.csv", err);
    if (!f) return err->status;
    write_csv(f, traces, count, reference);
    cs_status rc = cs_out_finish(out, f, CS_OK, err);
    if (rc != CS_OK) return rc;
    if (!(f = cs_out_begin(out, "compare.md", err))) return err->status;
    fprintf(f, "# Comparison\n\nDifferences are against %s%s.\n\n", traces[reference].label,
            traces[reference].measured ? " (measured)" : "");
    write_table(f, traces, count, reference, 0);
    write_metrics(f, traces, count, reference, 1);
    if ((rc = cs_out_finish(out, f, CS_OK, err)) != CS_OK) return rc;
    if (traces[reference].measured) {
        if (!(f = cs_out_begin(out, "metrics.csv", err))) return err->status;
        write_metrics(f, traces, count, reference, 0);
        if ((rc = cs_out_finish(out, f, CS_OK, err)) != CS_OK) return rc;
    }
    if ((rc = cs_out_subdir(out, "plots", err)) != CS_OK) return rc;
    static const cs_plot_format formats[] = {CS_PLOT_PNG, CS_PLOT_SVG};
    for (int k = 0; k < CS_COMPARE_PLOTS; k++)
        for (int j = 0; j < 2; j++) {
            char name[128];
            snprintf(name, sizeof name, "plots/%s.%s", figures[k].name, cs_plot_extension(formats[j]));
            if (!(f = cs_out_begin(out, name, err))) return err->status;
            plot_job job = {&figures[k], traces, count, reference};
            rc = cs_plot_write(f, formats[j], WIDTH, HEIGHT, draw, &job, err);
            if ((rc = cs_out_finish(out, f, rc, err)) != CS_OK) return rc;
        }
    /* the page: the table and each plot's SVG inline, so it opens from disk alone */
    if (!(f = cs_out_begin(out, "compare.html", err))) return err->status;
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>cablesim: "
          "comparison</title>\n"
          "<style>body{font-family:sans-serif;margin:1.5em;max-width:1000px}table{border-collapse:collapse}"
          "td,th{border:1px solid #bbb;padding:3px 8px;text-align:left}svg{max-width:100%;height:auto}"
          "</style></head><body>\n<h1>Comparison</h1>\n<p>Differences are against ",
          f);
    cs_html_text(f, traces[reference].label);
    fprintf(f, "%s.</p>\n<table>\n", traces[reference].measured ? " (measured)" : "");
    write_table(f, traces, count, reference, 1);
    fputs("</table>\n", f);
    write_metrics(f, traces, count, reference, 2);
    for (int k = 0; k < CS_COMPARE_PLOTS && rc == CS_OK; k++) {
        fprintf(f, "<h2>%s</h2>\n", figures[k].title);
        char id[16];
        snprintf(id, sizeof id, "f%d", k);
        plot_job job = {&figures[k], traces, count, reference};
        rc = cs_html_figure(f, id, WIDTH, HEIGHT, draw, &job, err);
    }
    fputs("</body></html>\n", f);
    return cs_out_finish(out, f, rc, err);
}
