/* SPDX-License-Identifier: MIT */
/* Occupant risk against closed forms: the J211/1 filter's gain at named frequencies against the
 * Butterworth magnitude of its bilinear design (and J211's nominal -3 dB at 1.667 CFC), no phase shift;
 * a constant deceleration's flail-space impact time, OIV and ORA; the impact after the record at the
 * relative velocity held; THIV on a circular path (the head's straight line seen from the turning
 * vehicle); PHD and ASI of constant accelerations; the ridedown of an impact less than a window before
 * the record's end; the moving-average maximum of a ramp. */
#include <stdlib.h>

#include "check.h"
#include "out/record.h"
#include "study/occupant.h"

#define PI 3.14159265358979323846
#define G 9.80665

/* The gain and the quadrature (phase) part of the filtered sine of frequency f, sampled every dt, fitted
 * over whole periods in the middle half of a 1-s record (the ends' transients left out). */
static void sine_response(double cfc, double f, double dt, double *gain, double *quad) {
    int n = (int)lround(1.0 / dt);
    double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
    for (int i = 0; i < n; i++)
        x[i] = sin(2 * PI * f * i * dt);
    assert_int_equal(cs_cfc_filter(cfc, dt, x, y, n), 0);
    int k0 = n / 4, m = n / 2; /* 0.5 s: whole periods of every frequency below */
    double s = 0, c = 0;
    for (int i = k0; i < k0 + m; i++)
        s += y[i] * sin(2 * PI * f * i * dt), c += y[i] * cos(2 * PI * f * i * dt);
    *gain = 2 * s / m, *quad = 2 * c / m;
    free(x);
    free(y);
}

static void cfc_gain_closed_form(void **state) {
    (void)state;
    const double dt = 1e-4, cfcs[] = {60, 180};
    for (int k = 0; k < 2; k++) {
        double cfc = cfcs[k], fd = 2.0775 * cfc;
        /* CFC, 1.667 CFC (J211's -3 dB), 2 CFC and 5 CFC: whole periods in 0.5 s */
        const double fs[] = {cfc, cfc * 5 / 3, 2 * cfc, 5 * cfc};
        for (int i = 0; i < 4; i++) {
            double gain, quad;
            sine_response(cfc, fs[i], dt, &gain, &quad);
            double r = tan(PI * fs[i] * dt) / tan(PI * fd * dt);
            CHECK_REL(gain, 1.0 / (1.0 + r * r * r * r), 2e-4); /* |H|^2 of the 2-pole design */
            CHECK_ABS(quad / gain, 0.0, 1e-4);                  /* forward and back: no phase */
        }
        /* J211's nominal corner: -3 dB at 1.667 CFC (the analog form; 10 kHz is close to it) */
        double gain, quad;
        sine_response(cfc, cfc * 5 / 3, dt, &gain, &quad);
        CHECK_REL(gain, 1.0 / sqrt(2.0), 0.01);
    }
    /* a constant passes unchanged; an interval too long for the class is refused */
    double x[50], y[50];
    for (int i = 0; i < 50; i++)
        x[i] = 3.25;
    assert_int_equal(cs_cfc_filter(180, 1e-3, x, y, 50), 0);
    for (int i = 0; i < 50; i++)
        CHECK_REL(y[i], 3.25, 1e-12);
    cs_cfc_coeffs c;
    assert_int_equal(cs_cfc_coefficients(180, 1.0 / (2 * 2.0775 * 180) * 1.001, &c), -1);
    assert_int_equal(cs_cfc_coefficients(180, 1.0 / (2 * 2.0775 * 180) * 0.999, &c), 0);
}

/* A motion of n samples of constant body accelerations (m/s^2) and yaw rate. */
typedef struct {
    double *buf;
    cs_vehicle_motion m;
} motion;

static motion constant_motion(int n, double dt, double ax, double ay, double az, double r) {
    motion mo;
    mo.buf = malloc((size_t)n * 4 * sizeof *mo.buf);
    for (int i = 0; i < n; i++)
        mo.buf[i] = ax, mo.buf[n + i] = ay, mo.buf[2 * n + i] = az, mo.buf[3 * n + i] = r;
    mo.m = (cs_vehicle_motion){n, dt, mo.buf, mo.buf + n, mo.buf + 2 * n, mo.buf + 3 * n};
    return mo;
}

