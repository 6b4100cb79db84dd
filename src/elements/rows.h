/* SPDX-License-Identifier: MIT */
/* The barrier's unknowns and the interface through which each element gives its rows of the residual
 * and of the Jacobian (system.c assembles them; post.c, support.c, contact.c and anchor.c give them).
 *
 * Every unknown is a slot (kind, element a, component or node b), ordered along the barrier so that the
 * Jacobian is banded. Every row is a function of a few cable nodes: their positions (moved by a post's
 * tilt, a contact's height, the crush or an anchor's displacement) and their material coordinates; an
 * element forms its row's gradient with respect to those nodes, and cs_rows_add_node_gradient chains it
 * to the columns that move them. */
#ifndef CS_ROWS_H
#define CS_ROWS_H

#include "core/band.h"
#include "elements/elements.h"

typedef enum cs_unknown_kind {
    CS_U_TILT = 0,   /* a post's tilt (2 slots: b = 0, 1) */
    CS_U_NODE = 1,   /* the material coordinate of node b of cable a where the rope slides */
    CS_U_CRUSH = 2,  /* the crush of the vehicle's face */
    CS_U_HEIGHT = 3, /* the height of cable a's contact at corner b of the outline (CS_CORNERS) */
    CS_U_ANCHOR = 4, /* anchor a's horizontal displacement (2 slots: b = 0, 1) */
    CS_U_PULL = 5,   /* how far post a has slid out of its footing along its axis (post_pullout.c) */
    CS_U_LIFT = 6,   /* how far anchor a has risen out of the soil (anchor.c) */
    CS_U_KIND_COUNT
} cs_unknown_kind;

typedef struct cs_slot {
    double x; /* where it sits along the barrier (the order of the unknowns) */
    int kind, a, b;
    int id; /* its place in the order the unknowns are gathered in (system.c) */
} cs_slot;

/* What the rows read besides the state: the unknowns' columns, each span's chord and tension gradient
 * and each post axis' Jacobian at the placement, and the Jacobian being built. */
typedef struct cs_rows {
    int n;
    cs_slot *slots;
    int *tilt_index;     /* [post_count] a post's first tilt column, -1 if none */
    int *pull_index;     /* [post_count] a post's pull column, -1 if none */
    int *node_index;     /* [cable_count * max_nodes] a node's material column, -1 if none */
    int *height_index;   /* [cable_count * CS_CORNERS] a contact's height column, -1 if none */
    int crush_index;     /* -1 if none */
    int anchor_index[2]; /* an anchor's first column, -1 if none */
    int lift_index[2];   /* an anchor's rise column, -1 if none */
    double *chords;      /* [4 cable_count max_nodes] each span's chord and length at the placement */
    double *axes;        /* [18 post_count] each post axis' Jacobian and its tilt derivatives */
    cs_span_grad *spans; /* [cable_count * max_nodes] each span's tension and gradient */
    double *rails;       /* [4 post_count rail_count] the rails' moments on the posts at the placement */
    cs_band *jac;        /* the Jacobian being built */
} cs_rows;

/* One kind of element: its residual rows at the state as placed (1 or 2 entries from r), and its rows
 * of the Jacobian (from row `row`) with the spans' gradients and the axes current. */
typedef struct cs_row_kind {
    int width; /* slots, and rows, per element */
    void (*residual)(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                     double *r);
    void (*jacobian)(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                     const cs_slot *u);
} cs_row_kind;

extern const cs_row_kind cs_post_rows;    /* post.c */
extern const cs_row_kind cs_support_rows; /* support.c */
extern const cs_row_kind cs_height_rows;  /* contact.c */
extern const cs_row_kind cs_crush_rows;   /* contact.c */
extern const cs_row_kind cs_anchor_rows;  /* anchor.c */
extern const cs_row_kind cs_pull_rows;    /* post_pullout.c */
extern const cs_row_kind cs_lift_rows;    /* anchor.c */

/* The force unit of the rows that balance forces (supports, anchors, a post's pull): the strongest rope's
 * strength, so that one tolerance is one force everywhere. */
static inline double cs_rows_force_unit(const cs_model *model) {
    double u = 0.0;
    for (int c = 0; c < model->cable_count; c++)
        u = u > model->cables[c].rope.fu ? u : model->cables[c].rope.fu;
    return u > 0.0 ? u : 1.0;
}

static inline const double *cs_rows_chords(const cs_model *model, const cs_rows *rows, int c) {
    return rows->chords + 4 * (size_t)c * (size_t)model->max_nodes;
}
/* The two spans at node i of cable c. */
static inline const cs_span_grad *cs_rows_spans(const cs_model *model, const cs_rows *rows, int c, int i) {
    return rows->spans + (size_t)c * (size_t)model->max_nodes + (size_t)i - 1;
}
static inline void cs_rows_add(const cs_rows *rows, int i, int j, double value) {
    cs_band_add(rows->jac, i, j, value);
}
/* Row `row`'s gradient with respect to nodes i-1, i, i+1 of cable c (positions gp, materials gm), chained
 * to the columns that move them. */
void cs_rows_add_node_gradient(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int c,
                               int i, double gp[3][3], const double *gm);
/* Gradient of rho . f_i, f_i the two spans' pull on node i, for a fixed 3-vector rho; adds to gp, gm. */
void cs_rows_force_gradient(const cs_span_grad *sp, const double *rho, double gp[3][3], double *gm);
/* The same for the pull of its one span on a rope's end node (at_start: node 0, span 0; else the last
 * node and span); gp[1] is the end node's, gp[2] (start) or gp[0] (end) its neighbour's. */
void cs_rows_end_force_gradient(const cs_span_grad *sp, int at_start, const double *rho, double gp[3][3],
                                double *gm);
/* Gradient of the span lengths l_L + l_R at node i, times coef; adds to gp. */
void cs_rows_length_gradient(const cs_span_grad *sp, double coef, double gp[3][3]);
/* Gradient of the turning angle at node i, times coef; adds to gp (0 where the rope runs straight). */
void cs_rows_angle_gradient(const cs_span_grad *sp, double coef, double gp[3][3]);

/* The row of a rope end node i that slips through its fitting (termination.c), and its Jacobian row. */
double cs_termination_slip_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, int c,
                                    int i);
void cs_termination_slip_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                                  int c, int i);

/* The rails' share of post p's rows (rail.c): its tilts' in its moment unit, and its pull's (if it slides
 * out) in the force unit. */
void cs_rail_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int p,
                      double unit);

/* Coulomb's clamp(y, -b, b) with its corners rounded over a width w (a parabola over |x| < 4 ln 2 widths
 * at each: C1, exact outside the band, at most w ln 2 off at the corner), so that Newton sees a smooth
 * switch between sticking and sliding; and its slopes in y and b. */
double cs_smooth_clamp(double y, double b, double w);
/* max(a, w) with its corner rounded as the clamp's (exact for a >= (1 + 4 ln 2) w; 1.28 w at a = 0), and
 * its slope in a into *slope if not NULL: a band that is mu F_n where that is well above w, and w where
 * the rope pulls nothing into the body. */
double cs_smooth_floor(double a, double w, double *slope);
void cs_smooth_clamp_slopes(double y, double b, double w, double *dy, double *db);

/* The small stiffness by which a node between two slack spans sticks instead of being undetermined
 * (solve residuals: lambda - proj(...) - eps c dm). */
#define CS_STICK_EPS 1e-4

#endif
