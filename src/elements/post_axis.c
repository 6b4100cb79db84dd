/* SPDX-License-Identifier: MIT */
/* The axis of a tilted post: a post tilts about its pivot by a rotation vector alpha = theta * u (u the
 * horizontal direction its top moves), so a point at height z (when upright) sits at
 *   pivot + (z + pivot depth + w) a(alpha),   a = (u sin theta, cos theta),
 * w how far it has slid out of the ground along its axis (post_pullout.c), or, for a post whose stub
 * stays upright, at pivot + (z + pivot depth) a(alpha) + w e_z; J = da/dalpha carries a force at that
 * point into the post's generalised moment (post.c, rail.c).
 * Geometry only: no forces, and of the state only how a post slides; what the post and the rails both
 * build on. */
#include "core/vec3.h"
#include "elements/elements.h"

#include <math.h>

/* sin(t)/t, its derivative over t and cos t. Below t = 0.1 (a post that has not failed) by their series
 * to t^12, whose next terms are at most 1.2e-25: exact to round-off, cheaper than sin and cos, and more
 * accurate for the derivative, whose closed form (t cos t - sin t) / t^3 loses digits to cancellation
 * (1e-9 of it at t = 1e-3). */
void cs_post_axis_terms(double t, double *s, double *g, double *c) {
    if (t < 0.1) {
        static const double sc[] = {1.0,          -1.0 / 6,        1.0 / 120,       -1.0 / 5040,
                                    1.0 / 362880, -1.0 / 39916800, 1.0 / 6227020800};
        static const double gc[] = {-1.0 / 3,       1.0 / 30,        -1.0 / 840,        1.0 / 45360,
                                    -1.0 / 3991680, 1.0 / 518918400, -1.0 / 93405312000};
        static const double cc[] = {1.0,         -1.0 / 2,       1.0 / 24,       -1.0 / 720,
                                    1.0 / 40320, -1.0 / 3628800, 1.0 / 479001600};
        double t2 = t * t, ss = 0.0, gs = 0.0, cs = 0.0;
        for (int k = 6; k >= 0; k--)
            ss = sc[k] + t2 * ss, gs = gc[k] + t2 * gs, cs = cc[k] + t2 * cs;
        *s = ss, *g = gs, *c = cs;
    } else {
        double sn = sin(t);
        *c = cos(t);
        *s = sn / t;
        *g = (t * *c - sn) / (t * t * t);
    }
}

/* The point at height z (when upright) of post p at tilt alpha, slid out by w, s and c from
 * cs_post_axis_terms at |alpha|: pivot + (z + pivot depth + w) a(alpha), or upright pivot + (z + pivot
 * depth) a(alpha) + w e_z. */
void cs_post_attachment_from(const cs_model *model, int p, const double *tilt, double pull, int upright,
                             double s, double c, double z, double *out) {
    double dp = model->posts[p].pivot, l = z + dp + (upright ? 0.0 : pull);
    v3_set(out, model->posts[p].x + l * tilt[0] * s, l * tilt[1] * s, -dp + l * c + (upright ? pull : 0.0));
}

void cs_post_attachment(const cs_model *model, int p, const double *tilt, double pull, int upright, double z,
                        double *out) {
    double s, g, c;
    cs_post_axis_terms(v2_norm(tilt[0], tilt[1]), &s, &g, &c);
    cs_post_attachment_from(model, p, tilt, pull, upright, s, c, z, out);
}

void cs_post_slide_direction(const cs_model *model, int p, const double *tilt, double *d) {
    if (cs_post_upright(&model->posts[p]))
        v3_set(d, 0.0, 0.0, 1.0);
    else
        cs_post_axis_at(tilt, d);
}

/* Jacobian of the post axis a(alpha), 3 x 2, row-major, from cs_post_axis_terms' s and g at |alpha|. */
void cs_post_axis_jacobian_from(const double *al, double s, double g, double *j) {
    j[0] = s + al[0] * al[0] * g, j[1] = al[0] * al[1] * g;
    j[2] = al[0] * al[1] * g, j[3] = s + al[1] * al[1] * g;
    j[4] = -s * al[0], j[5] = -s * al[1];
}

void cs_post_axis_jacobian_at(const double *al, double *j) {
    double s, g, c;
    cs_post_axis_terms(v2_norm(al[0], al[1]), &s, &g, &c);
    cs_post_axis_jacobian_from(al, s, g, j);
}

void cs_post_axis_at(const double *tilt, double *a) {
    double s, g, c;
    cs_post_axis_terms(v2_norm(tilt[0], tilt[1]), &s, &g, &c);
    v3_set(a, tilt[0] * s, tilt[1] * s, c);
}

/* The axis Jacobian j (3 x 2) at a tilt and its derivatives along the two tilts,
 * dj[6 m + e] = d j[e] / d alpha_m (2 x 6): the solver's linearisation of a post's moment. With
 * s = sin t / t, g = s'(t) / t and q = g'(t) / t, d s / d alpha_m = g alpha_m and d g / d alpha_m =
 * q alpha_m, where q = -(3 g + s) / t^2; that loses digits to cancellation near 0 (3 g + s -> 0), so
 * below t = 0.05 its series 1/15 - t^2/210 + t^4/7560 (next term t^6/498960: below 1e-16 there). */
void cs_post_axis_jacobian(const double *tilt, double *j, double *dj) {
    double t = v2_norm(tilt[0], tilt[1]), s, g, c, t2 = t * t;
    cs_post_axis_terms(t, &s, &g, &c);
    double q = t < 0.05 ? 1.0 / 15.0 - t2 / 210.0 + t2 * t2 / 7560.0 : -(3.0 * g + s) / t2;
    cs_post_axis_jacobian_from(tilt, s, g, j);
    for (int m = 0; m < 2; m++) {
        double a = tilt[m], *d = dj + 6 * m;
        d[0] = g * a + (m == 0 ? 2.0 * tilt[0] * g : 0.0) + tilt[0] * tilt[0] * q * a;
        d[1] = (m == 0 ? tilt[1] : tilt[0]) * g + tilt[0] * tilt[1] * q * a;
        d[2] = d[1];
        d[3] = g * a + (m == 1 ? 2.0 * tilt[1] * g : 0.0) + tilt[1] * tilt[1] * q * a;
        d[4] = -(g * a * tilt[0] + (m == 0 ? s : 0.0));
        d[5] = -(g * a * tilt[1] + (m == 1 ? s : 0.0));
    }
}
