/* SPDX-License-Identifier: MIT */
/* The vehicle: a rigid body in 6 degrees of freedom on four tyres, with a crushable front face.
 *
 * Forces: gravity; each tyre a vertical spring-damper at its contact point (stiffness from the static
 * axle load and a static deflection; a stiff stop once it is pressed down to its rim), with rolling
 * resistance along the wheel's heading and, across it, the tyre's cornering force: its cornering stiffness
 * times its slip angle at small angles, the friction's mu N when it slides (tyre_force); the barrier's
 * resultant force and moment from the quasi-static solve at the pose. Integration is velocity Verlet
 * (kick-drift-kick, second order in dt): v += a dt / 2 with the forces at the step's start, x += v dt, the
 * barrier solved at the new pose, v += a dt / 2 with the forces there; the same for Euler's equations in the
 * body frame, I dw/dt = tau - w x I w, with the quaternion advanced by the exponential map. The tyre
 * forces depend on velocity too: they are taken with the half-step velocity.
 *
 * Crush: the front face sits cg_to_front - crush ahead of the CG. Loading follows the force-deformation
 * curve (extrapolated with its last slope); below the largest crush reached the face unloads elastically
 * with crush_unload_stiffness, so the permanent set stays. */
#include "core/vec3.h"
#include "elements/elements.h"

#include <math.h>

/* A tyre pressed down past its section height (its radius less its rim's) bears on its rim: a stop this
 * many times the tyre's rate, stiff enough that the compression stays within millimetres of the section
 * and stiffer stops change nothing the runs report (docs/theory.md, "Tyres that bottom on their rims"). */
#define CS_RIM_STOP 50.0

void cs_vehicle_derive(const cs_vehicle_def *v, double g, cs_vehicle_model *vm) {
    vm->def = *v;
    double a = v->cg_to_front_axle, b = v->wheelbase - a;
    double axle_load[2] = {v->mass * g * b / v->wheelbase, v->mass * g * a / v->wheelbase};
    cs_vehicle_wheel_points(v, vm->wheel);
    for (int i = 0; i < 4; i++) {
        int rear = i >= 2;
        double n = 0.5 * axle_load[rear];
        vm->tyre_k[i] = n / v->tyre_static_deflection;
        double m_share = g > 0.0 ? n / g : 0.25 * v->mass;
        vm->tyre_c[i] = 2.0 * v->tyre_damping_ratio * sqrt(vm->tyre_k[i] * m_share);
        if (g == 0.0) vm->tyre_k[i] = vm->tyre_c[i] = 0.0;
        vm->rim_k[i] = CS_RIM_STOP * vm->tyre_k[i];
        vm->rim_c[i] = sqrt(CS_RIM_STOP) * vm->tyre_c[i]; /* the same fraction of critical */
    }
    vm->rim_travel = v->rim_radius > 0.0 ? v->wheel_radius - v->rim_radius : HUGE_VAL;
    for (int i = 0; i < 3; i++)
        vm->inv_inertia[i] = 1.0 / v->inertia[i];
}

#define CS_TYRE_VREG 0.05 /* m/s: slip speed over which tyre friction builds up to mu N */
/* A rolling tyre's cornering stiffness over its load, per radian of slip angle: 0.15 per degree, the
 * middle of radial tyres' 11-19% (Gillespie 1992, Fundamentals of Vehicle Dynamics; docs/assumptions.md). */
#define CS_TYRE_CORNERING (0.15 * 180.0 / CS_PI)

static void body_to_world(const cs_state *s, const double *body, double *world) {
    quat_rotate(world, s->quat, body);
    v3_add(world, world, s->pos);
}

void cs_vehicle_face_point(const cs_model *model, const cs_state *s, double crush, double y_body,
                           double z_body, double *world) {
    double b[3] = {model->vehicle.def.cg_to_front - crush, y_body, z_body};
    body_to_world(s, b, world);
}

/* The wheels' contact points. At the rear axle the tyre fills the side from the ground to the wheel arch,
 * and the body from there up, so a rear wheel meets ropes from the ground to the side's top, its tyre's
 * outer face taken in the plane of the side (docs/assumptions.md): a rope that passes under the rear
 * overhang meets it there (docs/theory.md, "The rear wheels"). A front tyre meets a rope that passes under
 * the bumper with its tread: above the axle it pushes the rope forward and up into the wheel arch and takes
 * it, below the axle it presses it down and climbs over it, so a front wheel's band starts at the axle's
 * height at rest, `wheel_radius - tyre_static_deflection` (docs/theory.md, "The front wheels"). */
