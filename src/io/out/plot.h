/* SPDX-License-Identifier: MIT */
/* A small plotting layer on cairo: panels with axes (nice ticks, unit labels, an optional second y scale
 * on the right, equal-aspect views), lines, markers, filled and stacked areas, text, legends and a
 * colour bar, written as PNG, SVG or PDF. Immediate mode: a figure is a function that draws on a
 * cs_plot; cs_plot_write calls it once for the format asked. Device units are pixels (points in PDF). */
#ifndef CS_PLOT_H
#define CS_PLOT_H

#include <stddef.h>
#include <stdio.h>

#include <cairo.h>

#include "cablesim/sim.h"

typedef enum cs_plot_format { CS_PLOT_UNKNOWN = -1, CS_PLOT_PNG, CS_PLOT_SVG, CS_PLOT_PDF } cs_plot_format;

/* The format named by a file name's extension (.png, .svg, .pdf), CS_PLOT_UNKNOWN otherwise. */
cs_plot_format cs_plot_format_of(const char *name);
const char *cs_plot_extension(cs_plot_format format); /* "png", "svg", "pdf" */

typedef struct cs_plot_log cs_plot_log;

typedef struct cs_plot {
    cairo_t *cr;
    double width, height;
    cs_plot_log *log; /* NULL; cs_plot_trace: what the drawing puts where */
    FILE *svg_text;   /* an SVG's texts as <text> elements, written over the drawing; NULL: glyphs */
} cs_plot;

typedef struct cs_rgb {
    double r, g, b;
} cs_rgb;

typedef enum cs_marker {
    CS_MARK_NONE = 0,
    CS_MARK_CIRCLE,
    CS_MARK_SQUARE,
    CS_MARK_TRIANGLE, /* pointing up */
    CS_MARK_DIAMOND,
    CS_MARK_CROSS /* an x */
} cs_marker;

typedef enum cs_dash { CS_SOLID = 0, CS_DASHED, CS_DOTTED } cs_dash;

typedef struct cs_style {
    cs_rgb color;
    double width; /* line width; 0 draws no line (markers only) */
    cs_dash dash;
    cs_marker marker; /* drawn at every point */
    double marker_size;
} cs_style;

typedef struct cs_box {
    double x, y, w, h; /* device units, y down */
} cs_box;

enum { CS_LEGEND_MAX = 16, CS_LABEL_SIZE = 96, CS_INK_COLS = 400, CS_INK_ROWS = 250 };

typedef enum cs_legend_kind { CS_LEGEND_LINE, CS_LEGEND_AREA } cs_legend_kind;

typedef struct cs_legend_entry {
    cs_legend_kind kind;
    cs_style style; /* for an area: style.color is the fill */
    char label[CS_LABEL_SIZE];
} cs_legend_entry;

typedef enum cs_legend_place {
    CS_LEGEND_TOP_RIGHT,
    CS_LEGEND_TOP_LEFT,
    CS_LEGEND_BOTTOM_RIGHT,
    CS_LEGEND_BOTTOM_LEFT,
    CS_LEGEND_OUTSIDE_RIGHT /* needs legend_width reserved before layout */
} cs_legend_place;

/* One panel. The caller sets the labels and options, fits the data range, then lays it out; after
 * cs_axes_layout the ranges are final and area is the plotting area. */
typedef struct cs_axes {
    const char *title;
    const char *xlabel, *ylabel; /* with units: "time (s)" */
    const char *y2label;         /* right axis, showing y * y2_scale (e.g. mph beside m/s) */
    double y2_scale;             /* 0: no right axis */
    int equal;                   /* a view: one unit is as long on x as on y */
    int fix_x, fix_y;            /* keep the range as set, do not round it out to ticks */
    double legend_width;         /* space kept on the right for an outside legend */
    int legend_rows;         /* the rows of a legend inside at the top: y1 raised so no data is under it */
    const char *const *xcat; /* categories: x ticks at 0, 1, ... named so (on two staggered rows) */
    int xcat_count;
    const char *const *ycat; /* categories: y ticks at 0, 1, ... named so */
    int ycat_count;
    double x0, x1, y0, y1;       /* data range */
    double xstep, ystep, y2step; /* tick spacing, set by layout */
    cs_box area;                 /* plotting area, set by layout */
    int legend_count;
    cs_legend_entry legend[CS_LEGEND_MAX];
    double ink_cell; /* the cells of the area that data, markers and notes were drawn on, ink_cell px */
    unsigned char ink[CS_INK_ROWS][CS_INK_COLS / 8];
} cs_axes;

/* Empty axes with these labels (NULL: none). */
void cs_axes_init(cs_axes *a, const char *title, const char *xlabel, const char *ylabel);
/* Widen the range to hold the finite points (x or y may be NULL: that coordinate is not fitted). */
void cs_axes_fit(cs_axes *a, const double *x, const double *y, int n);
void cs_axes_fit_point(cs_axes *a, double x, double y);
/* Set the range (and keep it: no rounding out to ticks). */
void cs_axes_set_x(cs_axes *a, double x0, double x1);
void cs_axes_set_y(cs_axes *a, double y0, double y1);
/* Choose ticks, fix the ranges and the area inside panel, draw frame, grid, ticks, labels, title. */
void cs_axes_layout(cs_plot *p, cs_axes *a, cs_box panel);
/* Device coordinates of a data point (after layout). */
double cs_axes_px(const cs_axes *a, double x);
double cs_axes_py(const cs_axes *a, double y);

