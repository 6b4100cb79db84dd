/* SPDX-License-Identifier: MIT */
/* The plotting layer (plot.h): drawing on a cairo surface (plotfile.c makes it and writes it). Text
 * uses cairo's own font selection (DejaVu Sans, or whatever fontconfig gives for "sans-serif"). In an
 * SVG the texts are <text> elements, editable, written over the drawing (cairo's SVG surface would write
 * each glyph's outline). */
#define _POSIX_C_SOURCE 200809L
#include "plot.h"
#include "cablesim/units.h"
#include "out/cairo_lib.h"
#include "out/htmltext.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char FONT[] = "DejaVu Sans";
static const double TICK_FONT = 15, LABEL_FONT = 16, TITLE_FONT = 18, LEGEND_FONT = 14, NOTE_FONT = 14;
static const cs_rgb INK = {0.15, 0.15, 0.15}, GRID = {0.86, 0.86, 0.86};
static const double LEGEND_INSET = 10; /* an inside legend's distance from the frame */

/* A legend of rows entries: its height. */
static double legend_height(int rows) {
    return 1.5 * LEGEND_FONT * rows + 10;
}

cs_plot_format cs_plot_format_of(const char *name) {
    static const char *const ext[] = {".png", ".svg", ".pdf"};
    size_t n = strlen(name);
    for (int k = 0; k < 3; k++)
        if (n > 4 && strcmp(name + n - 4, ext[k]) == 0) return (cs_plot_format)k;
    return CS_PLOT_UNKNOWN;
}

const char *cs_plot_extension(cs_plot_format format) {
    return format == CS_PLOT_PNG ? "png" : format == CS_PLOT_SVG ? "svg" : format == CS_PLOT_PDF ? "pdf" : "";
}

static void set_color(cairo_t *cr, cs_rgb c) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

static void set_font(cairo_t *cr, double size, int bold) {
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

static double text_width(cairo_t *cr, const char *text, double size, int bold) {
    cairo_text_extents_t e;
    set_font(cr, size, bold);
    cairo_text_extents(cr, text, &e);
    return e.x_advance;
}

/* The box of text's ink drawn by draw_text at (x, y) (halo: 2 px wider each way). */
static cs_box text_box(cairo_t *cr, double x, double y, double size, int bold, double align, double angle,
                       int halo, const char *text) {
    cairo_text_extents_t e;
    set_font(cr, size, bold);
    cairo_text_extents(cr, text, &e);
    double ox = -align * e.x_advance + e.x_bearing, oy = 0.36 * size + e.y_bearing, m = halo ? 2 : 0;
    double c = cos(angle), s = sin(angle), lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int k = 0; k < 4; k++) {
        double u = ox + (k & 1 ? e.width + m : -m), v = oy + (k & 2 ? e.height + m : -m);
        double px = x + c * u - s * v, py = y + s * u + c * v;
        lo[0] = fmin(lo[0], px), hi[0] = fmax(hi[0], px), lo[1] = fmin(lo[1], py), hi[1] = fmax(hi[1], py);
    }
    return (cs_box){lo[0], lo[1], hi[0] - lo[0], hi[1] - lo[1]};
}

/* The same text as an SVG <text> element on out: anchored at its start, middle or end as align is
 * nearest 0, 0.5 or 1; the halo as a white stroke painted under the fill. */
static void svg_text(FILE *out, double x, double y, double size, int bold, double align, double angle,
                     int halo, const char *text) {
    fprintf(out,
            "<text transform=\"translate(%.2f %.2f) rotate(%.2f)\" y=\"%.2f\" font-family=\"%s, sans-serif\" "
            "font-size=\"%.1f\"%s text-anchor=\"%s\" fill=\"rgb(%d,%d,%d)\"%s>",
            x, y, angle * 180 / CS_PI, 0.36 * size, FONT, size, bold ? " font-weight=\"bold\"" : "",
            align < 0.25   ? "start"
            : align > 0.75 ? "end"
                           : "middle",
            (int)lround(255 * INK.r), (int)lround(255 * INK.g), (int)lround(255 * INK.b),
            halo ? " stroke=\"white\" stroke-width=\"4\" stroke-linejoin=\"round\" paint-order=\"stroke\""
                 : "");
    cs_html_text(out, text);
    fputs("</text>\n", out);
}

/* Text at (x, y) rotated by angle (rad, clockwise on the page), aligned along its own direction, its
 * vertical centre at y. halo: a white outline under the glyphs. frame: what it belongs inside, for the
 * log (NULL: the figure). */