static void constant_deceleration(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    const double dt = 1e-4, a = 10 * G, b = 3 * G;
    motion mo = constant_motion(5000, dt, -a, b, 0.0, 0.0); /* 0.5 s */
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    /* x reaches 0.6 m first: t = sqrt(2 0.6 / a); the lateral 0.3 m would take sqrt(2 0.3 / b) */
    double t = sqrt(2 * 0.6 / a);
    assert_true(t < sqrt(2 * 0.3 / b));
    assert_int_equal(o.impact, CS_FLAIL_IN_RECORD);
    CHECK_REL(o.t_impact, t, 1e-4);
    CHECK_REL(o.oiv_x, a * t, 1e-4);
    CHECK_REL(o.oiv_y, b * t, 1e-4);
    CHECK_REL(o.ora_x, 10.0, 1e-9);
    CHECK_REL(o.ora_y, 3.0, 1e-9);
    /* no yaw: the head meets the front at the same time; THIV the resultant; PHD the resultant in g */
    assert_int_equal(o.thiv_impact, CS_FLAIL_IN_RECORD);
    CHECK_REL(o.t_thiv, t, 1e-4);
    CHECK_REL(o.thiv, hypot(a, b) * t, 1e-4);
    CHECK_REL(o.phd, hypot(10.0, 3.0), 1e-9);
    free(mo.buf);

    /* lateral first: 8 g across, 2 g along */
    mo = constant_motion(5000, dt, -2 * G, -8 * G, 0.0, 0.0);
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    t = sqrt(2 * 0.3 / (8 * G));
    CHECK_REL(o.t_impact, t, 1e-4);
    CHECK_REL(o.oiv_y, 8 * G * t, 1e-4);
    CHECK_REL(o.oiv_x, 2 * G * t, 1e-4);
    free(mo.buf);
}

static void impact_after_the_record(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    const double dt = 1e-4, a = 10 * G, tau = 0.05;
    motion mo = constant_motion((int)lround(tau / dt) + 1, dt, -a, 0.0, 0.0, 0.0);
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    /* at the end: v = a tau, d = a tau^2 / 2, then 0.6 m reached at v held */
    double v = a * tau, d = 0.5 * a * tau * tau;
    assert_int_equal(o.impact, CS_FLAIL_AFTER_RECORD);
    CHECK_REL(o.t_impact, tau + (0.6 - d) / v, 1e-6);
    CHECK_REL(o.oiv_x, v, 1e-9);
    CHECK_ABS(o.ora_x, 0.0, 0.0);
    free(mo.buf);
    /* no relative motion at all: no impact */
    mo = constant_motion(100, dt, 0.0, 0.0, 0.0, 0.0);
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    assert_int_equal(o.impact, CS_FLAIL_NONE);
    assert_int_equal(o.thiv_impact, CS_FLAIL_NONE);
    free(mo.buf);
}

/* The head's place against the vehicle on a circle of radius R at speed V (turning left): the head goes
 * straight on at V from the CG; the vehicle's axes turn by r t. */
static void head_on_circle(double V, double R, double t, double b[2]) {
    double r = V / R, dx = V * t - R * sin(r * t), dy = -R * (1 - cos(r * t)), c = cos(r * t), s = sin(r * t);
    b[0] = c * dx + s * dy, b[1] = -s * dx + c * dy;
}

static void thiv_on_a_circle(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    const double dt = 1e-4, V = 100 / 3.6, R = 40.0;
    motion mo = constant_motion(8000, dt, 0.0, V * V / R, 0.0, V / R);
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    /* the closed form's first time at |b_x| = 0.6 or |b_y| = 0.3, by bisection */
    double lo = 0, hi = 0.8, b[2];
    for (int k = 0; k < 100; k++) {
        double mid = 0.5 * (lo + hi);
        head_on_circle(V, R, mid, b);
        if (fabs(b[0]) >= 0.6 || fabs(b[1]) >= 0.3)
            hi = mid;
        else
            lo = mid;
    }
    double t = hi, h = 1e-6, b1[2], b0[2];
    head_on_circle(V, R, t + h, b1);
    head_on_circle(V, R, t - h, b0);
    double thiv =
        hypot((b1[0] - b0[0]) / (2 * h), (b1[1] - b0[1]) / (2 * h)); /* d/dt in the vehicle's axes */
    assert_int_equal(o.thiv_impact, CS_FLAIL_IN_RECORD);
    CHECK_REL(o.t_thiv, t, 1e-3);
    CHECK_REL(o.thiv, thiv, 1e-3);
    /* the flail space ignores the yaw: lateral 0.3 m at sqrt(2 0.3 / ay) */
    double tf = sqrt(2 * 0.3 / (V * V / R));
    CHECK_REL(o.t_impact, tf, 1e-4);
    CHECK_REL(o.oiv_y, V * V / R * tf, 1e-4);
    free(mo.buf);
}