/* A tick spacing of 1, 2 or 5 times a power of ten giving about target ticks over [lo, hi]. */
double cs_plot_nice_step(double lo, double hi, int target);

/* Data drawing, clipped to the area. A non-finite y breaks a line. label: a legend entry (NULL: none). */
void cs_plot_line(cs_plot *p, cs_axes *a, const double *x, const double *y, int n, const cs_style *s,
                  const char *label);
/* Stacked areas: layer k (of count) is y[k * n + i]; bands are drawn from zero upward in order. */
void cs_plot_stack(cs_plot *p, cs_axes *a, const double *x, const double *y, int count, int n,
                   const cs_rgb *fills, const char *const *labels);
void cs_plot_hline(cs_plot *p, cs_axes *a, double y, const cs_style *s, const char *label);
/* A closed polygon: fill (NULL: none) and outline (NULL: none). */
void cs_plot_polygon(cs_plot *p, cs_axes *a, const double *x, const double *y, int n, const cs_rgb *fill,
                     const cs_style *outline);
/* A line segment from (x0, y0) to (x1, y1). */
void cs_plot_segment(cs_plot *p, cs_axes *a, double x0, double y0, double x1, double y1, const cs_style *s);
/* Text at a data point, offset by (dx, dy) device units; align 0 left, 0.5 centre, 1 right of the point.
 * Drawn on a white halo so it stays readable over lines, and inside the plotting area: a label that
 * would cross its right or left edge goes to the other side of the point (align mirrored, dx negated),
 * one that would cross its top or bottom below or above it (dy negated), then it is moved in. */
void cs_plot_label(cs_plot *p, cs_axes *a, double x, double y, double dx, double dy, double align,
                   const char *text);
/* Add a legend entry without drawing (for things drawn piecewise). */
void cs_axes_legend_add(cs_axes *a, cs_legend_kind kind, const cs_style *s, const char *label);
/* The legend, drawn after the data. Inside: at place if no data, marker or note is under it there, else
 * at the first corner (top right, top left, bottom right, bottom left) where none is, else where least is;
 * legend_rows set before layout keeps the top clear of data for it. */
void cs_plot_legend(cs_plot *p, const cs_axes *a, cs_legend_place place);

/* Text in device units: size in px, align as for cs_plot_label, vertical centre at y. */
void cs_plot_text(cs_plot *p, double x, double y, double size, int bold, double align, const char *text);
/* A horizontal colour bar of the colour map over [0, 1] with ticks at 0, 0.25, ..., 1. */
void cs_plot_colorbar(cs_plot *p, cs_box box, const char *label);
/* The sequential colour map: f in [0, 1] from blue (low) to red (high). */
cs_rgb cs_plot_colormap(double f);
/* A distinct colour for series k. */
cs_rgb cs_plot_palette(int k);

/* Draws a figure on p: CS_OK, or a failure's status with err filled. */
typedef cs_status (*cs_plot_draw_fn)(cs_plot *p, const void *user, cs_error *err);

/* What a drawing put where, in device units (y down): the box of every text's ink with the frame it
 * belongs inside (a label's: its plotting area; an inside legend's: the plotting area; any other text's:
 * the figure), every panel's plotting area and final data ranges, and every legend's box with how much
 * ink it covers. For tests of the layout. */
enum { CS_PLOT_LOG_TEXTS = 1024, CS_PLOT_LOG_PANELS = 32, CS_PLOT_LOG_LEGENDS = 32 };

typedef struct cs_plot_logged_text {
    cs_box box, frame;
    char text[CS_LABEL_SIZE];
} cs_plot_logged_text;

typedef struct cs_plot_logged_panel {
    cs_box area;
    double x0, x1, y0, y1;
    int equal;
    char title[CS_LABEL_SIZE];
} cs_plot_logged_panel;

typedef struct cs_plot_logged_legend {
    cs_box box;
    int inside;  /* in its plotting area (not outside on the right) */
    int covered; /* cells of data, markers or notes under it (ink_cell px each) */
} cs_plot_logged_legend;

struct cs_plot_log {
    int text_count, panel_count,
        legend_count;     /* how many were drawn: those past the arrays' sizes are not kept */
    double width, height; /* the figure's */
    cs_plot_logged_text text[CS_PLOT_LOG_TEXTS];
    cs_plot_logged_panel panel[CS_PLOT_LOG_PANELS];
    cs_plot_logged_legend legend[CS_PLOT_LOG_LEGENDS];
};

/* Draw a width x height figure with draw and write it to f in format. Returns CS_OK, or draw's own
 * failure, or CS_ERR_IO with err filled (cairo not loaded, a cairo error, a write error), or
 * CS_ERR_MEMORY. */
cs_status cs_plot_write(FILE *f, cs_plot_format format, double width, double height, cs_plot_draw_fn draw,
                        const void *user, cs_error *err);
/* Draw a width x height figure with draw on an image (as a PNG would be drawn) and write nothing: log
 * (zeroed first) gets where every text and panel went. Returns as cs_plot_write. */
cs_status cs_plot_trace(double width, double height, cs_plot_draw_fn draw, const void *user, cs_plot_log *log,
                        cs_error *err);
/* The same to a file; the format follows path's extension (CS_ERR_INVALID for another). */
cs_status cs_plot_save(const char *path, double width, double height, cs_plot_draw_fn draw, const void *user,
                       cs_error *err);

/* Release what cairo and fontconfig keep for the life of the process (font configuration and caches).
 * Optional, once at exit after the last plot: it keeps leak checkers quiet. */
void cs_plot_release(void);

#endif