static void draw_text(cs_plot *p, const cs_box *frame, double x, double y, double size, int bold,
                      double align, double angle, int halo, const char *text) {
    cairo_t *cr = p->cr;
    cs_plot_log *log = p->log;
    if (log && log->text_count++ < CS_PLOT_LOG_TEXTS) {
        cs_plot_logged_text *t = &log->text[log->text_count - 1];
        t->box = text_box(cr, x, y, size, bold, align, angle, halo, text);
        t->frame = frame ? *frame : (cs_box){0, 0, p->width, p->height};
        snprintf(t->text, sizeof t->text, "%s", text);
    }
    if (p->svg_text) {
        svg_text(p->svg_text, x, y, size, bold, align, angle, halo, text);
        return;
    }
    cairo_text_extents_t e;
    set_font(cr, size, bold);
    cairo_text_extents(cr, text, &e);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, angle);
    cairo_move_to(cr, -align * e.x_advance, 0.36 * size);
    if (halo) {
        cairo_text_path(cr, text);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 4);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_stroke_preserve(cr);
        set_color(cr, INK);
        cairo_fill(cr);
    } else {
        set_color(cr, INK);
        cairo_show_text(cr, text);
    }
    cairo_restore(cr);
}

void cs_plot_text(cs_plot *p, double x, double y, double size, int bold, double align, const char *text) {
    draw_text(p, NULL, x, y, size, bold, align, 0, 0, text);
}

/* ---- ink: the cells of a plotting area that data, markers and notes were drawn on ---- */

static void ink_set(cs_axes *a, double px, double py) {
    double u = (px - a->area.x) / a->ink_cell, v = (py - a->area.y) / a->ink_cell;
    if (!(a->ink_cell > 0) || !(px <= a->area.x + a->area.w && py <= a->area.y + a->area.h)) return;
    if (!(u >= 0 && v >= 0 && u < CS_INK_COLS && v < CS_INK_ROWS)) return;
    int c = (int)u;
    a->ink[(int)v][c / 8] |= (unsigned char)(1u << (c % 8));
}

static void ink_segment(cs_axes *a, double x0, double y0, double x1, double y1) {
    if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1) || !(a->ink_cell > 0)) return;
    int n = (int)fmin(4000, ceil(hypot(x1 - x0, y1 - y0) / (0.5 * a->ink_cell)));
    for (int k = 0; k <= n; k++) {
        double f = n > 0 ? (double)k / n : 0;
        ink_set(a, x0 + f * (x1 - x0), y0 + f * (y1 - y0));
    }
}

static void ink_box(cs_axes *a, cs_box b) {
    if (!(a->ink_cell > 0)) return;
    for (double y = b.y; y < b.y + b.h + 0.5 * a->ink_cell; y += 0.5 * a->ink_cell)
        ink_segment(a, b.x, fmin(y, b.y + b.h), b.x + b.w, fmin(y, b.y + b.h));
}

/* The inked cells whose centres are inside b. */
static int ink_under(const cs_axes *a, cs_box b) {
    int count = 0;
    for (int r = 0; a->ink_cell > 0 && r < CS_INK_ROWS; r++)
        for (int c = 0; c < CS_INK_COLS; c++) {
            double x = a->area.x + (c + 0.5) * a->ink_cell, y = a->area.y + (r + 0.5) * a->ink_cell;
            count +=
                (a->ink[r][c / 8] >> (c % 8) & 1) && x > b.x && x < b.x + b.w && y > b.y && y < b.y + b.h;
        }
    return count;
}

/* ---- axes ---- */

void cs_axes_init(cs_axes *a, const char *title, const char *xlabel, const char *ylabel) {
    memset(a, 0, sizeof *a);
    a->title = title;
    a->xlabel = xlabel;
    a->ylabel = ylabel;
    a->x0 = a->y0 = HUGE_VAL;
    a->x1 = a->y1 = -HUGE_VAL;
}

static void widen(double *lo, double *hi, double v) {
    if (!isfinite(v)) return;
    if (v < *lo) *lo = v;
    if (v > *hi) *hi = v;
}

void cs_axes_fit_point(cs_axes *a, double x, double y) {
    if (!a->fix_x) widen(&a->x0, &a->x1, x);
    if (!a->fix_y) widen(&a->y0, &a->y1, y);
}

void cs_axes_fit(cs_axes *a, const double *x, const double *y, int n) {
    for (int i = 0; i < n; i++)
        if ((!x || isfinite(x[i])) && (!y || isfinite(y[i])))
            cs_axes_fit_point(a, x ? x[i] : NAN, y ? y[i] : NAN);
}

void cs_axes_set_x(cs_axes *a, double x0, double x1) {
    a->x0 = x0, a->x1 = x1, a->fix_x = 1;
}