void cs_vehicle_corner_point(const cs_model *model, const cs_state *s, double crush, int k, double z_body,
                             double *world) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double x = cs_corner_front(k)         ? v->cg_to_front - crush
               : cs_corner_front_wheel(k) ? v->cg_to_front_axle
               : cs_corner_wheel(k)       ? v->cg_to_front_axle - v->wheelbase
                                          : -v->cg_to_rear;
    double b[3] = {x, (k % 2 == 0 ? 0.5 : -0.5) * v->front_width, z_body};
    body_to_world(s, b, world);
}

void cs_vehicle_corner_band(const cs_model *model, int k, double *lo, double *hi) {
    const cs_vehicle_def *v = &model->vehicle.def;
    *lo = (cs_corner_front(k)         ? v->face_bottom
           : cs_corner_front_wheel(k) ? v->wheel_radius - v->tyre_static_deflection
           : cs_corner_wheel(k)       ? 0.0
                                      : v->side_bottom) -
          v->cg_height;
    *hi = (cs_corner_front(k) ? v->face_top : v->side_top) - v->cg_height;
}

double cs_crush_curve(const cs_vehicle_def *v, double d) {
    int n = v->crush_point_count;
    const double *x = v->crush_deformation, *f = v->crush_force;
    if (d <= 0.0) return 0.0;
    int i = 1;
    while (i < n - 1 && d > x[i])
        i++;
    return f[i - 1] + (f[i] - f[i - 1]) * (d - x[i - 1]) / (x[i] - x[i - 1]);
}

double cs_crush_force(const cs_vehicle_def *v, double d, double dmax) {
    if (d >= dmax) return cs_crush_curve(v, d);
    double f = cs_crush_curve(v, dmax) - v->crush_unload_stiffness * (dmax - d);
    return f > 0.0 ? f : 0.0;
}

double cs_crush_permanent(const cs_vehicle_def *v, double dmax) {
    double p = dmax - cs_crush_curve(v, dmax) / v->crush_unload_stiffness;
    return p > 0.0 ? p : 0.0;
}

/* The spring force of wheel w's tyre at compression comp > 0 (its rim's stop past the section height),
 * its energy into *energy and its damping coefficient into *damper (may be NULL). */
static double tyre_spring(const cs_vehicle_model *vm, int w, double comp, double *energy, double *damper) {
    double past = comp - vm->rim_travel, n = vm->tyre_k[w] * comp;
    *energy = 0.5 * vm->tyre_k[w] * comp * comp;
    if (damper) *damper = vm->tyre_c[w] + (past > 0.0 ? vm->rim_c[w] : 0.0);
    if (past > 0.0) n += vm->rim_k[w] * past, *energy += 0.5 * vm->rim_k[w] * past * past;
    return n;
}

/* Tyre contact force of wheel w (world) at its contact point; adds its dissipated power. */
static void tyre_force(const cs_model *model, const cs_state *s, int w, double *f, double *point,
                       double *power) {
    const cs_vehicle_model *vm = &model->vehicle;
    v3_set(f, 0.0, 0.0, 0.0);
    body_to_world(s, vm->wheel[w], point);
    double comp = vm->def.tyre_static_deflection - point[2];
    if (comp <= 0.0) return;
    double r[3], wv[3], v[3];
    v3_sub(r, point, s->pos);
    quat_rotate(wv, s->quat, s->omega);
    v3_cross(v, wv, r);
    v3_add(v, v, s->vel);
    double stored, c, spring = tyre_spring(vm, w, comp, &stored, &c), n = spring - c * v[2];
    if (n <= 0.0) {
        /* the damper holds the extending tyre off the ground: the spring's energy, which the potential
         * counts, goes to the damper at the spring's force times v_z */
        *power += spring * v[2];
        return;
    }
    double fwd[3], body_x[3] = {1.0, 0.0, 0.0};
    quat_rotate(fwd, s->quat, body_x);
    fwd[2] = 0.0;
    double fn = v3_norm(fwd);
    if (fn < 1e-9) return; /* standing on its nose: no rolling direction */
    v3_scale(fwd, fwd, 1.0 / fn);
    double side[3] = {-fwd[1], fwd[0], 0.0};
    double vf = v3_dot(v, fwd), vs = v3_dot(v, side);
    double ff = -vm->def.rolling_resistance * n * vf / sqrt(vf * vf + CS_TYRE_VREG * CS_TYRE_VREG);
    /* across: c N tan(alpha) at a small slip angle (tan(alpha) = vs / |vf|), saturating at the friction's
     * mu N, as F = -mu N vs / sqrt(vs^2 + vr^2) with vr = mu |vf| / c (never below the regularising speed:
     * a tyre rolling slower than c v_reg / mu, 0.6 m/s, keeps smooth Coulomb friction) */
    double mu = vm->def.tyre_friction, vr = fmax(CS_TYRE_VREG, mu * fabs(vf) / CS_TYRE_CORNERING);
    double fs = -mu * n * vs / sqrt(vs * vs + vr * vr);
    v3_set(f, ff * fwd[0] + fs * side[0], ff * fwd[1] + fs * side[1], n);
    /* friction, and the damper's c v_z^2 whether the tyre is compressing or extending (n > 0 here) */
    *power += -(ff * vf + fs * vs) + c * v[2] * v[2];
}

