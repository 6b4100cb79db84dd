/* SPDX-License-Identifier: MIT */
/* Figure 7 of a run (figures.h): the crash in snapshots, top and side views of the barrier's cables and
 * posts and the vehicle's schematic body at frames from first contact to the end; the body's outline,
 * which figure 9 draws too. */
#include "figures_int.h"
#include "numtext.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The schematic body: front face (crushed), rear, half width, face bottom and top, wheels (their radius,
 * their axles at the height at rest where the front tyres take a rope: vehicle.c); body frame (x
 * forward, z up from the CG). The definition has no overall length: the rear overhang is taken equal to
 * the front one. */
typedef struct body {
    double xf, xr, hw, zb, zt, axle[2], wheel_r, wheel_z;
} body;

static body vehicle_body(const cs_vehicle_def *v, double crush) {
    body b;
    b.xf = v->cg_to_front - crush;
    b.axle[0] = v->cg_to_front_axle;
    b.axle[1] = v->cg_to_front_axle - v->wheelbase;
    b.xr = -v->cg_to_rear;
    b.hw = 0.5 * v->front_width;
    b.zb = v->face_bottom - v->cg_height;
    b.zt = v->face_top - v->cg_height;
    b.wheel_r = v->wheel_radius;
    b.wheel_z = v->wheel_radius - v->tyre_static_deflection - v->cg_height;
    return b;
}

/* World point of a body point (roll, pitch, yaw: rotations about x, y, z applied in z-y-x order). */
static void to_world(const cs_vehicle_view *v, double bx, double by, double bz, double w[3]) {
    double cr = cos(v->roll), sr = sin(v->roll), cp = cos(v->pitch), sp = sin(v->pitch), cy = cos(v->yaw),
           sy = sin(v->yaw);
    w[0] = v->position[0] + cy * cp * bx + (cy * sp * sr - sy * cr) * by + (cy * sp * cr + sy * sr) * bz;
    w[1] = v->position[1] + sy * cp * bx + (sy * sp * sr + cy * cr) * by + (sy * sp * cr - cy * sr) * bz;
    w[2] = v->position[2] - sp * bx + cp * sr * by + cp * cr * bz;
}

void cs_fig_outline(const cs_vehicle_def *vd, const cs_vehicle_view *v, int side, double *u, double *w) {
    body b = vehicle_body(vd, v->crush);
    double zm = 0.5 * (b.zb + b.zt), p[3];
    const double corners[4][3] = {{b.xf, b.hw, zm}, {b.xf, -b.hw, zm}, {b.xr, -b.hw, zm}, {b.xr, b.hw, zm}};
    const double profile[4][3] = {{b.xf, 0, b.zt}, {b.xf, 0, b.zb}, {b.xr, 0, b.zb}, {b.xr, 0, b.zt}};
    for (int k = 0; k < 4; k++) {
        const double *c = side ? profile[k] : corners[k];
        to_world(v, c[0], c[1], c[2], p);
        u[k] = side ? p[1] : p[0];
        w[k] = side ? p[2] : p[1];
    }
}

typedef struct snap_geometry {
    int frames[SNAPS], count;
    double x0, x1, y0, y1, z0, z1; /* views' ranges, m: top x-y, side ys0-y1 by z (ys0 = y0) */
    double ys0;
    double area_h, top_w, row_h; /* layout, device units */
    double tmax;                 /* largest span tension of the run, N */
} snap_geometry;

static const double *path_xyz(const cs_record *r, int f, int c) {
    return r->path_xyz + ((size_t)f * (size_t)r->cable_count + (size_t)c) * (size_t)r->max_nodes * 3;
}