void cs_axes_set_y(cs_axes *a, double y0, double y1) {
    a->y0 = y0, a->y1 = y1, a->fix_y = 1;
}

double cs_plot_nice_step(double lo, double hi, int target) {
    double span = hi - lo;
    if (!(span > 0) || !isfinite(span)) return 1;
    double raw = span / (target > 1 ? target : 1), mag = pow(10, floor(log10(raw))), f = raw / mag;
    return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * mag;
}

/* An empty or zero-width range made usable. */
static void sane_range(double *lo, double *hi) {
    if (!(*lo <= *hi)) *lo = 0, *hi = 1;
    if (*hi - *lo < 1e-12 * fmax(1, fabs(*lo))) {
        double d = *lo != 0 ? 0.1 * fabs(*lo) : 1;
        *lo -= d, *hi += d;
    }
}

static void tick_label(char *buf, size_t size, double v, double step) {
    int dec = 0; /* the decimals that write the step itself (0.25: two) */
    while (dec < 6 && fabs(step * pow(10.0, dec) - round(step * pow(10.0, dec))) > 1e-9 * pow(10.0, dec))
        dec++;
    if (fabs(v) < 1e-9 * step) v = 0;
    snprintf(buf, size, "%.*f", dec, v);
}

/* First tick at or above lo. */
static double first_tick(double lo, double step) {
    return ceil(lo / step - 1e-9) * step;
}

/* The widest tick label over [lo, hi] (cat: the names of categories at 0, 1, ..., count of them). */
static double widest_tick(cairo_t *cr, double lo, double hi, double step, const char *const *cat, int count) {
    double w = 0;
    char buf[32];
    for (double v = first_tick(lo, step); v <= hi + 1e-9 * step; v += step) {
        long k = lround(v);
        if (cat && (k < 0 || k >= count)) continue;
        tick_label(buf, sizeof buf, v, step);
        w = fmax(w, text_width(cr, cat ? cat[k] : buf, TICK_FONT, 0));
    }
    return w;
}

double cs_axes_px(const cs_axes *a, double x) {
    return a->area.x + (x - a->x0) / (a->x1 - a->x0) * a->area.w;
}
double cs_axes_py(const cs_axes *a, double y) {
    return a->area.y + (a->y1 - y) / (a->y1 - a->y0) * a->area.h;
}

static void draw_ticks(cs_plot *p, const cs_axes *a) {
    cairo_t *cr = p->cr;
    char buf[32];
    const cs_box *b = &a->area;
    cairo_set_line_width(cr, 1);
    for (double v = first_tick(a->x0, a->xstep); v <= a->x1 + 1e-9 * a->xstep; v += a->xstep) {
        int cat = (int)lround(v);
        if (a->xcat && (cat < 0 || cat >= a->xcat_count)) continue;
        double x = round(cs_axes_px(a, v)) + 0.5;
        set_color(cr, GRID);
        cairo_move_to(cr, x, b->y);
        cairo_line_to(cr, x, b->y + b->h);
        cairo_stroke(cr);
        set_color(cr, INK);
        cairo_move_to(cr, x, b->y + b->h);
        cairo_line_to(cr, x, b->y + b->h + 5);
        cairo_stroke(cr);
        tick_label(buf, sizeof buf, v, a->xstep);
        draw_text(p, NULL, x, b->y + b->h + 8 + (0.6 + (a->xcat ? 1.2 * (cat % 2) : 0)) * TICK_FONT,
                  TICK_FONT, 0, 0.5, 0, 0, a->xcat ? a->xcat[cat] : buf);
    }
    for (double v = first_tick(a->y0, a->ystep); v <= a->y1 + 1e-9 * a->ystep; v += a->ystep) {
        int cat = (int)lround(v);
        if (a->ycat && (cat < 0 || cat >= a->ycat_count)) continue;
        double y = round(cs_axes_py(a, v)) + 0.5;
        set_color(cr, GRID);
        cairo_move_to(cr, b->x, y);
        cairo_line_to(cr, b->x + b->w, y);
        cairo_stroke(cr);
        set_color(cr, INK);
        cairo_move_to(cr, b->x - 5, y);
        cairo_line_to(cr, b->x, y);
        cairo_stroke(cr);
        tick_label(buf, sizeof buf, v, a->ystep);
        draw_text(p, NULL, b->x - 8, y, TICK_FONT, 0, 1, 0, 0, a->ycat ? a->ycat[cat] : buf);
    }
    if (a->y2_scale == 0) return;
    double s = a->y2_scale;
    for (double v = first_tick(fmin(a->y0 * s, a->y1 * s), a->y2step);
         v <= fmax(a->y0 * s, a->y1 * s) + 1e-9 * a->y2step; v += a->y2step) {
        double y = round(cs_axes_py(a, v / s)) + 0.5;
        set_color(cr, INK);
        cairo_move_to(cr, b->x + b->w, y);
        cairo_line_to(cr, b->x + b->w + 5, y);
        cairo_stroke(cr);
        tick_label(buf, sizeof buf, v, a->y2step);
        draw_text(p, NULL, b->x + b->w + 8, y, TICK_FONT, 0, 0, 0, 0, buf);
    }
}