static void asi_constant(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    motion mo = constant_motion(2000, 1e-4, 6 * G, -4.5 * G, 5 * G, 0.0);
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    CHECK_REL(o.asi, sqrt(3 * 0.25), 1e-9); /* 6/12, 4.5/9, 5/10 */
    free(mo.buf);
    /* one direction at its limit: ASI 1 */
    mo = constant_motion(2000, 1e-4, 0.0, 9 * G, 0.0, 0.0);
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    CHECK_REL(o.asi, 1.0, 1e-9);
    free(mo.buf);
}

static void window_mean(void **state) {
    (void)state;
    double x[100];
    for (int i = 0; i < 100; i++)
        x[i] = i;
    int at;
    /* a ramp's largest 10-sample mean is its last window's: 90..99, mean 94.5 */
    CHECK_REL(cs_window_mean_max(x, 100, 10, 20, &at), 94.5, 1e-12);
    assert_int_equal(at, 90);
    for (int i = 0; i < 100; i++)
        x[i] = -fabs(i - 40.0);
    /* |mean| is largest in the window furthest from 40 that fits: 90..99 (mean -54.5) */
    CHECK_REL(cs_window_mean_max(x, 100, 10, 0, &at), 54.5, 1e-12);
    /* from 95 no whole window fits: the samples past the end count as zeros, (55 + ... + 59) / 10 */
    CHECK_REL(cs_window_mean_max(x, 100, 10, 95, &at), 28.5, 1e-12);
    assert_int_equal(at, 95);
    assert_int_equal(cs_window_mean_max(x, 100, 10, 100, &at), 0.0);
    assert_int_equal(at, -1);
}

/* An occupant impact less than a ridedown window before the record's end: the vehicle taken on at
 * constant velocity past it (as for an impact after the record), so a constant deceleration a gives the
 * ridedown a (t_end - t_impact) / 10 ms, and PHD the same share of its resultant. */
static void impact_near_the_end(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    const double dt = 1e-4, a = 10 * G, b = 2 * G, t = sqrt(2 * 0.6 / a), left = 0.004;
    int n = (int)lround((t + left) / dt) + 1;
    motion mo = constant_motion(n, dt, -a, b, 0.0, 0.0);
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_OK);
    assert_int_equal(o.impact, CS_FLAIL_IN_RECORD);
    CHECK_REL(o.t_impact, t, 1e-4);
    double share = ((n - 1) * dt - t) / 0.010; /* 0.4, to within a sample */
    CHECK_ABS(o.ora_x, 10.0 * share, 10.0 * 0.011);
    CHECK_ABS(o.ora_y, 2.0 * share, 2.0 * 0.011);
    CHECK_ABS(o.phd, hypot(10.0, 2.0) * share, hypot(10.0, 2.0) * 0.011);
    assert_true(o.ora_x > 3.8 && o.ora_x < 4.2);
    free(mo.buf);
}

static void bad_motion(void **state) {
    (void)state;
    cs_occupant_rules rules = cs_default_occupant_rules();
    motion mo = constant_motion(100, 1e-4, 1.0, 0.0, 0.0, 0.0);
    mo.buf[50] = NAN;
    cs_occupant_risk o;
    cs_error err;
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "not finite"));
    mo.buf[50] = 1.0;
    mo.m.dt = 0.01; /* 100 Hz: too coarse for CFC 180 */
    assert_int_equal(cs_occupant_risk_compute(&mo.m, &rules, &o, &err), CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "too long"));
    free(mo.buf);
}

/* A record holding these vehicle frames alone. */
static cs_record record_of(cs_vehicle_view *frames, int n) {
    cs_record rec;
    memset(&rec, 0, sizeof rec);
    rec.frame_count = n, rec.vehicle = frames;
    return rec;
}

/* A record's motion in the vehicle's axes: a vehicle yawed 30 deg and rolled 10 deg decelerating at 8 g
 * along its own x and 2 g along its own y (the world accelerations turned by Rz Ry Rx), frames every
 * 1 ms from 0 to 0.5 s, first contact at 0.1 s: resampled every 0.1 ms from the contact, the body
 * accelerations come back, and the occupant risk is the constant deceleration's closed form. */