/* Linear and angular (body frame) accelerations at the pose and velocities as they stand, with the
 * barrier's last resultant; and the power the tyres dissipate. */
static void accelerations(const cs_model *model, cs_state *s) {
    const cs_vehicle_model *vm = &model->vehicle;
    double m = vm->def.mass;
    double f[3], mo[3], power = 0.0;
    v3_set(f, s->force[0], s->force[1], s->force[2] - m * model->scenario.gravity);
    v3_copy(mo, s->moment);
    for (int w = 0; w < 4; w++) {
        double fw[3], p[3], r[3], t[3];
        tyre_force(model, s, w, fw, p, &power);
        v3_add(f, f, fw);
        v3_sub(r, p, s->pos);
        v3_cross(t, r, fw);
        v3_add(mo, mo, t);
    }
    s->tyre_power = power;
    v3_scale(s->acc, f, 1.0 / m);
    double tb[3], iw[3], gyro[3];
    quat_unrotate(tb, s->quat, mo);
    for (int i = 0; i < 3; i++)
        iw[i] = vm->def.inertia[i] * s->omega[i];
    v3_cross(gyro, s->omega, iw);
    for (int i = 0; i < 3; i++)
        s->ang_acc[i] = vm->inv_inertia[i] * (tb[i] - gyro[i]);
}

/* Half a step's kick (h the step): velocities by the accelerations, and the tyres' dissipation over
 * that half. */
static void kick(cs_state *s, double h) {
    v3_addto(s->vel, s->acc, 0.5 * h);
    v3_addto(s->omega, s->ang_acc, 0.5 * h);
    s->e_tyre += s->tyre_power * 0.5 * h;
}

void cs_vehicle_start(const cs_model *model, cs_state *s) {
    accelerations(model, s);
}

/* Start of a step of h: kick with the forces at the step's start, then drift to the new pose. */
void cs_vehicle_integrate(cs_state *s, double h) {
    kick(s, h);
    v3_addto(s->pos, s->vel, h);
    quat_integrate(s->quat, s->omega, h);
}

/* End of a step of h: the forces at the new pose (the barrier's resultant included), the second kick. */
void cs_vehicle_finish(const cs_model *model, cs_state *s, double h) {
    accelerations(model, s);
    kick(s, h);
}

/* The accelerations are linear in the barrier's push, and the tyres' forces and the gyroscopic term stay as
 * they were found at the step's end. */
void cs_vehicle_push_changed(const cs_model *model, cs_state *s, const double *old_force,
                             const double *old_moment) {
    const cs_vehicle_model *vm = &model->vehicle;
    double df[3], dm[3], db[3];
    v3_sub(df, s->force, old_force);
    v3_sub(dm, s->moment, old_moment);
    v3_addto(s->acc, df, 1.0 / vm->def.mass);
    quat_unrotate(db, s->quat, dm);
    for (int i = 0; i < 3; i++)
        s->ang_acc[i] += vm->inv_inertia[i] * db[i];
}

double cs_vehicle_kinetic_energy(const cs_model *model, const cs_state *s) {
    const double *in = model->vehicle.def.inertia;
    double e = 0.5 * model->vehicle.def.mass * v3_dot(s->vel, s->vel);
    for (int i = 0; i < 3; i++)
        e += 0.5 * in[i] * s->omega[i] * s->omega[i];
    return e;
}

/* Gravity (from grade) plus the tyre springs, absolute; energy.c takes it relative to t = 0. */
double cs_vehicle_potential_energy(const cs_model *model, const cs_state *s) {
    const cs_vehicle_model *vm = &model->vehicle;
    double e = vm->def.mass * model->scenario.gravity * s->pos[2];
    for (int w = 0; w < 4; w++) {
        double p[3];
        body_to_world(s, vm->wheel[w], p);
        double comp = vm->def.tyre_static_deflection - p[2], stored;
        if (comp > 0.0) tyre_spring(vm, w, comp, &stored, NULL), e += stored;
    }
    return e;
}