void cs_axes_layout(cs_plot *p, cs_axes *a, cs_box panel) {
    cairo_t *cr = p->cr;
    sane_range(&a->x0, &a->x1);
    sane_range(&a->y0, &a->y1);
    double top = a->title ? 2.2 * TITLE_FONT : 12,
           bottom = (a->xcat ? 2.8 : 1.6) * TICK_FONT + 14 + (a->xlabel ? 1.8 * LABEL_FONT : 0);
    double label_left = a->ylabel ? 1.8 * LABEL_FONT : 0, label_right = a->y2label ? 1.8 * LABEL_FONT : 0;
    int xt = (int)fmax(3, panel.w / 130), yt = (int)fmax(3, panel.h / 70);
    if (a->equal) {
        /* Fit the area with a generous tick margin, then stretch the ranges to one scale. */
        a->area = (cs_box){panel.x + label_left + 14 + 4 * TICK_FONT * 0.62, panel.y + top, 0, 0};
        a->area.w = panel.x + panel.w - 16 - a->legend_width - a->area.x;
        a->area.h = panel.y + panel.h - bottom - a->area.y;
        double sx = a->area.w / (a->x1 - a->x0), sy = a->area.h / (a->y1 - a->y0), s = fmin(sx, sy);
        double cx = 0.5 * (a->x0 + a->x1), cy = 0.5 * (a->y0 + a->y1);
        double hx = 0.5 * a->area.w / s, hy = 0.5 * a->area.h / s;
        a->x0 = cx - hx, a->x1 = cx + hx, a->y0 = cy - hy, a->y1 = cy + hy;
        a->xstep = cs_plot_nice_step(a->x0, a->x1, (int)fmax(3, a->area.w / 90));
        a->ystep = cs_plot_nice_step(a->y0, a->y1, (int)fmax(3, a->area.h / 45));
    } else {
        /* headroom: a largest value, or a limit drawn at it, stays off the frame */
        double data_top = a->y1;
        if (!a->fix_y) {
            double span = a->y1 - a->y0;
            a->y1 += 0.03 * span;
            if (a->y0 < 0) a->y0 -= 0.03 * span;
        }
        /* a legend at the top: y1 raised (again while rounding out moves the data up) until the data
         * stays below it */
        double room = a->legend_rows > 0 ? legend_height(a->legend_rows) + LEGEND_INSET + 4 : 0;
        for (int k = 0; k < 4; k++) {
            a->xstep = a->xcat ? 1 : cs_plot_nice_step(a->x0, a->x1, xt);
            a->ystep = a->ycat ? 1 : cs_plot_nice_step(a->y0, a->y1, yt);
            if (!a->fix_x)
                a->x0 = floor(a->x0 / a->xstep + 1e-9) * a->xstep,
                a->x1 = ceil(a->x1 / a->xstep - 1e-9) * a->xstep;
            if (!a->fix_y)
                a->y0 = floor(a->y0 / a->ystep + 1e-9) * a->ystep,
                a->y1 = ceil(a->y1 / a->ystep - 1e-9) * a->ystep;
            double left = label_left + 14 + widest_tick(cr, a->y0, a->y1, a->ystep, a->ycat, a->ycat_count);
            double right = 16 + a->legend_width;
            if (a->y2_scale != 0) {
                double s0 = a->y0 * a->y2_scale, s1 = a->y1 * a->y2_scale;
                a->y2step = cs_plot_nice_step(fmin(s0, s1), fmax(s0, s1), yt);
                right += 14 + label_right + widest_tick(cr, fmin(s0, s1), fmax(s0, s1), a->y2step, NULL, 0);
            }
            a->area = (cs_box){panel.x + left + 8, panel.y + top, panel.w - left - right - 8,
                               panel.h - top - bottom};
            if (a->fix_y || !(room > 0 && room < 0.8 * a->area.h) ||
                cs_axes_py(a, data_top) >= a->area.y + room)
                break;
            a->y1 = a->y0 + (data_top - a->y0) * a->area.h / (a->area.h - room);
        }
    }
    a->ink_cell = fmax(4, fmax(a->area.w / CS_INK_COLS, a->area.h / CS_INK_ROWS));
    const cs_box *b = &a->area;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, b->x, b->y, b->w, b->h);
    cairo_fill(cr);
    draw_ticks(p, a);
    set_color(cr, INK);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, round(b->x) + 0.5, round(b->y) + 0.5, round(b->w), round(b->h));
    cairo_stroke(cr);
    if (a->title)
        draw_text(p, NULL, b->x + 0.5 * b->w, panel.y + 0.95 * TITLE_FONT, TITLE_FONT, 1, 0.5, 0, 0,
                  a->title);
    if (a->xlabel)
        draw_text(p, NULL, b->x + 0.5 * b->w,
                  b->y + b->h + 14 + (a->xcat ? 2.8 : 1.6) * TICK_FONT + 0.8 * LABEL_FONT, LABEL_FONT, 0, 0.5,
                  0, 0, a->xlabel);
    if (a->ylabel)
        draw_text(p, NULL, panel.x + 0.9 * LABEL_FONT, b->y + 0.5 * b->h, LABEL_FONT, 0, 0.5, -CS_PI / 2, 0,
                  a->ylabel);
    if (a->y2label)
        draw_text(p, NULL, panel.x + panel.w - a->legend_width - 0.9 * LABEL_FONT - 8, b->y + 0.5 * b->h,
                  LABEL_FONT, 0, 0.5, CS_PI / 2, 0, a->y2label);
    cs_plot_log *log = p->log;
    if (log && log->panel_count++ < CS_PLOT_LOG_PANELS) {
        cs_plot_logged_panel *q = &log->panel[log->panel_count - 1];
        *q = (cs_plot_logged_panel){a->area, a->x0, a->x1, a->y0, a->y1, a->equal, ""};
        snprintf(q->title, sizeof q->title, "%s", a->title ? a->title : "");
    }
}

