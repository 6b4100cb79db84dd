/* SPDX-License-Identifier: MIT */
/* Results read back for comparison (load/runread.h): the 50-ms average of a deceleration history against
 * its closed forms (a constant, a ramp, on an uneven time grid), a measured file's units, read in SI, its
 * quoted cells, its columns' quantities known by their names and refused where the name or the unit does
 * not fit, and a run's 50-ms average undefined before its first window. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "load/runread.h"

/* avg(t) = (1/W) integral over [t - W, t]: a for a constant a, k (t - W/2) for a ramp k t; exact for the
 * integral of a piecewise-linear history, whatever the grid. NAN before the first full window. */
static void average_50ms_closed_forms(void **state) {
    (void)state;
    enum { N = 400 };
    double t[N], a[N], r[N], avg[N];
    for (int i = 0; i < N; i++) {
        t[i] = 0.0005 * i + 0.0002 * (i % 3); /* uneven, increasing */
        a[i] = 30.0, r[i] = 200.0 * t[i];
    }
    cs_trace_average_50ms(t, a, N, avg);
    for (int i = 0; i < N; i++) {
        if (t[i] < t[0] + 0.05 - 1e-12)
            assert_true(isnan(avg[i]));
        else if (fabs(avg[i] - 30.0) > 1e-9)
            fail_msg("constant: t = %g s: %.12g, want 30", t[i], avg[i]);
    }
    cs_trace_average_50ms(t, r, N, avg);
    for (int i = 0; i < N; i++)
        if (t[i] >= t[0] + 0.05 && fabs(avg[i] - 200.0 * (t[i] - 0.025)) > 1e-9)
            fail_msg("ramp: t = %g s: %.12g, want %.12g", t[i], avg[i], 200.0 * (t[i] - 0.025));
}

