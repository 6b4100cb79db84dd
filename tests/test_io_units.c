/* SPDX-License-Identifier: MIT */
/* Units: exact conversion factors, the field's aliases, wrong dimensions, and two unit systems used
 * from two threads at once. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "load/units.h"

static double read_ok(cs_units *u, const char *text, cs_quantity q) {
    double v = NAN;
    cs_error err;
    if (cs_units_read(u, text, q, &v, &err) != CS_OK) fail_msg("'%s': %s", text, err.message);
    return v;
}

static void close_to(double got, double want) {
    if (!(fabs(got - want) <= 1e-12 * fabs(want))) fail_msg("got %.17g, want %.17g", got, want);
}

static int setup(void **state) {
    *state = cs_units_open(NULL);
    return *state ? 0 : -1;
}

static int teardown(void **state) {
    cs_units_free(*state);
    return 0;
}

/* Exact factors: 1 ft = 0.3048 m, 1 lb = 0.45359237 kg, g0 = 9.80665 m/s^2, lbf = lb g0. */
static void test_exact_factors(void **state) {
    cs_units *u = *state;
    const double lbf = 0.45359237 * 9.80665, ft = 0.3048, in = 0.0254;
    close_to(read_ok(u, "40 mph", CS_Q_SPEED), 17.8816);                     /* 40 * 1609.344 / 3600 */
    close_to(read_ok(u, "8000 psf", CS_Q_PRESSURE), 8000 * lbf / (ft * ft)); /* 383042.0718... */
    close_to(read_ok(u, "8000 psf", CS_Q_PRESSURE), 383042.07184268673);
    close_to(read_ok(u, "52 kip", CS_Q_FORCE), 52000 * lbf);
    close_to(read_ok(u, "20000 ksi", CS_Q_PRESSURE), 20e6 * lbf / (in * in));
    close_to(read_ok(u, "15000 lb", CS_Q_MASS), 6803.88555);
    close_to(read_ok(u, "1.75 in", CS_Q_LENGTH), 0.04445);
    close_to(read_ok(u, "8 ft", CS_Q_LENGTH), 2.4384);
    close_to(read_ok(u, "0.5 ms", CS_Q_TIME), 5e-4);
    close_to(read_ok(u, "45 deg", CS_Q_ANGLE), 0.78539816339744831);
    close_to(read_ok(u, "0.471 in2", CS_Q_AREA), 0.471 * in * in);
    close_to(read_ok(u, "1.67 lb/ft", CS_Q_MASS_PER_LENGTH), 1.67 * 0.45359237 / ft);
    close_to(read_ok(u, "20 MN/m", CS_Q_STIFFNESS), 2e7);
    close_to(read_ok(u, "2.192 in4", CS_Q_SECOND_MOMENT), 2.192 * pow(in, 4));
    close_to(read_ok(u, "1.287 in3", CS_Q_SECTION_MODULUS), 1.287 * pow(in, 3));
    close_to(read_ok(u, "1 g", CS_Q_ACCELERATION), 9.80665);
    close_to(read_ok(u, "1 lbf", CS_Q_FORCE), lbf);
    close_to(read_ok(u, "60 km/h", CS_Q_SPEED), 60 / 3.6);
}

static void test_bare_numbers_are_pure(void **state) {
    cs_units *u = *state;
    close_to(read_ok(u, "  0.15 ", CS_Q_NUMBER), 0.15);
    close_to(read_ok(u, "0", CS_Q_SPEED), 0.0); /* 0 in any unit */
    close_to(read_ok(u, "1.75in", CS_Q_LENGTH), 0.04445);
    close_to(read_ok(u, "-5 kip", CS_Q_FORCE), -5000 * 0.45359237 * 9.80665);
}