/* ---- drawing data ---- */

static void clip_to(cairo_t *cr, const cs_axes *a) {
    cairo_save(cr);
    cairo_rectangle(cr, a->area.x, a->area.y, a->area.w, a->area.h);
    cairo_clip(cr);
}

static void stroke_style(cairo_t *cr, const cs_style *s) {
    static const double dashed[] = {9, 5}, dotted[] = {2, 4};
    set_color(cr, s->color);
    cairo_set_line_width(cr, s->width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, s->dash == CS_DOTTED ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    cairo_set_dash(cr, s->dash == CS_DASHED ? dashed : dotted, s->dash == CS_SOLID ? 0 : 2, 0);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
}

static void draw_marker(cairo_t *cr, double x, double y, cs_marker m, double size, cs_rgb c) {
    double r = 0.5 * (size > 0 ? size : 9);
    cairo_new_path(cr);
    switch (m) {
    case CS_MARK_NONE:
        return;
    case CS_MARK_CIRCLE:
        cairo_arc(cr, x, y, r, 0, 2 * CS_PI);
        break;
    case CS_MARK_SQUARE:
        cairo_rectangle(cr, x - r, y - r, 2 * r, 2 * r);
        break;
    case CS_MARK_TRIANGLE:
        cairo_move_to(cr, x, y - 1.2 * r);
        cairo_line_to(cr, x + 1.1 * r, y + 0.8 * r);
        cairo_line_to(cr, x - 1.1 * r, y + 0.8 * r);
        cairo_close_path(cr);
        break;
    case CS_MARK_DIAMOND:
        cairo_move_to(cr, x, y - 1.3 * r);
        cairo_line_to(cr, x + r, y);
        cairo_line_to(cr, x, y + 1.3 * r);
        cairo_line_to(cr, x - r, y);
        cairo_close_path(cr);
        break;
    case CS_MARK_CROSS:
        cairo_move_to(cr, x - r, y - r);
        cairo_line_to(cr, x + r, y + r);
        cairo_move_to(cr, x - r, y + r);
        cairo_line_to(cr, x + r, y - r);
        cairo_set_line_width(cr, fmax(2.5, 0.3 * r));
        set_color(cr, c);
        cairo_stroke(cr);
        return;
    }
    set_color(cr, c);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.5 * c.r, 0.5 * c.g, 0.5 * c.b);
    cairo_set_line_width(cr, 1.2);
    cairo_stroke(cr);
}

void cs_axes_legend_add(cs_axes *a, cs_legend_kind kind, const cs_style *s, const char *label) {
    if (!label || a->legend_count == CS_LEGEND_MAX) return;
    cs_legend_entry *e = &a->legend[a->legend_count++];
    e->kind = kind;
    e->style = *s;
    snprintf(e->label, sizeof e->label, "%s", label);
}

