/* SPDX-License-Identifier: MIT */
/* cs_g10 writes the bytes snprintf's "%.10g" writes, for every kind of double: signed zeros, the
 * boundaries of styles f and e (1e-5, 1e10), exact ties at the tenth digit (to even), the halfway points
 * between 10-digit decimals and the doubles either side of them at exponents -25 to 45, rounding up to
 * the next power of ten, integers, subnormals, the largest and smallest doubles, infinities, NaN, and
 * some millions of pseudo-random values over every exponent. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "out/numtext.h"

static uint64_t rng = 0x9e3779b97f4a7c15u;

static uint64_t next(void) { /* xorshift64: the same sequence on every run */
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static long checked;

static void same(double v) {
    char want[64], got[CS_G10_SIZE + 8];
    int n = snprintf(want, sizeof want, "%.10g", v);
    memset(got, 'x', sizeof got);
    int len = cs_g10(v, got);
    if (len != n || strcmp(got, want) != 0)
        fail_msg("%a: cs_g10 gives \"%s\" (%d), snprintf \"%s\" (%d)", v, got, len, want, n);
    checked++;
    if (!isnan(v)) { /* and the negative */
        n = snprintf(want, sizeof want, "%.10g", -v);
        len = cs_g10(-v, got);
        if (len != n || strcmp(got, want) != 0)
            fail_msg("%a: cs_g10 gives \"%s\" (%d), snprintf \"%s\" (%d)", -v, got, len, want, n);
        checked++;
    }
}

static void known_texts(void **state) {
    (void)state;
    static const struct {
        double v;
        const char *text;
    } cases[] = {
        {0.0, "0"},
        {-0.0, "-0"},
        {1.0, "1"},
        {-2.5, "-2.5"},
        {0.1, "0.1"},
        {1e-4, "0.0001"},
        {1e-5, "1e-05"},
        {123456.789, "123456.789"},
        {9999999999.0, "9999999999"},
        {1e10, "1e+10"},
        {9999999999.5, "1e+10"},      /* an exact tie: to even, up */
        {9999999998.5, "9999999998"}, /* an exact tie: to even, down */
        {1234567890.5, "1234567890"},
        {1234567891.5, "1234567892"},
        {0.30000000000000004, "0.3"},
        {2.0 / 3.0, "0.6666666667"},
        {1e100, "1e+100"},
        {-1.5e-300, "-1.5e-300"},
        {DBL_MAX, "1.797693135e+308"},
        {5e-324, "4.940656458e-324"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char got[CS_G10_SIZE];
        cs_g10(cases[i].v, got);
        assert_string_equal(got, cases[i].text);
        same(cases[i].v);
    }
    same(INFINITY);
    same(NAN);
    same(DBL_MIN);
    same(DBL_TRUE_MIN);
    same(nextafter(DBL_MIN, 0.0));
}

/* The halfway point between two 10-digit decimals at each exponent, the doubles either side, and the
 * decimals themselves, with 9.999999999|5 (rounding up to the next power of ten) among them. */
static void rounding_edges(void **state) {
    (void)state;
    for (int x = -25; x <= 45; x++) {
        for (int i = 0; i < 2000; i++) {
            uint64_t d = i == 0 ? 9999999999u : i == 1 ? 1000000000u : 1000000000u + next() % 9000000000u;
            char text[64];
            snprintf(text, sizeof text, "%llu5e%d", (unsigned long long)d, x - 10);
            double half = strtod(text, NULL);
            same(half);
            same(nextafter(half, 0.0));
            same(nextafter(half, INFINITY));
            snprintf(text, sizeof text, "%llue%d", (unsigned long long)d, x - 9);
            same(strtod(text, NULL));
        }
    }
    for (uint64_t d = 1000000000u; d < 1000000000u + 20000u; d++) { /* ties at 11 digits: exact integers */
        same((double)d + 0.5);
        same((double)(d * 10 + 5));
    }
}

static void pseudo_random_values(void **state) {
    (void)state;
    for (int i = 0; i < 500000; i++) { /* every exponent, subnormals, infinities and NaN among them */
        uint64_t bits = next();
        double v;
        memcpy(&v, &bits, sizeof v);
        same(v);
    }
    for (int i = 0; i < 500000; i++) { /* 1e-20 to 1e40, evenly by exponent: the common range */
        double v = pow(10.0, -20.0 + 60.0 * (double)(next() >> 11) / 9007199254740992.0);
        same(v);
    }
    for (int i = 0; i < 200000; i++) { /* integers up to 2^53, and short decimals */
        same((double)(next() >> (11 + next() % 53)));
        same((double)(next() % 100000) / 1000.0);
    }
    assert_true(checked > 3000000);
}

/* A run's times to the decimals that show them exactly: a sum of 0.5-ms steps, with its round-off, keeps
 * its last 5 (0.5345), a whole millisecond keeps 3 decimals (0.050), a 0.05-ms step shows 5. */
static void times_shown_exactly(void **state) {
    (void)state;
    char buf[CS_TIME_TEXT_SIZE];
    double t = 0.0;
    for (int k = 0; k < 1069; k++)
        t += 0.0005;
    assert_string_equal(cs_time_text(t, buf), "0.5345");
    assert_string_equal(cs_time_text(0.437, buf), "0.437");
    assert_string_equal(cs_time_text(0.05, buf), "0.050");
    assert_string_equal(cs_time_text(0.43705, buf), "0.43705");
    assert_string_equal(cs_time_text(0.0, buf), "0.000");
    assert_string_equal(cs_time_text(1.0 / 3.0, buf), "0.333333");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(known_texts),
        cmocka_unit_test(rounding_edges),
        cmocka_unit_test(pseudo_random_values),
        cmocka_unit_test(times_shown_exactly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