static void snap_layout(const cs_figure_data *d, snap_geometry *g) {
    const cs_record *r = d->rec;
    const cs_barrier_def *b = &d->in->barrier;
    int n = r->frame_count, first = 0;
    memset(g, 0, sizeof *g);
    while (first < n - 1 && r->vehicle[first].face_force <= 0) {
        int engaged = 0;
        for (int c = 0; c < r->cable_count; c++)
            engaged |= r->cables[(size_t)first * (size_t)r->cable_count + (size_t)c].engaged;
        if (engaged) break;
        first++;
    }
    for (int k = 0; n > 0 && k < SNAPS; k++) {
        double tk = r->vehicle[first].t + k * (r->vehicle[n - 1].t - r->vehicle[first].t) / (SNAPS - 1);
        int f = first;
        while (f + 1 < n && fabs(r->vehicle[f + 1].t - tk) <= fabs(r->vehicle[f].t - tk))
            f++;
        g->frames[g->count++] = f;
    }
    double xi = d->in->scenario.impact_x;
    g->x0 = fmax(b->start_anchor.x, xi - 25) - 1;
    g->x1 = fmin(b->end_anchor.x, xi + 25) + 1;
    g->y0 = g->y1 = g->ys0 = 0;
    g->z0 = -0.3;
    g->z1 = fmax(b->start_anchor.z, b->end_anchor.z);
    for (int p = 0; p < b->post_count; p++)
        g->z1 = fmax(g->z1, b->posts[p].height);
    for (int s = 0; s < g->count; s++) {
        int f = g->frames[s];
        double u[4], w[4];
        cs_fig_outline(&d->in->vehicle, &r->vehicle[f], 0, u, w);
        for (int k = 0; k < 4; k++) {
            g->ys0 = fmin(g->ys0, w[k]), g->y1 = fmax(g->y1, w[k]);
            g->x0 = fmin(g->x0, u[k] - 0.5), g->x1 = fmax(g->x1, u[k] + 0.5);
        }
        cs_fig_outline(&d->in->vehicle, &r->vehicle[f], 1, u, w);
        for (int k = 0; k < 4; k++)
            g->z1 = fmax(g->z1, w[k]);
        for (int c = 0; c < r->cable_count; c++) {
            const double *xyz = path_xyz(r, f, c);
            for (int j = 0; j < r->path_count[(size_t)f * (size_t)r->cable_count + (size_t)c]; j++)
                if (xyz[3 * j] >= g->x0 && xyz[3 * j] <= g->x1) g->y1 = fmax(g->y1, xyz[3 * j + 1]);
        }
        for (int p = 0; p < r->post_count; p++)
            g->y1 = fmax(g->y1, r->posts[(size_t)f * (size_t)r->post_count + (size_t)p].top[1]);
    }
    for (size_t i = 0; i < (size_t)n * (size_t)r->cable_count * (size_t)r->max_nodes; i++)
        g->tmax = fmax(g->tmax, r->path_tension[i]);
    g->ys0 -= 0.5, g->y0 = g->ys0, g->y1 += 0.5, g->z1 += 0.3;
    /* rows: top view (x-y) and side view (y-z) side by side, as wide as the figure, each at true scale
     * (as many metres a pixel across as up) with the whole vehicle in it */
    const double extra_w = 104, extra_h = 110;
    double wide = (g->x1 - g->x0) / (g->y1 - g->y0) + (g->y1 - g->ys0) / (g->z1 - g->z0);
    g->area_h = fmin(300, fmax(110, (SNAP_WIDTH - 2 * MARGIN - 2 * extra_w) / wide));
    g->top_w = g->area_h * (g->x1 - g->x0) / (g->y1 - g->y0) + extra_w;
    g->top_w = fmin(g->top_w, SNAP_WIDTH - 2 * MARGIN - extra_w - 200);
    g->row_h = g->area_h + extra_h;
}

static cs_rgb post_color(cs_post_status s) {
    if (s == CS_POST_ELASTIC) return (cs_rgb){0.10, 0.55, 0.25};
    if (s == CS_POST_HINGED || s == CS_POST_SOIL) return (cs_rgb){0.60, 0.20, 0.75};
    return BLACK;
}

/* One view of frame f: side 0 top (x-y), side 1 side (y-z). */
static void draw_view(cs_plot *p, const cs_figure_data *d, const snap_geometry *g, int f, int side,
                      cs_box panel) {
    const cs_record *r = d->rec;
    const cs_barrier_def *b = &d->in->barrier;
    char title[96], tt[CS_TIME_TEXT_SIZE];
    snprintf(title, sizeof title, "t = %s s: %s", cs_time_text(r->vehicle[f].t, tt),
             side ? "side view (y-z)" : "top view (x-y)");
    cs_axes a;
    cs_axes_init(&a, title, side ? "y, toward the protected side (m)" : "x, along the barrier (m)",
                 side ? "z, height (m)" : "y (m)");
    a.equal = 1;
    if (side) {
        cs_axes_set_x(&a, g->ys0, g->y1);
        cs_axes_set_y(&a, g->z0, g->z1);
    } else {
        cs_axes_set_x(&a, g->x0, g->x1);
        cs_axes_set_y(&a, g->y0, g->y1);
    }
    cs_axes_layout(p, &a, panel);
    cs_style ground = line((cs_rgb){0.60, 0.45, 0.30}, 2), face_line = dashed(GREY, 1);
    if (side)
        cs_plot_hline(p, &a, 0, &ground, NULL);
    else
        cs_plot_hline(p, &a, 0, &face_line, NULL);
    /* posts: elastic first, failed last, so the worst state shows on top */
    for (int rank = 0; rank < 3; rank++)
        for (int q = 0; q < r->post_count; q++) {
            const cs_post_view *pv = &r->posts[(size_t)f * (size_t)r->post_count + (size_t)q];
            if (cs_fig_post_rank(pv->status) != rank) continue;
            double bx = side ? 0 : b->posts[q].x, tx = side ? pv->top[1] : pv->top[0],
                   ty = side ? pv->top[2] : pv->top[1];
            cs_style s = line(post_color(pv->status), 3.5);
            cs_plot_segment(p, &a, bx, 0, tx, ty, &s);
            cs_style m =
                mark(post_color(pv->status), rank == 2 ? CS_MARK_CROSS : CS_MARK_SQUARE, rank == 2 ? 10 : 7);
            cs_plot_line(p, &a, &bx, (const double[]){0}, 1, &m, NULL);
        }
    /* cables, each span coloured by its tension */
    for (int c = 0; c < r->cable_count; c++) {
        size_t k = (size_t)f * (size_t)r->cable_count + (size_t)c;
        const double *xyz = path_xyz(r, f, c), *ten = r->path_tension + k * (size_t)r->max_nodes;
        int intact = cs_cable_status_holds(r->cables[k].status);
        for (int j = 0; j + 1 < r->path_count[k]; j++) {
            const double *p0 = xyz + 3 * j, *p1 = p0 + 3;
            cs_style s = intact ? line(cs_plot_colormap(ten[j] / g->tmax), 3) : dashed(GREY, 2);
            cs_plot_segment(p, &a, side ? p0[1] : p0[0], side ? p0[2] : p0[1], side ? p1[1] : p1[0],
                            side ? p1[2] : p1[1], &s);
        }
    }
    /* the vehicle: outline, wheels (side view), front face */
    const cs_vehicle_view *v = &r->vehicle[f];
    double u[4], w[4];
    cs_fig_outline(&d->in->vehicle, v, side, u, w);
    cs_rgb body_fill = {0.80, 0.80, 0.80};
    cs_style edge = line(GREY, 1.5), face = line(BLACK, 5);
    cs_plot_polygon(p, &a, u, w, 4, &body_fill, &edge);
    if (side) {
        body bd = vehicle_body(&d->in->vehicle, v->crush);
        for (int k = 0; k < 2; k++) {
            double cu[24], cw[24], pt[3];
            for (int j = 0; j < 24; j++) {
                to_world(v, bd.axle[k] + bd.wheel_r * cos(j * CS_PI / 12), 0,
                         bd.wheel_z + bd.wheel_r * sin(j * CS_PI / 12), pt);
                cu[j] = pt[1], cw[j] = pt[2];
            }
            cs_rgb tyre = {0.25, 0.25, 0.25};
            cs_plot_polygon(p, &a, cu, cw, 24, &tyre, NULL);
        }
    }
    cs_plot_segment(p, &a, u[0], w[0], u[1], w[1], &face);
}