/* text into a new temporary file, its name into path (of "/tmp/cablesim-runread-XXXXXX"). */
static void write_temp(char *path, const char *text) {
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* A measured file in ms, mph and ft: read in s, m/s and m; its 50-ms deceleration from its speed, a speed
 * falling at 0.5 g giving 0.5 g after the first 50 ms. */
static void measured_units_and_average(void **state) {
    (void)state;
    char path[] = "/tmp/cablesim-runread-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fputs("time [ms],speed [mph],penetration (ft)\n", f);
    const double g = 9.80665, mph = 0.44704, ft = 0.3048;
    for (int i = 0; i <= 200; i++) {
        double ts = 0.001 * i;
        fprintf(f, "%.6f,%.12f,%.12f\n", ts * 1e3, (20.0 - 0.5 * g * ts) / mph, 0.1 * i / ft);
    }
    fclose(f);
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    cs_trace tr;
    if (cs_trace_load_measured(path, u, &tr, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(tr.n, 201);
    assert_true(fabs(tr.t[200] - 0.2) < 1e-12 && fabs(tr.y[CS_TRACE_SPEED][0] - 20.0) < 1e-9);
    assert_true(fabs(tr.max_penetration - 20.0) < 1e-9);
    assert_true(fabs(tr.max_decel_50ms_g - 0.5) < 1e-9);
    assert_true(isnan(tr.y[CS_TRACE_DECEL_50MS][10]) && !tr.have[CS_TRACE_TENSION]);
    cs_trace_free(&tr);
    cs_units_free(u);
    remove(path);
}

/* A blank line is skipped; a row of another width than the header is refused at its own line. */
static void measured_row_of_another_width(void **state) {
    (void)state;
    char path[] = "/tmp/cablesim-runread-XXXXXX", want[600];
    write_temp(path, "time [s],speed [m/s]\n0,20\n\n0.001,19.9\n0.002,19.8,7\n");
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    cs_trace tr;
    assert_int_equal(cs_trace_load_measured(path, u, &tr, &err), CS_ERR_INVALID);
    snprintf(want, sizeof want, "%s:5:1: 3 cells, the header has 2", path);
    assert_string_equal(err.message, want);
    cs_units_free(u);
    remove(path);
}

/* Cells quoted as a spreadsheet writes them (RFC 4180), header and numbers, read to the same trace as the
 * same file unquoted; a quoted cell that is not a number ("12,5", a decimal comma) refused at its place. */
static void measured_quoted_cells(void **state) {
    (void)state;
    char plain[] = "/tmp/cablesim-runread-XXXXXX", quoted[] = "/tmp/cablesim-runread-XXXXXX",
         comma[] = "/tmp/cablesim-runread-XXXXXX", want[600];
    write_temp(plain, "time [ms],speed [mph],deceleration [g]\n0,40,0\n10,39.5,1.25\n20,38.75,2.5\n");
    write_temp(quoted, "\"time [ms]\",\"speed [mph]\",\"deceleration [g]\"\r\n\"0\",\"40\",\"0\"\r\n"
                       "\"10\",\"39.5\",\"1.25\"\r\n\"20\",\"38.75\",\"2.5\"\r\n");
    write_temp(comma, "time [ms],speed [mph]\n0,40\n10,\"12,5\"\n");
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    cs_trace a, b;
    if (cs_trace_load_measured(plain, u, &a, &err) != CS_OK) fail_msg("%s", err.message);
    if (cs_trace_load_measured(quoted, u, &b, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(b.n, 3);
    assert_true(fabs(b.t[2] - 0.020) < 1e-15 && fabs(b.y[CS_TRACE_SPEED][1] - 39.5 * 0.44704) < 1e-12);
    assert_true(fabs(b.y[CS_TRACE_DECEL][2] - 2.5 * 9.80665) < 1e-12);
    for (size_t i = 0; i < a.n; i++) {
        assert_true(a.t[i] == b.t[i]);
        for (int k = 0; k < CS_TRACE_COUNT; k++)
            assert_true(a.have[k] == b.have[k] &&
                        (a.y[k][i] == b.y[k][i] || (isnan(a.y[k][i]) && isnan(b.y[k][i]))));
    }
    cs_trace_free(&a), cs_trace_free(&b);
    assert_int_equal(cs_trace_load_measured(comma, u, &a, &err), CS_ERR_INVALID);
    snprintf(
        want, sizeof want,
        "%s:3:4: '12,5' is not a number (expected a finite number, or an empty cell where there is none)",
        comma);
    assert_string_equal(err.message, want);
    cs_units_free(u);
    remove(plain), remove(quoted), remove(comma);
}

/* A column's name says its quantity by a word (case and punctuation aside, a capital after a lower-case
 * letter starting a word), its unit is checked against it: an
 * acceleration along the travel read as a deceleration with its sign turned, a speed, a penetration and a
 * rope tension each from a name a user writes. A group in brackets that names no unit of the column's
 * quantity is part of its name ("(CG)", the instrument's place; "(CFC 60)", its filter). */
static void measured_names(void **state) {
    (void)state;
    char accel[] = "/tmp/cablesim-runread-XXXXXX", rest[] = "/tmp/cablesim-runread-XXXXXX";
    write_temp(accel, "Time [ms],Longitudinal Acceleration (CG) [g]\n0,0\n10,-0.5\n20,-1.5\n");
    write_temp(rest, "t (s),vehicleSpeed (km/h),Rope tension (CFC 60) [kN],dynamic PENETRATION [ft]\n0,72,0,"
                     "0\n1,36,50,10\n");
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    cs_trace tr;
    if (cs_trace_load_measured(accel, u, &tr, &err) != CS_OK) fail_msg("%s", err.message);
    assert_true(tr.have[CS_TRACE_DECEL] && !tr.have[CS_TRACE_SPEED] && !tr.have[CS_TRACE_PENETRATION]);
    assert_true(tr.y[CS_TRACE_DECEL][0] == 0.0 && fabs(tr.y[CS_TRACE_DECEL][1] - 0.5 * 9.80665) < 1e-12 &&
                fabs(tr.y[CS_TRACE_DECEL][2] - 1.5 * 9.80665) < 1e-12);
    cs_trace_free(&tr);
    if (cs_trace_load_measured(rest, u, &tr, &err) != CS_OK) fail_msg("%s", err.message);
    assert_true(fabs(tr.y[CS_TRACE_SPEED][1] - 10.0) < 1e-12 && fabs(tr.final_speed - 10.0) < 1e-12);
    assert_true(fabs(tr.max_tension - 50e3) < 1e-6 && fabs(tr.max_penetration - 3.048) < 1e-12);
    assert_true(!tr.have[CS_TRACE_DECEL]);
    cs_trace_free(&tr);
    cs_units_free(u);
    remove(accel), remove(rest);
}

/* A column whose name names no quantity compared (no word begins as one: "extension" holds no tension)
 * is refused at its place, whatever its unit, as are a
 * unit that does not fit the name, a name of two quantities, one across the travel or averaged, a name of
 * two units of its quantity (which of them its numbers are in cannot be told), and a second column of one
 * quantity (an acceleration beside a deceleration). */
static void measured_names_refused(void **state) {
    (void)state;
    static const char *const cases[][2] = {
        {"time [s],foo [m]",
         ":1:10: 'foo [m]' names no quantity compared (expected a name holding decel, accel, "
         "speed, velocity, penetration or tension, e.g. \"speed [mph]\")"},
        {"time [s],speed [mph],post displacement [m]",
         ":1:22: 'post displacement [m]' names no quantity compared"},
        {"time [s],x [g]", ":1:10: 'x [g]' names no quantity compared"},
        {"time [s],dynamic deflection [m]", ":1:10: 'dynamic deflection [m]' names no quantity compared"},
        {"time [s],spring extension [kN]", ":1:10: 'spring extension [kN]' names no quantity compared"},
        {"time [s],speed [m]", ":1:10: 'speed [m]' names a speed: 'm' is a unit of length, not of speed "
                               "(expected mph, km/h or m/s)"},
        {"time [s],\"tension (g)\"", ":1:10: 'tension (g)' names a rope tension: 'g' is a unit of mass, not "
                                     "of force (expected kip or kN)"},
        {"time [s],speed and tension [kN]", ":1:10: 'speed and tension [kN]' names both a speed and a rope "
                                            "tension (expected one quantity a column)"},
        {"time [s],lateral acceleration [g]",
         ":1:10: 'lateral acceleration [g]' names an acceleration across the "
         "travel (expected the vehicle's along its travel, not averaged)"},
        {"time [s],decel_50ms [g]", ":1:10: 'decel_50ms [g]' names a deceleration averaged over time"},
        {"time [s],decel50ms [g]", ":1:10: 'decel50ms [g]' names a deceleration averaged over time"},
        {"time [s],Decel 50 ms [g]", ":1:10: 'Decel 50 ms [g]' names a deceleration averaged over time"},
        {"time [s],Y Accel [g]", ":1:10: 'Y Accel [g]' names an acceleration across the travel"},
        {"time [s],accel_z [g]", ":1:10: 'accel_z [g]' names an acceleration across the travel"},
        {"time [s],Lat Accel [g]", ":1:10: 'Lat Accel [g]' names an acceleration across the travel"},
        {"time [s],speed [mph] (km/h)", ":1:10: 'speed [mph] (km/h)' names two units of a speed, 'mph' and "
                                        "'km/h' (expected one, as \"name [unit]\" or \"name (unit)\")"},
        {"time [s],speed [mph] [km/h]", ":1:10: 'speed [mph] [km/h]' names two units of a speed, 'mph' and "
                                        "'km/h'"},
        {"time [s],tension (kN) [kip]", ":1:10: 'tension (kN) [kip]' names two units of a rope tension, 'kN' "
                                        "and 'kip'"},
        {"time (s) (ms),speed [mph]", ":1:1: 'time (s) (ms)' names two units of the time, 's' and 'ms'"},
        {"time [s],deceleration [g],acceleration [g]", ":1:27: 'acceleration [g]' is a second column of the "
                                                       "quantity of 'deceleration [g]' (the header's column "
                                                       "2, at 1:10) (expected one column of each)"},
    };
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char path[] = "/tmp/cablesim-runread-XXXXXX", text[200], want[600];
        int cols = 1;
        for (const char *c = cases[k][0]; *c; c++)
            cols += *c == ',';
        snprintf(text, sizeof text, "%s\n0%s\n1%s\n", cases[k][0], cols > 2 ? ",1,1" : ",1",
                 cols > 2 ? ",1,1" : ",1");
        write_temp(path, text);
        cs_trace tr;
        assert_int_equal(cs_trace_load_measured(path, u, &tr, &err), CS_ERR_INVALID);
        snprintf(want, sizeof want, "%s%s", path, cases[k][1]);
        if (strncmp(err.message, want, strlen(want)) != 0) fail_msg("%s\nwant %s", err.message, want);
        remove(path);
    }
    cs_units_free(u);
}

/* A run's folder: its timeseries.csv's decel_50ms column is 0 for the first 50 ms, where the average is
 * undefined; read so it is NaN there and the column's own value from t = 50 ms. */
static void run_average_undefined_before_a_window(void **state) {
    (void)state;
    char dir[] = "/tmp/cablesim-runread-XXXXXX", path[64];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/summary.json", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("{\"outcome\": \"stopped\"}\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/timeseries.csv", dir);
    assert_non_null(f = fopen(path, "w"));
    fputs(
        "t [s],vx [m/s],vy [m/s],ax [m/s^2],ay [m/s^2],forward_speed [m/s],decel_50ms [g],penetration [m]\n",
        f);
    for (int i = 0; i <= 100;
         i++) /* 2 g from the start, the column 0 until t = 50 ms as the engine writes it */
        fprintf(f, "%.3f,%.6f,0,%.6f,0,%.6f,%d,0\n", 0.001 * i, 20 - 19.6133 * 0.001 * i, -19.6133,
                20 - 19.6133 * 0.001 * i, i < 50 ? 0 : 2);
    fclose(f);
    cs_error err;
    cs_trace tr;
    if (cs_trace_load_run(dir, &tr, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(tr.n, 101);
    for (size_t i = 0; i < tr.n; i++)
        if (i < 50 ? !isnan(tr.y[CS_TRACE_DECEL_50MS][i])
                   : fabs(tr.y[CS_TRACE_DECEL_50MS][i] - 2 * 9.80665) > 1e-9)
            fail_msg("t = %g s: the 50-ms average %g m/s^2, want %s", tr.t[i], tr.y[CS_TRACE_DECEL_50MS][i],
                     i < 50 ? "none" : "19.6133");
    cs_trace_free(&tr);
    remove(path);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    remove(path);
    rmdir(dir);
}

/* A long name: its quantity's word is found after 200 characters of other words, and a message quotes
 * the first 57 characters and "..." so that its reason is kept whole. */
static void measured_long_names(void **state) {
    (void)state;
    char long_ok[] = "/tmp/cablesim-runread-XXXXXX", long_bad[] = "/tmp/cablesim-runread-XXXXXX";
    char text[1200] = "time [s],", name[400] = "";
    for (int k = 0; k < 25; k++)
        strcat(name, "vehicle "); /* 200 characters */
    snprintf(text + strlen(text), sizeof text - strlen(text), "%sspeed [mph]\n0,10\n1,5\n", name);
    write_temp(long_ok, text);
    snprintf(text, sizeof text, "time [s],%sspeed [m]\n0,10\n1,5\n", name);
    write_temp(long_bad, text);
    cs_error err;
    cs_units *u = cs_units_open(&err);
    assert_non_null(u);
    cs_trace tr;
    if (cs_trace_load_measured(long_ok, u, &tr, &err) != CS_OK) fail_msg("%s", err.message);
    assert_true(tr.have[CS_TRACE_SPEED] && fabs(tr.y[CS_TRACE_SPEED][1] - 5 * 0.44704) < 1e-12);
    cs_trace_free(&tr);
    assert_int_equal(cs_trace_load_measured(long_bad, u, &tr, &err), CS_ERR_INVALID);
    char want[400];
    snprintf(
        want, sizeof want,
        "%s:1:10: '%.57s...' names a speed: 'm' is a unit of length, not of speed (expected mph, km/h or "
        "m/s)",
        long_bad, name);
    assert_string_equal(err.message, want);
    cs_units_free(u);
    remove(long_ok), remove(long_bad);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(average_50ms_closed_forms),
                                       cmocka_unit_test(measured_units_and_average),
                                       cmocka_unit_test(measured_row_of_another_width),
                                       cmocka_unit_test(measured_quoted_cells),
                                       cmocka_unit_test(measured_names),
                                       cmocka_unit_test(measured_names_refused),
                                       cmocka_unit_test(measured_long_names),
                                       cmocka_unit_test(run_average_undefined_before_a_window)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
