/* SPDX-License-Identifier: MIT */
/* The engine's fuzzer's findings kept (tests/fuzz-regressions/engine/): each input is decoded as
 * fuzz/fuzz_engine.c decodes it (tests/design.h) and run to its end. Each must keep the engine's contract
 * (an outcome, or the ledger's own error; every response finite) and end within a stated bound of work:
 * the solver's work counter (solver/work.h, in rows evaluated) at most the run's work budget plus what
 * one pass of the solver can add once it is spent (one Newton solve over every unknown the model can
 * have). The work is asserted, never the time (no timed test); ctest gives the test a timeout of 30 s in
 * a plain build (CMakeLists.txt), where it takes about 1.5 s of CPU.
 *
 * fallback-ced48187 (input `4d c9`): 1 rope of 1.09 in, 7 posts at 11.1 ft, 4 rails, a 5,958-lb vehicle at
 * 26.3 mph and 88 deg (stress design 19913): it runs to its time limit, 0.15 s, on 0.4% of its work budget
 * (301 solves, none through the fallback's sweeps). A run
 * whose work passes the budget ends did_not_converge with what it has (tests/test_crash.c,
 * a_spent_solve_budget_ends_the_run).
 *
 * fallback-2040a4aa (input `be 00`): 2 ropes of 1.72 in, 10 posts at 10.7 ft, 1 rail, a 9,034-lb vehicle
 * at 34.2 mph and 74 deg: it runs to its time limit
 * (0.15 s, 301 solves, none through the fallback, the ledger within 0.1%). */
#include "check.h"
#include "design.h"
#include "run/run.h"
#include "solver/work.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

#define DIR_ENGINE CS_SOURCE_DIR "/tests/fuzz-regressions/engine"

typedef struct replayed {
    cs_status status;
    char message[512];
    cs_summary sm;
    double work, budget, most; /* the work done, the budget, the budget plus one Newton solve's most */
} replayed;

static void replay(const char *path, double budget, replayed *out) {
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    uint8_t data[4096];
    size_t size = fread(data, 1, sizeof data, f);
    fclose(f);
    design d;
    design_source src = {0x5eed0000ULL, data, size, 0}; /* as fuzz/fuzz_engine.c */
    design_make(-1, &src, &d);
    design_add_slip(&src, &d);
    d.fx.scenario.solve_budget = budget * CS_SOLVE_BUDGET;
    cs_error err = {0};
    cs_model *m = cs_model_create(&d.fx.barrier, &d.fx.vehicle, &d.fx.scenario, &err);
    assert_non_null(m);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    out->status = cs_run(m, s, NULL, NULL, &err);
    snprintf(out->message, sizeof out->message, "%s", err.message);
    out->sm = (cs_summary){.size = sizeof out->sm};
    cs_state_summary(s, &out->sm, NULL);
    /* every unknown the model can have (solver/system.c, cs_system_init) */
    double unknowns = 3.0 * m->post_count + (double)m->cable_count * (m->max_nodes + CS_CORNERS) + 5.0;
    out->work = s->work->count.work, out->budget = m->work_budget;
    out->most = m->work_budget + CS_NEWTON_MOST_PASSES * unknowns;
    printf("%s: %s\n  %s at %.4f s, ledger %.2g, %d solver warnings; work %.4g of a budget of %.4g (%ld "
           "solves, %ld Newton "
           "passes, %ld sweeps)\n",
           strrchr(path, '/') + 1, d.what,
           out->status == CS_OK ? cs_outcome_name(out->sm.outcome) : out->message, out->sm.t_end_s,
           out->sm.energy_balance_error, out->sm.solver_warnings, out->work, out->budget,
           s->work->count.solves, s->work->count.newton, s->work->count.sweeps);
    cs_state_free(s);
    cs_model_free(m);
}

/* The engine's contract for a replayed input: an outcome (or the ledger's own error), every response
 * finite, the work within its bound. */
static void keeps_the_contract(const char *name, const replayed *r) {
    if (r->status != CS_OK && !(r->status == CS_ERR_UNSTABLE && strstr(r->message, "energy ledger")))
        fail_msg("%s: %s", name, r->message);
    if (r->status == CS_OK) assert_int_not_equal(r->sm.outcome, CS_RUNNING);
    const double v[] = {r->sm.max_50ms_decel_g, r->sm.max_dynamic_penetration_m,
                        r->sm.max_barrier_deflection_m, r->sm.energy_balance_error,
                        r->sm.max_cable_tension_n};
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        assert_true(isfinite(v[i]));
    if (!(r->work <= r->most)) fail_msg("%s: work %.6g past the bound %.6g", name, r->work, r->most);
}

static void every_input_ends_within_its_work(void **state) {
    (void)state;
    DIR *dir = opendir(DIR_ENGINE);
    assert_non_null(dir);
    int count = 0;
    for (struct dirent *e; (e = readdir(dir)) != NULL;) {
        if (e->d_name[0] == '.') continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", DIR_ENGINE, e->d_name);
        replayed r;
        replay(path, SANITIZED ? 0.1 : 1.0, &r);
        keeps_the_contract(e->d_name, &r);
        count++;
    }
    closedir(dir);
    assert_true(count >= 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(every_input_ends_within_its_work)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