static void motion_of_a_record(void **state) {
    (void)state;
    enum { FRAMES = 501 };
    static cs_vehicle_view frames[FRAMES];
    const double yaw = 30 * PI / 180, roll = 10 * PI / 180, bx = -8 * G, by = 2 * G;
    for (int i = 0; i < FRAMES; i++) {
        cs_vehicle_view *v = &frames[i];
        memset(v, 0, sizeof *v);
        v->t = 1e-3 * i, v->yaw = yaw, v->roll = roll, v->angular_velocity[2] = 0.0;
        /* world = Rz(yaw) Rx(roll) (bx, by, 0) */
        double ry = cos(roll) * by, rz = sin(roll) * by;
        v->acceleration[0] = cos(yaw) * bx - sin(yaw) * ry;
        v->acceleration[1] = sin(yaw) * bx + cos(yaw) * ry;
        v->acceleration[2] = rz;
    }
    cs_record rec = record_of(frames, FRAMES);
    cs_vehicle_motion m;
    cs_error err;
    assert_int_equal(cs_vehicle_motion_of_record(&rec, 0.1, 1e-4, NULL, &m, &err), CS_OK);
    assert_int_equal(m.n, 4001); /* 0.4 s after the contact, every 0.1 ms */
    for (int i = 0; i < m.n; i += 97) {
        CHECK_REL(m.ax[i], bx, 1e-12);
        CHECK_REL(m.ay[i], by, 1e-12);
        CHECK_ABS(m.az[i], 0.0, 1e-9);
    }
    free((void *)m.ax);
    cs_occupant_risk o;
    assert_int_equal(cs_occupant_risk_for_run(&rec, 0.1, NULL, &o, &err), CS_OK);
    double t = sqrt(2 * 0.6 / (8 * G));
    CHECK_REL(o.t_impact, t, 1e-4);
    CHECK_REL(o.oiv_x, 8 * G * t, 1e-4);
    CHECK_REL(o.oiv_y, 2 * G * t, 1e-4);
    CHECK_REL(o.ora_x, 8.0, 1e-9);
    double roll_peak, pitch_peak;
    cs_record_roll_pitch_peaks(&rec, &roll_peak, &pitch_peak);
    CHECK_REL(roll_peak, roll, 1e-12);
    CHECK_ABS(pitch_peak, 0.0, 0.0);
    /* no contact, or none before the end: refused with the reason */
    assert_int_equal(cs_occupant_risk_for_run(&rec, -1.0, NULL, &o, &err), CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "never touched"));
    assert_int_equal(cs_occupant_risk_for_run(&rec, 0.5, NULL, &o, &err), CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "no motion after the first contact"));
}

/* At a point r from the CG of a body turning about its vertical axis with yaw rate w = w0 + alpha t and
 * no acceleration at its CG: a = alpha x r + w x (w x r); for r = (x0, y0, z0): (-w^2 x0 - alpha y0,
 * -w^2 y0 + alpha x0, 0). */
static void motion_at_a_point(void **state) {
    (void)state;
    enum { FRAMES = 201 };
    static cs_vehicle_view frames[FRAMES];
    const double w0 = 0.5, alpha = 2.0, r[3] = {0.6, -0.4, 0.3};
    for (int i = 0; i < FRAMES; i++) {
        memset(&frames[i], 0, sizeof frames[i]);
        frames[i].t = 1e-3 * i;
        frames[i].angular_velocity[2] = w0 + alpha * frames[i].t;
    }
    cs_record rec = record_of(frames, FRAMES);
    cs_vehicle_motion m;
    cs_error err;
    assert_int_equal(cs_vehicle_motion_of_record(&rec, 0.0, 1e-4, r, &m, &err), CS_OK);
    for (int i = 0; i < m.n; i += 101) {
        double t = i * m.dt, w = w0 + alpha * t;
        /* linear in t between frames, w^2 is not: within (1 ms)^2 alpha^2 / 4 of the closed form */
        CHECK_ABS(m.ax[i], -w * w * r[0] - alpha * r[1], 1e-5);
        CHECK_ABS(m.ay[i], -w * w * r[1] + alpha * r[0], 1e-5);
        CHECK_ABS(m.az[i], 0.0, 1e-12);
        CHECK_REL(m.yaw_rate[i], w, 1e-12);
    }
    free((void *)m.ax);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(cfc_gain_closed_form),
                                       cmocka_unit_test(constant_deceleration),
                                       cmocka_unit_test(impact_after_the_record),
                                       cmocka_unit_test(thiv_on_a_circle),
                                       cmocka_unit_test(asi_constant),
                                       cmocka_unit_test(window_mean),
                                       cmocka_unit_test(impact_near_the_end),
                                       cmocka_unit_test(bad_motion),
                                       cmocka_unit_test(motion_of_a_record),
                                       cmocka_unit_test(motion_at_a_point)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
