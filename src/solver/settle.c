/* SPDX-License-Identifier: MIT */
/* The posts' lean under the pretension, as an installer tensions a rope on standing posts: every span at
 * the pretension T0 (held, not following the spans' stretch), each post turned until the ropes' and
 * rails' moment on it balances its resistance (post.c, cs_post_residual_at). The posts are tied to each
 * other by the rails and by the spans between them, so this is one system, F(alpha) = 0 over every
 * standing post's tilt (2 each), solved by the barrier's Newton driver (newton.c) on its banded LU.
 *
 * Its Jacobian is the difference quotient of F, taken a colour at a time: a post's residual depends on
 * the tilts of the posts within `reach` of it along the barrier (the rails tie neighbours; a span joins
 * the posts at its ends, which on a line that skips posts are further apart), so posts 2 reach + 1 apart
 * share no row and are perturbed together: 2 (2 reach + 1) evaluations of F a Jacobian, 6 on a line of
 * posts every rope and rail visits. Residuals are scaled by each post's moment unit (post.c), as the
 * barrier solve's, and solved to 1e-12 of it.
 *
 * A post that the pretension would bend past its elastic limit (a weak end post under a heavy pretension)
 * leans no further than that limit here (the step limit): the barrier's solve then lets it yield and the
 * rope slide over it, as a propped post let go would. */
#include "core/vec3.h"
#include "solver/newton.h"
#include "solver/solver.h"
#include "solver/work.h"

#include <math.h>

#define CS_SETTLE_TOL 1e-12 /* of a post's moment unit */
#define CS_SETTLE_STEP 1e-7 /* rad: the difference quotient's step */
#define CS_ELASTIC_SHARE 0.999

typedef struct settle {
    const cs_model *model;
    cs_state *s;
    int reach;       /* posts apart that one's residual can still see */
    double *shifted; /* [n] F at a perturbed tilt */
} settle;

static int solved(const cs_state *s, int p) {
    return cs_post_in_barrier(&s->posts[p]) && !s->posts[p].captured;
}

static void place(void *ctx, const double *x) {
    settle *st = ctx;
    for (int p = 0; p < st->model->post_count; p++) {
        if (!solved(st->s, p)) continue;
        st->s->posts[p].tilt[0] = x[2 * p], st->s->posts[p].tilt[1] = x[2 * p + 1];
        cs_post_place_nodes(st->model, st->s, p, st->s->posts[p].tilt, NULL);
    }
}

static void residual(void *ctx, double *r) {
    settle *st = ctx;
    for (int p = 0; p < st->model->post_count; p++) {
        r[2 * p] = r[2 * p + 1] = 0.0;
        if (!solved(st->s, p)) continue;
        cs_post_residual_at(st->model, st->s, p, st->s->posts[p].tilt, NULL, NULL, NULL, r + 2 * p);
        double unit = st->model->posts[p].moment_scale;
        r[2 * p] /= unit, r[2 * p + 1] /= unit;
    }
}

static int jacobian(void *ctx, const double *x, const double *r, cs_band *jac) {
    settle *st = ctx;
    int posts = st->model->post_count, n = 2 * posts, w = 2 * st->reach + 1, band = 2 * st->reach + 1;
    if (cs_band_shape(jac, n, band, band) != 0) return -1;
    double *xs = st->shifted + n; /* the perturbed tilts */
    for (int colour = 0; colour < w; colour++)
        for (int b = 0; b < 2; b++) {
            for (int k = 0; k < n; k++)
                xs[k] = x[k];
            for (int q = colour; q < posts; q += w)
                xs[2 * q + b] += CS_SETTLE_STEP;
            place(st, xs);
            residual(st, st->shifted);
            for (int q = colour; q < posts; q += w)
                for (int p = q - st->reach; p <= q + st->reach; p++)
                    for (int i = 0; i < 2 && p >= 0 && p < posts; i++)
                        cs_band_add(jac, 2 * p + i, 2 * q + b,
                                    (st->shifted[2 * p + i] - r[2 * p + i]) / CS_SETTLE_STEP);
        }
    for (int p = 0; p < posts; p++) /* a post not solved for keeps its tilt: an identity row */
        if (!solved(st->s, p))
            cs_band_add(jac, 2 * p, 2 * p, 1.0), cs_band_add(jac, 2 * p + 1, 2 * p + 1, 1.0);
    place(st, x);
    return 0;
}

/* The largest share of the step that keeps every post within its elastic limit: |e + t d| <= L, e the
 * elastic tilt (tilt less plastic), d the step, L the limit. */
static double step_limit(void *ctx, const double *dx) {
    settle *st = ctx;
    double t = 1.0;
    for (int p = 0; p < st->model->post_count; p++) {
        if (!solved(st->s, p)) continue;
        const cs_post_model *pm = &st->model->posts[p];
        const cs_post_state *ps = &st->s->posts[p];
        double lim = CS_ELASTIC_SHARE * pm->moment_cap / pm->k_rot, d[2] = {dx[2 * p], dx[2 * p + 1]};
        double e[2] = {ps->tilt[0] - ps->plastic[0], ps->tilt[1] - ps->plastic[1]};
        double a = d[0] * d[0] + d[1] * d[1], bb = e[0] * d[0] + e[1] * d[1], c = e[0] * e[0] + e[1] * e[1];
        if (!(a > 0.0) || v2_norm(e[0] + d[0], e[1] + d[1]) <= lim) continue;
        double root = (-bb + sqrt(fmax(bb * bb - a * (c - lim * lim), 0.0))) / a; /* |e + t d| = L */
        t = fmin(t, fmax(root, 0.0));
    }
    return t;
}

/* How many posts apart two posts one residual sees can be: neighbours (the rails), or the posts at the
 * two ends of a span. */
static int reach_of(const cs_model *model, const cs_state *s) {
    int reach = 1;
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        for (int i = 1, last = -1; i + 1 < cs->node_count; i++) {
            int p = cs->node[i];
            if (p < 0) continue;
            if (last >= 0 && p - last > reach) reach = p - last;
            last = p;
        }
    }
    return reach;
}

double cs_settle_posts(const cs_model *model, cs_state *s) {
    int n = 2 * model->post_count;
    cs_newton *nw = &s->work->sys.newton;
    if (n == 0 || 2 * n > nw->capacity) return 0.0;
    settle st = {model, s, reach_of(model, s), s->work->sys.scratch};
    for (int p = 0; p < model->post_count; p++)
        nw->x[2 * p] = s->posts[p].tilt[0], nw->x[2 * p + 1] = s->posts[p].tilt[1];
    cs_newton_problem problem = {&st, n, place, residual, jacobian, step_limit};
    cs_newton_forget(nw);
    double r = cs_newton_solve(nw, &problem, CS_SETTLE_TOL);
    place(&st, nw->x);
    cs_newton_forget(nw); /* the band is the barrier solve's again */
    return r;
}
