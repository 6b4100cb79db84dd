/* SPDX-License-Identifier: MIT */
/* The interface's rating (cablesim/rating.h) of examples/aps3.yaml, its truck head-on at 40 mph, is the one
 * `cablesim rate --standard astm-f2656 --class M40` prints: the same wording, and the same penetration to
 * the command's 0.01 m. A rating struct of an earlier, smaller size is filled to that size only. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "cablesim/cablesim.h"

static void rating_is_the_commands(void **state) {
    (void)state;
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    if (!l) fail_msg("%s", err.message);
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    if (cs_loader_load(l, CS_SOURCE_DIR "/examples/aps3.yaml", &in) != CS_OK ||
        !(m = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fail();
    }
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    cs_rating_result r = {.size = sizeof r};
    assert_int_equal(cs_rate(m, s, CS_ASTM_F2656, NULL, &r, &err), CS_ERR_INVALID); /* not run yet */
    assert_int_equal(cs_run(m, s, NULL, NULL, &err), CS_OK);
    cs_standard std;
    assert_int_equal(cs_standard_from_name("astm-f2656", &std), CS_OK);
    assert_int_equal(cs_standard_from_name("astm", &std), CS_ERR_INVALID);
    assert_int_equal(cs_rate(m, s, std, NULL, &r, &err), CS_OK);
    assert_string_equal(r.vehicle_class, "M");
    assert_int_equal(r.speed_mph, 40);

    FILE *p = popen(CS_BINARY_DIR "/cablesim rate " CS_SOURCE_DIR
                                  "/examples/aps3.yaml --standard astm-f2656 --class M40 2>&1",
                    "r");
    assert_non_null(p);
    char line[512], text[512] = "";
    double pen = NAN;
    while (fgets(line, sizeof line, p)) {
        const char *at = strstr(line, "penetration ");
        if (strncmp(line, "rating: ", 8) == 0)
            snprintf(text, sizeof text, "%.*s", (int)strcspn(line + 8, "\n"), line + 8);
        if (at && strstr(line, "M ") && sscanf(at, "penetration %lf m", &pen) != 1) pen = HUGE_VAL;
    }
    assert_int_equal(pclose(p), 0);
    assert_string_equal(r.text, text);
    if (r.through)
        assert_true(isinf(pen));
    else
        assert_float_equal(r.penetration_m, pen, 0.005 + 1e-9); /* the command prints %.2f m */

    /* an earlier struct: the fields up to the note, no text */
    char earlier[offsetof(cs_rating_result, text) + 8];
    memset(earlier, 0x5a, sizeof earlier);
    size_t n = offsetof(cs_rating_result, text);
    memcpy(earlier, &n, sizeof n);
    const cs_rating_result *e = (const cs_rating_result *)(const void *)earlier;
    assert_int_equal(cs_rate(m, s, std, NULL, (cs_rating_result *)(void *)earlier, &err), CS_OK);
    assert_int_equal(e->size, n);
    assert_string_equal(e->label, r.label);
    assert_string_equal(e->note, r.note);
    assert_true(memcmp(&e->penetration_m, &r.penetration_m, sizeof r.penetration_m) == 0);
    for (size_t k = n; k < sizeof earlier; k++)
        assert_int_equal((unsigned char)earlier[k], 0x5a);
    r.size = 0;
    assert_int_equal(cs_rate(m, s, std, NULL, &r, &err), CS_ERR_INVALID);
    cs_state_free(s);
    cs_model_free(m);
    cs_loader_free(l);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(rating_is_the_commands)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