void cs_plot_line(cs_plot *p, cs_axes *a, const double *x, const double *y, int n, const cs_style *s,
                  const char *label) {
    cairo_t *cr = p->cr;
    clip_to(cr, a);
    if (s->width > 0) {
        int pen = 0;
        for (int i = 0; i < n; i++) {
            if (!isfinite(x[i]) || !isfinite(y[i])) {
                pen = 0;
                continue;
            }
            double px = cs_axes_px(a, x[i]), py = cs_axes_py(a, y[i]);
            if (pen) ink_segment(a, cs_axes_px(a, x[i - 1]), cs_axes_py(a, y[i - 1]), px, py);
            (pen ? cairo_line_to : cairo_move_to)(cr, px, py);
            pen = 1;
        }
        stroke_style(cr, s);
    }
    cairo_restore(cr);
    /* markers are not clipped: one on the frame shows whole */
    for (int i = 0; s->marker != CS_MARK_NONE && i < n; i++) {
        double px = cs_axes_px(a, x[i]), py = cs_axes_py(a, y[i]);
        if (px >= a->area.x - 1 && px <= a->area.x + a->area.w + 1 && py >= a->area.y - 1 &&
            py <= a->area.y + a->area.h + 1) {
            double r = 0.65 * (s->marker_size > 0 ? s->marker_size : 9);
            draw_marker(cr, px, py, s->marker, s->marker_size, s->color);
            ink_box(a, (cs_box){px - r, py - r, 2 * r, 2 * r});
        }
    }
    cs_axes_legend_add(a, CS_LEGEND_LINE, s, label);
}

/* Fill the band between lo(i) and hi(i), each the sum of layers [0, k0) and [0, k1) of y (count 1 when
 * y is a single series and k0 = 0 means the zero line). */
static double layer_sum(const double *y, int n, int i, int k) {
    double s = 0;
    for (int j = 0; j < k; j++)
        s += isfinite(y[(size_t)j * (size_t)n + (size_t)i]) ? y[(size_t)j * (size_t)n + (size_t)i] : 0;
    return s;
}

static void fill_band(cs_plot *p, cs_axes *a, const double *x, const double *lo, int klo, const double *hi,
                      int khi, int n, cs_rgb fill, double alpha) {
    cairo_t *cr = p->cr;
    if (n < 2) return;
    clip_to(cr, a);
    for (int i = 0; i < n; i++) {
        double px = cs_axes_px(a, x[i]), top = cs_axes_py(a, layer_sum(hi, n, i, khi));
        cairo_line_to(cr, px, top);
        ink_segment(a, px, top, px, cs_axes_py(a, lo ? layer_sum(lo, n, i, klo) : 0));
    }
    for (int i = n - 1; i >= 0; i--)
        cairo_line_to(cr, cs_axes_px(a, x[i]), cs_axes_py(a, lo ? layer_sum(lo, n, i, klo) : 0));
    cairo_close_path(cr);
    cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, alpha);
    cairo_fill(cr);
    cairo_restore(cr);
}

void cs_plot_stack(cs_plot *p, cs_axes *a, const double *x, const double *y, int count, int n,
                   const cs_rgb *fills, const char *const *labels) {
    for (int k = 0; k < count; k++)
        fill_band(p, a, x, y, k, y, k + 1, n, fills[k], 0.85);
    for (int k = count - 1; k >= 0; k--) { /* the legend reads top down, as the bands */
        cs_style s = {fills[k], 0, CS_SOLID, CS_MARK_NONE, 0};
        cs_axes_legend_add(a, CS_LEGEND_AREA, &s, labels ? labels[k] : NULL);
    }
}

void cs_plot_segment(cs_plot *p, cs_axes *a, double x0, double y0, double x1, double y1, const cs_style *s) {
    cairo_t *cr = p->cr;
    clip_to(cr, a);
    cairo_move_to(cr, cs_axes_px(a, x0), cs_axes_py(a, y0));
    cairo_line_to(cr, cs_axes_px(a, x1), cs_axes_py(a, y1));
    stroke_style(cr, s);
    ink_segment(a, cs_axes_px(a, x0), cs_axes_py(a, y0), cs_axes_px(a, x1), cs_axes_py(a, y1));
    cairo_restore(cr);
}

void cs_plot_hline(cs_plot *p, cs_axes *a, double y, const cs_style *s, const char *label) {
    cs_plot_segment(p, a, a->x0, y, a->x1, y, s);
    cs_axes_legend_add(a, CS_LEGEND_LINE, s, label);
}

