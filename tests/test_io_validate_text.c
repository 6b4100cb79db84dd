/* SPDX-License-Identifier: MIT */
/* validate's penetration in words reads as summary.json's: a number where the vehicle stopped short of it
 * (or was redirected), "beyond" it where the run ended with the vehicle through the barrier or still going
 * (its time limit, its solve budget), where summary.json has max_dynamic_penetration_m null and
 * penetration_beyond_m that number. */
#include "check.h"
#include "study/validate.h"

static const char *text(cs_outcome outcome, double pen, char *buf, size_t n) {
    cs_summary m = {.size = sizeof m};
    m.outcome = outcome, m.max_dynamic_penetration_m = pen;
    return cs_validate_penetration_text(&m, buf, n);
}

static void penetration_beyond_where_summary_json_has_it(void **state) {
    (void)state;
    char buf[64];
    assert_string_equal(text(CS_STOPPED, 4.2238, buf, sizeof buf), "4.22 m");
    assert_string_equal(text(CS_REDIRECTED, 2.5232, buf, sizeof buf), "2.52 m");
    assert_string_equal(text(CS_BREAKTHROUGH, 1.4512, buf, sizeof buf), "beyond 1.45 m");
    assert_string_equal(text(CS_OVERRIDE, 1.4512, buf, sizeof buf), "beyond 1.45 m");
    assert_string_equal(text(CS_TIME_LIMIT, 3.004, buf, sizeof buf), "beyond 3.00 m");
    assert_string_equal(text(CS_DID_NOT_CONVERGE, 3.004, buf, sizeof buf), "beyond 3.00 m");
    for (int o = CS_RUNNING; o <= CS_STEP_LIMIT;
         o++) /* "beyond" exactly where the penetration is not final */
        assert_int_equal(strncmp(text((cs_outcome)o, 1.0, buf, sizeof buf), "beyond ", 7) == 0,
                         !cs_penetration_is_final((cs_outcome)o));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(penetration_beyond_where_summary_json_has_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
