/* SPDX-License-Identifier: MIT */
/* Ratings: every penetration boundary (1, 6, 7, 15, 30 m) and speed window edge (a class's own
 * designations), the reference point each standard measures from (data/standards.md), the vehicle classes
 * and --class names, and a run's rating as run with each reason it is not rated, in the one wording. */
#include "check.h"
#include "study/rating.h"

#define MPH 0.44704

static cs_summary stopped_at(double front) {
    cs_summary s;
    memset(&s, 0, sizeof s);
    s.outcome = CS_STOPPED;
    s.max_dynamic_penetration_m = front;
    return s;
}

static void penetration_boundaries(void **state) {
    (void)state;
    struct {
        cs_standard std;
        double p;
        const char *level;
    } cases[] = {
        {CS_SD_STD_02_01, 1.00, "L3"}, {CS_SD_STD_02_01, 1.01, "L2"},  {CS_SD_STD_02_01, 6.00, "L2"},
        {CS_SD_STD_02_01, 6.01, "L1"}, {CS_SD_STD_02_01, 15.0, "L1"},  {CS_SD_STD_02_01, 15.01, NULL},
        {CS_SD_STD_02_01A, 1.00, "A"}, {CS_SD_STD_02_01A, 1.01, NULL}, {CS_ASTM_F2656, 1.00, "P1"},
        {CS_ASTM_F2656, 1.01, "P2"},   {CS_ASTM_F2656, 7.00, "P2"},    {CS_ASTM_F2656, 7.01, "P3"},
        {CS_ASTM_F2656, 30.0, "P3"},   {CS_ASTM_F2656, 30.01, "P4"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *got = cs_rating_level(cases[i].std, cases[i].p);
        if (cases[i].level == NULL)
            assert_null(got);
        else
            assert_string_equal(got, cases[i].level);
    }
}

static void speed_windows(void **state) {
    (void)state;
    cs_rating_rules r = cs_default_rating_rules();
    const double mph[] = {27.9, 28.0, 37.9, 38.0, 46.9, 47.0, 60.0};
    const int rating[] = {0, 30, 30, 40, 40, 50, 50};
    for (int i = 0; i < 7; i++)
        assert_int_equal(cs_rating_speed_for(&r, NULL, mph[i] * MPH), rating[i]);
}

static void reference_points(void **state) {
    (void)state;
    cs_rating_rules rules = cs_default_rating_rules();
    cs_vehicle_def truck = cs_default_vehicle_def();
    truck.front_to_cargo_bed = 2.6;
    cs_summary s = stopped_at(3.9); /* the truck's front stopped 3.9 m past the attack face */
    cs_rating sd = cs_rate_run(CS_SD_STD_02_01, "M", 40 * MPH, &s, &truck, &rules);
    CHECK_ABS(sd.penetration, 3.9, 1e-12); /* front from the attack face */
    assert_string_equal(sd.label, "K8/L2");
    cs_rating astm = cs_rate_run(CS_ASTM_F2656, "M", 40 * MPH, &s, &truck, &rules);
    CHECK_ABS(astm.penetration, 3.9 - 2.6 - rules.barrier_depth,
              1e-12); /* cargo bed from the protected face */
    assert_string_equal(astm.label, "M40/P2");
    cs_rating rev_a = cs_rate_run(CS_SD_STD_02_01A, "M", 50 * MPH, &s, &truck, &rules);
    assert_string_equal(rev_a.label, "none"); /* 1.2 m > 1 m */
    s.outcome = CS_BREAKTHROUGH;
    cs_rating through = cs_rate_run(CS_ASTM_F2656, "M", 50 * MPH, &s, &truck, &rules);
    assert_string_equal(through.label, "M50/P4");
    assert_string_equal(cs_rate_run(CS_SD_STD_02_01, "M", 50 * MPH, &s, &truck, &rules).label, "none");
    cs_standard st;
    assert_int_equal(cs_standard_parse("astm-f2656", &st), 0);
    assert_int_equal(st, CS_ASTM_F2656);
    assert_int_equal(cs_standard_parse("pas-68", &st), -1);
}

static void vehicle_classes_by_mass(void **state) {
    (void)state;
    assert_string_equal(cs_rating_vehicle_class(15000 * 0.45359237), "M"); /* the SD-STD truck */
    assert_string_equal(cs_rating_vehicle_class(2430 * 0.45359237), "C");
    assert_null(cs_rating_vehicle_class(4000.0)); /* between PU and M */
    assert_string_equal(cs_rating_vehicle_class(5070 * 0.45359237), "PU");
    assert_string_equal(cs_rating_vehicle_class(65000 * 0.45359237), "H");
    assert_null(cs_rating_vehicle_class(2000.0)); /* 13% under PU's 2,300 kg */
}

/* C and PU are rated at 40, 50 and 60 mph, M and H at 30, 40 and 50; a class's highest designation takes
 * every speed above it; --class names parse to a class and speed of a standard. */
static void class_speeds(void **state) {
    (void)state;
    cs_rating_rules r = cs_default_rating_rules();
    const double mph[] = {37.9, 38.0, 46.9, 47.0, 56.9, 57.0, 70.0};
    const int car[] = {0, 40, 40, 50, 50, 60, 60}, truck[] = {30, 40, 40, 50, 50, 50, 50};
    for (int i = 0; i < 7; i++) {
        assert_int_equal(cs_rating_speed_for(&r, "PU", mph[i] * MPH), car[i]);
        assert_int_equal(cs_rating_speed_for(&r, "C", mph[i] * MPH), car[i]);
        assert_int_equal(cs_rating_speed_for(&r, "H", mph[i] * MPH), truck[i]);
    }
    char cls[8];
    int v;
    assert_int_equal(cs_rating_class_parse(CS_ASTM_F2656, "PU50", cls, sizeof cls, &v), 0);
    assert_string_equal(cls, "PU"), assert_int_equal(v, 50);
    assert_int_equal(cs_rating_class_parse(CS_ASTM_F2656, "C60", cls, sizeof cls, &v), 0);
    assert_int_equal(cs_rating_class_parse(CS_SD_STD_02_01, "K8", cls, sizeof cls, &v), 0);
    assert_string_equal(cls, "M"), assert_int_equal(v, 40);
    assert_int_equal(cs_rating_class_parse(CS_ASTM_F2656, "PU30", cls, sizeof cls, &v), -1);
    assert_int_equal(cs_rating_class_parse(CS_ASTM_F2656, "K8", cls, sizeof cls, &v), -1);
    assert_int_equal(cs_rating_class_parse(CS_SD_STD_02_01, "M40", cls, sizeof cls, &v), -1);
    assert_true(cs_standard_tests_class(CS_ASTM_F2656, "PU") &&
                !cs_standard_tests_class(CS_SD_STD_02_01, "PU"));
}

/* A run as run: its vehicle's class by mass, head-on within 1 deg, a finished test; each reason it is not
 * rated said in the one wording. */
static void rated_as_run(void **state) {
    (void)state;
    cs_rating_rules rules = cs_default_rating_rules();
    cs_vehicle_def pu = cs_default_vehicle_def();
    pu.mass = 2300.0, pu.front_to_cargo_bed = 2.9;
    const double head_on = 0.5 * 3.14159265358979323846, deg = head_on / 90;
    cs_summary s = stopped_at(3.9);
    char text[256];
    cs_rating r = cs_rate_as_run(CS_ASTM_F2656, NULL, &pu, 50 * MPH, head_on + 0.99 * deg, &s, &rules);
    assert_string_equal(r.vehicle_class, "PU");
    assert_string_equal(r.label, "PU50/P2"); /* the front, 3.9 m less the 0.1-m barrier */
    CHECK_ABS(r.penetration, 3.8, 1e-12);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(text,
                        "ASTM F2656 PU50/P2 (penetration 3.80 m (12.5 ft), vehicle front, from the barrier's "
                        "protected-side face)");
    r = cs_rate_as_run(CS_ASTM_F2656, NULL, &pu, 50 * MPH, head_on - 1.01 * deg, &s, &rules);
    assert_false(r.rated || r.tested);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(text,
                        "ASTM F2656 not rated (the impact is at 89.0 deg; its test is head-on, at 90 deg)");
    r = cs_rate_as_run(CS_SD_STD_02_01, NULL, &pu, 50 * MPH, head_on, &s, &rules);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(
        text, "SD-STD-02.01 not rated (the vehicle, 2300 kg, is not its 15,000-lb truck, within 5%)");
    pu.mass = 2000.0; /* NCHRP 350's pickup: 13% off */
    r = cs_rate_as_run(CS_ASTM_F2656, NULL, &pu, 50 * MPH, head_on, &s, &rules);
    assert_string_equal(r.label, "not rated");
    r = cs_rate_as_run(CS_ASTM_F2656, "PU", &pu, 50 * MPH, head_on, &s, &rules); /* a sweep's class */
    assert_string_equal(r.label, "PU50/P2");
    s.outcome = CS_TIME_LIMIT;
    r = cs_rate_run(CS_ASTM_F2656, "PU", 50 * MPH, &s, &pu, &rules);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(
        text, "ASTM F2656 not rated (the run ended at its time limit with the vehicle still moving)");
    s.outcome = CS_UNDERRIDE;
    r = cs_rate_run(CS_ASTM_F2656, "C", 60 * MPH, &s, &pu, &rules);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(text, "ASTM F2656 C60/P4 (the vehicle got through)");
    s.outcome = CS_STOPPED;
    r = cs_rate_run(CS_ASTM_F2656, "C", 35 * MPH, &s, &pu, &rules);
    cs_rating_text(&r, text, sizeof text);
    assert_string_equal(text,
                        "ASTM F2656 none (35.0 mph is below the lowest speed of its C vehicle, 40 mph)");
}

/* The roadside tests of a level, or one by name, with their vehicles, speeds and angles; a redirected
 * run's exit angle against 60% of the impact angle. */
static void roadside_test_conditions(void **state) {
    (void)state;
    cs_roadside_test t[3];
    assert_int_equal(cs_roadside_tests("mash", 3, NULL, t), 2);
    assert_string_equal(t[0].name, "3-10"), assert_string_equal(t[0].vehicle, "1100C");
    assert_string_equal(t[1].name, "3-11"), assert_string_equal(t[1].vehicle, "2270P");
    CHECK_REL(t[1].speed, 100.0 / 3.6, 1e-12);
    CHECK_REL(t[1].angle, 25.0 * 3.14159265358979323846 / 180.0, 1e-12);
    assert_int_equal(cs_roadside_tests("nchrp-350", 4, NULL, t), 3);
    assert_string_equal(t[2].name, "4-12"), assert_string_equal(t[2].vehicle, "8000S");
    CHECK_REL(t[2].speed, 80.0 / 3.6, 1e-12);
    assert_int_equal(cs_roadside_tests("nchrp-350", 0, "3-10", t), 1);
    assert_string_equal(t[0].vehicle, "820C");
    assert_int_equal(cs_roadside_tests("en-1317", 3, NULL, t), 0);
    cs_roadside_tests("nchrp-350", 0, "3-11", t);
    cs_summary s = {0};
    s.outcome = CS_REDIRECTED, s.exit_speed_mps = 18.0, s.max_barrier_deflection_m = 2.5,
    s.working_width_m = 2.6;
    s.exit_angle_deg = 0.59 * t[0].angle * 180 / 3.14159265358979323846;
    cs_roadside_result r = cs_roadside_read(&t[0], &s);
    assert_true(r.contained && r.redirected && r.exit_angle_within);
    s.exit_angle_deg = 0.61 * t[0].angle * 180 / 3.14159265358979323846;
    assert_false(cs_roadside_read(&t[0], &s).exit_angle_within);
    s.exit_angle_deg = 0.6 * t[0].angle / (3.14159265358979323846 / 180.0); /* at 60%: not less than it */
    assert_false(cs_roadside_read(&t[0], &s).exit_angle_within);
    s.outcome = CS_BREAKTHROUGH;
    r = cs_roadside_read(&t[0], &s);
    assert_false(r.contained || r.redirected);
    CHECK_REL(r.exit_speed_mps, 18.0, 1e-12);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(penetration_boundaries),
                                       cmocka_unit_test(speed_windows),
                                       cmocka_unit_test(reference_points),
                                       cmocka_unit_test(vehicle_classes_by_mass),
                                       cmocka_unit_test(class_speeds),
                                       cmocka_unit_test(rated_as_run),
                                       cmocka_unit_test(roadside_test_conditions)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
