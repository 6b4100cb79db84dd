/* SPDX-License-Identifier: MIT */
/* Small 3D vector and quaternion helpers, all inline. Quaternions are (w, x, y, z), unit length,
 * rotating body-frame vectors into the world frame. */
#ifndef CS_VEC3_H
#define CS_VEC3_H

#include "cablesim/units.h"

#include <math.h>

static inline void v3_set(double *r, double x, double y, double z) {
    r[0] = x, r[1] = y, r[2] = z;
}
static inline void v3_copy(double *r, const double *a) {
    r[0] = a[0], r[1] = a[1], r[2] = a[2];
}
static inline void v3_add(double *r, const double *a, const double *b) {
    r[0] = a[0] + b[0], r[1] = a[1] + b[1], r[2] = a[2] + b[2];
}
static inline void v3_sub(double *r, const double *a, const double *b) {
    r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}
static inline void v3_scale(double *r, const double *a, double s) {
    r[0] = a[0] * s, r[1] = a[1] * s, r[2] = a[2] * s;
}
/* r += a * s */
static inline void v3_addto(double *r, const double *a, double s) {
    r[0] += a[0] * s, r[1] += a[1] * s, r[2] += a[2] * s;
}
static inline double v3_dot(const double *a, const double *b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline double v3_norm(const double *a) {
    return sqrt(v3_dot(a, a));
}
/* Length of a plane vector; sqrt of the sum (the engine's tilts and moments are far from overflow, and
 * hypot's care cost APS3 4% of its time). */
static inline double v2_norm(double x, double y) {
    return sqrt(x * x + y * y);
}
static inline void v3_cross(double *r, const double *a, const double *b) {
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    r[0] = x, r[1] = y, r[2] = z;
}
static inline double v3_dist(const double *a, const double *b) {
    double d[3];
    v3_sub(d, a, b);
    return v3_norm(d);
}

/* r = q * v * q^-1 (body to world) */
static inline void quat_rotate(double *r, const double *q, const double *v) {
    double u[3] = {q[1], q[2], q[3]}, t[3], c[3];
    v3_cross(t, u, v);
    v3_scale(t, t, 2.0);
    v3_cross(c, u, t);
    double x = v[0] + q[0] * t[0] + c[0], y = v[1] + q[0] * t[1] + c[1], z = v[2] + q[0] * t[2] + c[2];
    r[0] = x, r[1] = y, r[2] = z;
}
/* r = q^-1 * v * q (world to body) */
static inline void quat_unrotate(double *r, const double *q, const double *v) {
    double qc[4] = {q[0], -q[1], -q[2], -q[3]};
    quat_rotate(r, qc, v);
}
/* q <- q * exp(w_body * dt / 2), renormalised */
static inline void quat_integrate(double *q, const double *w, double dt) {
    double a = v3_norm(w) * dt, s, c;
    if (a < 1e-12) {
        s = 0.5 * dt, c = 1.0;
    } else {
        s = sin(0.5 * a) / a * dt, c = cos(0.5 * a);
    }
    double d[4] = {c, w[0] * s, w[1] * s, w[2] * s};
    double r[4] = {q[0] * d[0] - q[1] * d[1] - q[2] * d[2] - q[3] * d[3],
                   q[0] * d[1] + q[1] * d[0] + q[2] * d[3] - q[3] * d[2],
                   q[0] * d[2] - q[1] * d[3] + q[2] * d[0] + q[3] * d[1],
                   q[0] * d[3] + q[1] * d[2] - q[2] * d[1] + q[3] * d[0]};
    double n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    for (int i = 0; i < 4; i++)
        q[i] = r[i] / n;
}
/* World rotation vector that turns a into b (b = exp(r / 2) * a), the shorter way round. */
static inline void quat_turn(double *r, const double *a, const double *b) {
    double w = b[0] * a[0] + b[1] * a[1] + b[2] * a[2] + b[3] * a[3], v[3];
    v[0] = a[0] * b[1] - b[0] * a[1] - (b[2] * a[3] - b[3] * a[2]);
    v[1] = a[0] * b[2] - b[0] * a[2] - (b[3] * a[1] - b[1] * a[3]);
    v[2] = a[0] * b[3] - b[0] * a[3] - (b[1] * a[2] - b[2] * a[1]);
    double sg = w < 0.0 ? -1.0 : 1.0, n = v3_norm(v), f = n < 1e-12 ? 2.0 : 2.0 * atan2(n, sg * w) / n;
    v3_scale(r, v, sg * f);
}
/* Quaternion of a rotation by yaw about world z. */
static inline void quat_from_yaw(double *q, double yaw) {
    q[0] = cos(0.5 * yaw), q[1] = 0.0, q[2] = 0.0, q[3] = sin(0.5 * yaw);
}
/* Roll (x), pitch (y), yaw (z) of the Z-Y-X convention. */
static inline void quat_to_euler(const double *q, double *roll, double *pitch, double *yaw) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    *roll = atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
    double s = 2.0 * (w * y - z * x);
    *pitch = asin(s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s));
    *yaw = atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
}

#endif