static void expect_error(cs_units *u, const char *text, cs_quantity q, const char *part) {
    double v;
    cs_error err;
    assert_int_equal(cs_units_read(u, text, q, &v, &err), CS_ERR_INVALID);
    assert_int_equal(err.status, CS_ERR_INVALID);
    if (!strstr(err.message, part)) fail_msg("'%s': message '%s' lacks '%s'", text, err.message, part);
}

static void test_wrong_units(void **state) {
    cs_units *u = *state;
    expect_error(u, "40 kg", CS_Q_SPEED, "'kg' is a unit of mass, not of speed");
    expect_error(u, "15000 lb", CS_Q_FORCE, "'lb' is a unit of mass, not of force");
    expect_error(u, "1 lbf", CS_Q_MASS, "'lbf' is a unit of force, not of mass");
    expect_error(u, "3 furlongz", CS_Q_LENGTH, "unknown unit 'furlongz'");
    expect_error(u, "fast", CS_Q_TIME, "'fast' is not a number");
    expect_error(u, "", CS_Q_TIME, "is not a number");
    expect_error(u, "1 g", CS_Q_FORCE, "'g' is a unit of mass"); /* gram, unless an acceleration */
    expect_error(u, "0.3 m", CS_Q_NUMBER, "'m' is a unit of length, not of number");
    expect_error(u, "nan", CS_Q_LENGTH, "is not a number");
    expect_error(u, "1e400 m", CS_Q_LENGTH, "is out of range");
    expect_error(u, "35", CS_Q_SPEED, "'35' has no unit: give one, e.g. 35 mph");
    expect_error(u, "90", CS_Q_ANGLE, "'90' has no unit: give one, e.g. 90 deg");
    expect_error(u, "0x28 mph", CS_Q_SPEED, "'0x28 mph' is not a decimal number");
    expect_error(u, "inf m", CS_Q_LENGTH, "is not a number");
}

/* udunits2 converts a unit to one of the reciprocal dimension by 1/x: "2 s/m" would be 0.5 m/s and "0.5 ft-1"
 * (a '-' before a digit is a negative power) a 2-ft length. A value is never meant so: refused. */