void cs_plot_polygon(cs_plot *p, cs_axes *a, const double *x, const double *y, int n, const cs_rgb *fill,
                     const cs_style *outline) {
    cairo_t *cr = p->cr;
    clip_to(cr, a);
    for (int i = 0; i < n; i++)
        cairo_line_to(cr, cs_axes_px(a, x[i]), cs_axes_py(a, y[i]));
    cairo_close_path(cr);
    if (fill) {
        set_color(cr, *fill);
        if (outline)
            cairo_fill_preserve(cr);
        else
            cairo_fill(cr);
    }
    if (outline) stroke_style(cr, outline);
    cairo_restore(cr);
    for (int i = 0; i < n; i++)
        ink_segment(a, cs_axes_px(a, x[i]), cs_axes_py(a, y[i]), cs_axes_px(a, x[(i + 1) % n]),
                    cs_axes_py(a, y[(i + 1) % n]));
    for (int r = 0; fill && r < CS_INK_ROWS; r++) /* the cells whose centres are inside (even-odd) */
        for (int c = 0; c < CS_INK_COLS; c++) {
            double cx = a->area.x + (c + 0.5) * a->ink_cell, cy = a->area.y + (r + 0.5) * a->ink_cell;
            if (cx > a->area.x + a->area.w || cy > a->area.y + a->area.h) continue;
            int in = 0;
            for (int i = 0, j = n - 1; i < n; j = i++) {
                double xi = cs_axes_px(a, x[i]), yi = cs_axes_py(a, y[i]), xj = cs_axes_px(a, x[j]),
                       yj = cs_axes_py(a, y[j]);
                if ((yi > cy) != (yj > cy) && cx < xi + (cy - yi) * (xj - xi) / (yj - yi)) in = !in;
            }
            if (in) ink_set(a, cx, cy);
        }
}

void cs_plot_label(cs_plot *p, cs_axes *a, double x, double y, double dx, double dy, double align,
                   const char *text) {
    double px = cs_axes_px(a, x), py = cs_axes_py(a, y), pad = 3;
    if (!isfinite(px) || !isfinite(py)) return;
    const cs_box *f = &a->area;
    cs_box b = text_box(p->cr, px + dx, py + dy, NOTE_FONT, 0, align, 0, 1, text);
    if (b.x + b.w > f->x + f->w - pad || b.x < f->x + pad) { /* the other side of the point, if it fits */
        cs_box o = text_box(p->cr, px - dx, py + dy, NOTE_FONT, 0, 1 - align, 0, 1, text);
        if (o.x >= f->x + pad && o.x + o.w <= f->x + f->w - pad) dx = -dx, align = 1 - align, b = o;
    }
    if (b.y < f->y + pad || b.y + b.h > f->y + f->h - pad) {
        cs_box o = text_box(p->cr, px + dx, py - dy, NOTE_FONT, 0, align, 0, 1, text);
        if (o.y >= f->y + pad && o.y + o.h <= f->y + f->h - pad) dy = -dy, b = o;
    }
    /* what still sticks out is moved in (the left and top edges win over a text too big for the area) */
    double mx = fmin(0, f->x + f->w - pad - (b.x + b.w)), my = fmin(0, f->y + f->h - pad - (b.y + b.h));
    mx = fmax(mx, f->x + pad - b.x), my = fmax(my, f->y + pad - b.y);
    draw_text(p, f, px + dx + mx, py + dy + my, NOTE_FONT, 0, align, 0, 1, text);
    ink_box(a, text_box(p->cr, px + dx + mx, py + dy + my, NOTE_FONT, 0, align, 0, 1, text));
}

