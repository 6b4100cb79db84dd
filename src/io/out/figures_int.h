/* SPDX-License-Identifier: MIT */
/* Inside the figures (figures.c; the snapshots, figsnap.c): the page's measures, colours and styles. */
#ifndef CS_FIGURES_INT_H
#define CS_FIGURES_INT_H

#include "figures.h"

static const double MARGIN = 8, SNAP_WIDTH = 1800, SNAP_HEADER = 150;
enum { SNAPS = 6, NEAR_POSTS = 4 };

static inline cs_box whole(const cs_plot *p) {
    return (cs_box){MARGIN, MARGIN, p->width - 2 * MARGIN, p->height - 2 * MARGIN};
}

static inline cs_style line(cs_rgb c, double width) {
    return (cs_style){c, width, CS_SOLID, CS_MARK_NONE, 0};
}
static inline cs_style dashed(cs_rgb c, double width) {
    return (cs_style){c, width, CS_DASHED, CS_MARK_NONE, 0};
}
static inline cs_style mark(cs_rgb c, cs_marker m, double size) {
    return (cs_style){c, 0, CS_SOLID, m, size};
}

static const cs_rgb BLACK = {0.1, 0.1, 0.1}, GREY = {0.55, 0.55, 0.55}, RED = {0.85, 0.1, 0.1};

enum { TITLE_SIZE = 200 };

/* 0 elastic, 1 yielding (hinge or footing in the soil), 2 failed. */
static inline int cs_fig_post_rank(cs_post_status s) {
    return s == CS_POST_ELASTIC ? 0 : s == CS_POST_HINGED || s == CS_POST_SOIL ? 1 : 2;
}

/* The outline of the vehicle's body in frame v seen from above (side 0: x-y of a plan at mid-face height)
 * or from the side (side 1: y-z of the centre plane): 4 corners into u and w, front face first
 * (corners 0 and 1). */
void cs_fig_outline(const cs_vehicle_def *vd, const cs_vehicle_view *v, int side, double *u, double *w);
/* Figure 7, a strip of top and side snapshots of the crash (t unused), and its height for d's run. */
void cs_fig_snapshots(cs_plot *p, const cs_figure_data *d, double *t);
double cs_fig_snapshots_height(const cs_figure_data *d);

#endif