static void test_reciprocal_units_refused(void **state) {
    cs_units *u = *state;
    const struct {
        const char *text;
        cs_quantity q;
        const char *message;
    } bad[] = {
        {"2 s/m", CS_Q_SPEED, "'s/m' is a unit of 1/speed, not of speed"},
        {"0.5 ft-1", CS_Q_LENGTH,
         "'ft-1' is a unit of 1/length, not of length (a '-' before a digit is a negative power)"},
        {"1 ft-2", CS_Q_AREA, "'ft-2' is a unit of 1/area, not of area"},
        {"2 Hz", CS_Q_TIME, "'Hz' is a unit of 1/time, not of time"},
        {"2 in/kip", CS_Q_STIFFNESS, "'in/kip' is a unit of 1/stiffness, not of stiffness"},
        {"3 1/psi", CS_Q_PRESSURE, "'1/psi' is a unit of 1/pressure, not of pressure"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        expect_error(u, bad[i].text, bad[i].q, bad[i].message);
}

/* udunits2 reads a number in a unit's text as a factor of it and "@ N" or "since DATE" as an origin: "15
 * 000.5 kg" (digits grouped by a space) would be 15 x 0.5 kg and "5 s @ 3" a date's seconds. Refused, while a
 * power's digits and the 1 of 1/x read as before. */
static void test_number_in_unit_refused(void **state) {
    cs_units *u = *state;
    const char *why = "(expected one number, then its unit, e.g. \"15000 lb\": no space within the number)";
    const struct {
        const char *text, *unit;
        cs_quantity q;
    } bad[] = {{"15 000.5 kg", "'000.5 kg'", CS_Q_MASS},
               {"5 2 kg", "'2 kg'", CS_Q_MASS},
               {"1 m 2", "'m 2'", CS_Q_LENGTH},
               {"2 kg.5", "'kg.5'", CS_Q_MASS},
               {"1 m2.5", "'m2.5'", CS_Q_AREA},
               {"5 s @ 3", "'s @ 3'", CS_Q_TIME},
               {"5 s since 1970-01-01", "'s since 1970-01-01'", CS_Q_TIME},
               {"3 1000 lbf/ft^2", "'1000 lbf/ft^2'", CS_Q_PRESSURE}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char part[160];
        snprintf(part, sizeof part, "'%s' has a number in its unit %s %s", bad[i].text, bad[i].unit, why);
        expect_error(u, bad[i].text, bad[i].q, part);
    }
    const double in = 0.0254;
    close_to(read_ok(u, "3 in2", CS_Q_AREA), 3 * in * in);
    close_to(read_ok(u, "3 in^2", CS_Q_AREA), 3 * in * in);
    close_to(read_ok(u, "3 in**2", CS_Q_AREA), 3 * in * in);
    close_to(read_ok(u, "3 in^+2", CS_Q_AREA), 3 * in * in);
    close_to(read_ok(u, "2 kg m-1", CS_Q_MASS_PER_LENGTH), 2.0);
    close_to(read_ok(u, "2 kg m^-1", CS_Q_MASS_PER_LENGTH), 2.0);
    close_to(read_ok(u, "2 N 1/m", CS_Q_STIFFNESS), 2.0);
}

/* A moment or an energy as engineers write it: two units joined by a hyphen, a middle dot (U+00B7, or the dot
 * operator U+22C5 that looks the same), a '*', a '.' or a space, in either order, is their product. By hand:
 * 1 ft kip = 0.3048 m x 4448.2216152605 N = 1355.8179483314 J (1355.818 J to the 0.5 mJ of its last digit),
 * 1 ft lbf = 1.3558179483314 J, 1 kip in = 112.98482902762 J, 1 kN m = 1000 J. A pound written lb is of
 * mass: refused for an energy, saying so. */
static void test_products_of_units(void **state) {
    cs_units *u = *state;
    const double lbf = 0.45359237 * 9.80665, ft = 0.3048, in = 0.0254;
    const char *ft_kip[] = {"ft-kip", "kip-ft", "ft\u00b7kip", "kip\u00b7ft", "ft\u22c5kip",
                            "ft*kip", "kip ft", "ft.kip",      "ft-kips"};
    for (size_t i = 0; i < sizeof ft_kip / sizeof ft_kip[0]; i++) {
        char text[32];
        snprintf(text, sizeof text, "1 %s", ft_kip[i]);
        double v = read_ok(u, text, CS_Q_ENERGY);
        close_to(v, ft * 1000 * lbf);
        if (!(fabs(v - 1355.818) <= 5e-4)) fail_msg("'%s': %.9g J, not 1355.818 J", text, v);
    }
    close_to(read_ok(u, "2.5 ft-lbf", CS_Q_ENERGY), 2.5 * ft * lbf);
    close_to(read_ok(u, "2.5 lbf-ft", CS_Q_ENERGY), 2.5 * ft * lbf);
    close_to(read_ok(u, "2.5 ft\u00b7lbf", CS_Q_ENERGY), 2.5 * ft * lbf);
    close_to(read_ok(u, "3 kip-in", CS_Q_ENERGY), 3 * 1000 * lbf * in);
    close_to(read_ok(u, "3 in-kip", CS_Q_ENERGY), 3 * 1000 * lbf * in);
    close_to(read_ok(u, "3 kip\u00b7in", CS_Q_ENERGY), 3 * 1000 * lbf * in);
    close_to(read_ok(u, "7 kN-m", CS_Q_ENERGY), 7000);
    close_to(read_ok(u, "7 kN\u00b7m", CS_Q_ENERGY), 7000);
    close_to(read_ok(u, "7 kN\u22c5m", CS_Q_ENERGY), 7000);
    close_to(read_ok(u, "7 N\u00b7m", CS_Q_ENERGY), 7);
    close_to(read_ok(u, "7 N-m", CS_Q_ENERGY), 7);
    const char *pound = "is not a unit of energy (lb is a pound of mass: a pound of force is lbf)";
    expect_error(u, "1000 ft-lb", CS_Q_ENERGY, pound);
    expect_error(u, "1000 lb-ft", CS_Q_ENERGY, pound);
    expect_error(u, "1000 ft\u00b7lb", CS_Q_ENERGY, pound);
    expect_error(u, "1000 in-lb", CS_Q_ENERGY, pound);
    expect_error(u, "15000 lb", CS_Q_FORCE, "'lb' is a unit of mass, not of force (lb is a pound of mass");
    expect_error(u, "5 kip-ft", CS_Q_FORCE, "'kip-ft' is a unit of energy, not of force");
    expect_error(u, "5 kNm", CS_Q_ENERGY, "unknown unit 'kNm'");
}

/* Each thread has its own unit system; both read at once. */
static void *convert_many(void *arg) {
    cs_units *u = cs_units_open(NULL);
    double sum = 0, v;
    for (int i = 0; u && i < 300; i++)
        if (cs_units_read(u, (i & 1) ? "40 mph" : "8 ft", (i & 1) ? CS_Q_SPEED : CS_Q_LENGTH, &v, NULL) ==
            CS_OK)
            sum += v;
    cs_units_free(u);
    *(double *)arg = sum;
    return NULL;
}

static void test_two_threads(void **state) {
    (void)state;
    pthread_t t[2];
    double sums[2] = {0, 0};
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_create(&t[i], NULL, convert_many, &sums[i]), 0);
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    for (int i = 0; i < 2; i++)
        close_to(sums[i], 150 * 17.8816 + 150 * 2.4384);
}

/* A table of the usual units and the examples' own, written from udunits2, converts to the same bits and
 * words the same messages, a reciprocal unit's too ("'s/m' is a unit of 1/speed"); a unit it lacks is
 * unknown. */
static void test_table_same_bits(void **state) {
    cs_units *u = *state;
    char *text = NULL;
    cs_error err;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    assert_non_null(f);
    assert_int_equal(cs_units_write_table(u, cs_units_usual, cs_units_usual_count, 1, f),
                     cs_units_usual_count);
    const char *more[] = {"kPa/m", "in", "1000 lbf/ft^2", "no-such-unit"};
    assert_int_equal(cs_units_write_table(u, more, 4, 1, f), 3);
    fclose(f);
    cs_units *t = cs_units_from_table(text, &err);
    if (!t) fail_msg("%s", err.message);
    const struct {
        const char *text;
        cs_quantity q;
    } reads[] = {{"40 mph", CS_Q_SPEED},
                 {"8000 psf", CS_Q_PRESSURE},
                 {"52 kip", CS_Q_FORCE},
                 {"29000 ksi", CS_Q_PRESSURE},
                 {"15000 lb", CS_Q_MASS},
                 {"1.75in", CS_Q_LENGTH},
                 {"8 ft", CS_Q_LENGTH},
                 {"0.5 ms", CS_Q_TIME},
                 {"45 deg", CS_Q_ANGLE},
                 {"0.471 in2", CS_Q_AREA},
                 {"1.67 lb/ft", CS_Q_MASS_PER_LENGTH},
                 {"20 MN/m", CS_Q_STIFFNESS},
                 {"2.192 in4", CS_Q_SECOND_MOMENT},
                 {"1.287 in3", CS_Q_SECTION_MODULUS},
                 {"1 g", CS_Q_ACCELERATION},
                 {"177.3 kPa/m", CS_Q_PRESSURE_GRADIENT},
                 {"60 km/h", CS_Q_SPEED},
                 {"3 1000 lbf/ft^2", CS_Q_PRESSURE},
                 {"0.15", CS_Q_NUMBER},
                 {"40 kg", CS_Q_SPEED},
                 {"1 g", CS_Q_FORCE},
                 {"0.3 m", CS_Q_NUMBER},
                 {"fast", CS_Q_TIME},
                 {"1e400 m", CS_Q_LENGTH},
                 {"2 mph", CS_Q_ANGLE},
                 {"7 %", CS_Q_NUMBER},
                 {"2 s/m", CS_Q_SPEED},
                 {"2 h/km", CS_Q_SPEED},
                 {"0.5 ft-1", CS_Q_LENGTH},
                 {"0.5 1/ft", CS_Q_LENGTH},
                 {"2 in/kip", CS_Q_STIFFNESS},
                 {"3 1/psi", CS_Q_PRESSURE},
                 {"2 1/in2", CS_Q_AREA}};
    for (size_t i = 0; i < sizeof reads / sizeof reads[0]; i++) {
        double a = NAN, b = NAN;
        cs_error ea = {CS_OK, ""}, eb = {CS_OK, ""};
        cs_status ra = cs_units_read(u, reads[i].text, reads[i].q, &a, &ea);
        cs_status rb = cs_units_read(t, reads[i].text, reads[i].q, &b, &eb);
        if (ra != rb || (ra == CS_OK && memcmp(&a, &b, sizeof a) != 0) || strcmp(ea.message, eb.message) != 0)
            fail_msg("'%s': udunits2 %d %.17g '%s', table %d %.17g '%s'", reads[i].text, (int)ra, a,
                     ea.message, (int)rb, b, eb.message);
    }
    expect_error(t, "3 furlong", CS_Q_LENGTH, "unknown unit 'furlong'");
    cs_units_free(t);
    free(text);
    assert_null(cs_units_from_table("ft\t0.3048\n", &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "line 1"));
}

/* The usual units come from a table of the database's factors (built in); any other text reads the
 * database, when first met: a unit's other names there convert to the same bits as the table's. */
static void test_database_beyond_the_table(void **state) {
    (void)state;
    cs_error err;
    cs_units *u = cs_units_open(&err);
    if (!u) fail_msg("%s", err.message);
    const struct {
        const char *table, *database;
        cs_quantity q;
    } pairs[] = {{"8 ft", "8 foot", CS_Q_LENGTH},        {"1.75 in", "1.75 inch", CS_Q_LENGTH},
                 {"40 mph", "40 mile/hour", CS_Q_SPEED}, {"8000 psf", "8000 lbf/ft^2", CS_Q_PRESSURE},
                 {"15000 lb", "15000 pound", CS_Q_MASS}, {"20 MN/m", "20 meganewton/meter", CS_Q_STIFFNESS},
                 {"1 g", "1 gee", CS_Q_ACCELERATION}};
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        double a = read_ok(u, pairs[i].table, pairs[i].q), b = read_ok(u, pairs[i].database, pairs[i].q);
        if (memcmp(&a, &b, sizeof a) != 0)
            fail_msg("'%s' %.17g but '%s' %.17g", pairs[i].table, a, pairs[i].database, b);
    }
    close_to(read_ok(u, "3 furlong", CS_Q_LENGTH), 3 * 660 * 1200.0 / 3937); /* survey feet, as udunits2 */
    expect_error(u, "3 furlong", CS_Q_MASS, "'furlong' is a unit of length, not of mass");
    cs_units_free(u);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_factors),
        cmocka_unit_test(test_bare_numbers_are_pure),
        cmocka_unit_test(test_wrong_units),
        cmocka_unit_test(test_two_threads),
        cmocka_unit_test(test_table_same_bits),
        cmocka_unit_test(test_database_beyond_the_table),
        cmocka_unit_test(test_reciprocal_units_refused),
        cmocka_unit_test(test_number_in_unit_refused),
        cmocka_unit_test(test_products_of_units),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