void cs_plot_legend(cs_plot *p, const cs_axes *a, cs_legend_place place) {
    cairo_t *cr = p->cr;
    if (a->legend_count == 0) return;
    double row = 1.5 * LEGEND_FONT, sample = 30, w = 0; /* as legend_height has it */
    for (int i = 0; i < a->legend_count; i++)
        w = fmax(w, text_width(cr, a->legend[i].label, LEGEND_FONT, 0));
    w += sample + 24;
    double h = legend_height(a->legend_count), x = p->width - a->legend_width - 4, y = a->area.y;
    int covered = 0;
    if (place != CS_LEGEND_OUTSIDE_RIGHT) { /* place, else the first corner with nothing under it */
        const cs_legend_place corners[] = {place, CS_LEGEND_TOP_RIGHT, CS_LEGEND_TOP_LEFT,
                                           CS_LEGEND_BOTTOM_RIGHT, CS_LEGEND_BOTTOM_LEFT};
        const cs_box *b = &a->area;
        for (int k = 0, least = -1; k < 5 && least != 0; k++) {
            cs_legend_place q = corners[k];
            double qx = q == CS_LEGEND_TOP_LEFT || q == CS_LEGEND_BOTTOM_LEFT
                            ? b->x + LEGEND_INSET
                            : b->x + b->w - LEGEND_INSET - w;
            double qy = q == CS_LEGEND_BOTTOM_LEFT || q == CS_LEGEND_BOTTOM_RIGHT
                            ? b->y + b->h - LEGEND_INSET - h
                            : b->y + LEGEND_INSET;
            int under = ink_under(a, (cs_box){qx, qy, w, h});
            if (least < 0 || under < least) least = covered = under, x = qx, y = qy;
        }
    }
    cs_plot_log *log = p->log;
    if (log && log->legend_count++ < CS_PLOT_LOG_LEGENDS)
        log->legend[log->legend_count - 1] =
            (cs_plot_logged_legend){{x, y, w, h}, place != CS_LEGEND_OUTSIDE_RIGHT, covered};
    cairo_set_source_rgba(cr, 1, 1, 1, 0.88);
    cairo_rectangle(cr, x, y, w, h);
    cairo_fill_preserve(cr);
    set_color(cr, GRID);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    for (int i = 0; i < a->legend_count; i++) {
        const cs_legend_entry *e = &a->legend[i];
        double cy = y + 5 + row * (i + 0.5), sx = x + 8;
        if (e->kind == CS_LEGEND_AREA) {
            set_color(cr, e->style.color);
            cairo_rectangle(cr, sx, cy - 0.35 * row, sample, 0.7 * row);
            cairo_fill(cr);
        } else {
            if (e->style.width > 0) {
                cairo_move_to(cr, sx, cy);
                cairo_line_to(cr, sx + sample, cy);
                stroke_style(cr, &e->style);
            }
            draw_marker(cr, sx + 0.5 * sample, cy, e->style.marker, e->style.marker_size, e->style.color);
        }
        draw_text(p, place == CS_LEGEND_OUTSIDE_RIGHT ? NULL : &a->area, sx + sample + 8, cy, LEGEND_FONT, 0,
                  0, 0, 0, e->label);
    }
}

/* ---- colours ---- */

cs_rgb cs_plot_colormap(double f) {
    static const cs_rgb stops[] = {
        {0.23, 0.30, 0.75}, {0.20, 0.60, 0.80}, {0.45, 0.72, 0.30}, {0.95, 0.65, 0.10}, {0.78, 0.08, 0.10}};
    f = isfinite(f) ? fmin(1, fmax(0, f)) : 0;
    double u = f * 4;
    int k = u >= 4 ? 3 : (int)u;
    double t = u - k;
    cs_rgb a = stops[k], b = stops[k + 1];
    return (cs_rgb){a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
}

cs_rgb cs_plot_palette(int k) {
    static const cs_rgb colors[] = {
        {0.12, 0.47, 0.71}, {0.90, 0.45, 0.05}, {0.17, 0.60, 0.17}, {0.80, 0.15, 0.16}, {0.55, 0.36, 0.74},
        {0.55, 0.34, 0.29}, {0.85, 0.40, 0.72}, {0.45, 0.45, 0.45}, {0.70, 0.70, 0.10}, {0.09, 0.70, 0.78}};
    return colors[(k < 0 ? -k : k) % 10];
}

void cs_plot_colorbar(cs_plot *p, cs_box box, const char *label) {
    cairo_t *cr = p->cr;
    cairo_pattern_t *g = cairo_pattern_create_linear(box.x, 0, box.x + box.w, 0);
    for (int k = 0; k <= 20; k++) {
        cs_rgb c = cs_plot_colormap(k / 20.0);
        cairo_pattern_add_color_stop_rgb(g, k / 20.0, c.r, c.g, c.b);
    }
    cairo_rectangle(cr, box.x, box.y, box.w, box.h);
    cairo_set_source(cr, g);
    cairo_fill(cr);
    cairo_pattern_destroy(g);
    set_color(cr, INK);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, box.x, box.y, box.w, box.h);
    cairo_stroke(cr);
    char buf[16];
    for (int k = 0; k <= 4; k++) {
        double x = box.x + box.w * k / 4.0;
        cairo_move_to(cr, x, box.y + box.h);
        cairo_line_to(cr, x, box.y + box.h + 5);
        cairo_stroke(cr);
        tick_label(buf, sizeof buf, k / 4.0, 0.25);
        draw_text(p, NULL, x, box.y + box.h + 8 + 0.6 * TICK_FONT, TICK_FONT, 0, 0.5, 0, 0, buf);
    }
    if (label)
        draw_text(p, NULL, box.x + 0.5 * box.w, box.y - 0.8 * LABEL_FONT, LABEL_FONT, 0, 0.5, 0, 0, label);
}