void cs_fig_snapshots(cs_plot *p, const cs_figure_data *d, double *t) {
    (void)t;
    snap_geometry g;
    snap_layout(d, &g);
    if (g.tmax <= 0) g.tmax = 1;
    char text[200];
    snprintf(text, sizeof text, "%s: the crash in %d snapshots, from first contact to the end of the run",
             d->in->name, g.count);
    cs_plot_text(p, MARGIN + 10, MARGIN + 16, 20, 1, 0, text);
    snprintf(text, sizeof text, "cable tension / largest recorded (%.0f kN, %.0f kip)", g.tmax / 1e3,
             g.tmax / CS_KIP);
    cs_plot_colorbar(p, (cs_box){MARGIN + 40, MARGIN + 80, 480, 20}, text);
    cs_axes key;
    cs_axes_init(&key, NULL, NULL, NULL);
    cs_style s0 = line(post_color(CS_POST_ELASTIC), 3.5), s1 = line(post_color(CS_POST_HINGED), 3.5),
             s2 = (cs_style){BLACK, 3.5, CS_SOLID, CS_MARK_CROSS, 10}, sv = line(BLACK, 5),
             sb = dashed(GREY, 2);
    cs_style sf = line((cs_rgb){0.80, 0.80, 0.80}, 0);
    cs_axes_legend_add(&key, CS_LEGEND_LINE, &s0, "post elastic");
    cs_axes_legend_add(&key, CS_LEGEND_LINE, &s1, "post yielding (hinge or soil)");
    cs_axes_legend_add(&key, CS_LEGEND_LINE, &s2, "post failed");
    key.area = (cs_box){600, MARGIN + 40, 400, 100};
    cs_plot_legend(p, &key, CS_LEGEND_TOP_LEFT);
    cs_axes_init(&key, NULL, NULL, NULL);
    cs_axes_legend_add(&key, CS_LEGEND_AREA, &sf, "vehicle (schematic outline)");
    cs_axes_legend_add(&key, CS_LEGEND_LINE, &sv, "front face (crushed)");
    cs_axes_legend_add(&key, CS_LEGEND_LINE, &sb, "cable let go (broken, or released by its anchor)");
    key.area = (cs_box){920, MARGIN + 40, 400, 100};
    cs_plot_legend(p, &key, CS_LEGEND_TOP_LEFT);
    for (int s = 0; s < g.count; s++) {
        double y = SNAP_HEADER + s * g.row_h;
        draw_view(p, d, &g, g.frames[s], 0, (cs_box){MARGIN, y, g.top_w, g.row_h});
        draw_view(p, d, &g, g.frames[s], 1,
                  (cs_box){MARGIN + g.top_w, y, p->width - 2 * MARGIN - g.top_w, g.row_h});
    }
}

double cs_fig_snapshots_height(const cs_figure_data *d) {
    snap_geometry g;
    snap_layout(d, &g);
    return SNAP_HEADER + g.count * g.row_h + MARGIN;
}
