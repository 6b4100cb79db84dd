/* SPDX-License-Identifier: MIT */
/* A sweep's table of runs from fabricated results (a run that stopped, one that broke through, one that
 * failed, over a numeric and a text input): runs.csv to the byte, runs.nc read back through the netCDF C
 * API (every value exact, units, fill values where a run has none, the same bytes twice), and the plots
 * of `plot:` (files, captions, what they draw, a y refused). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>
#include <cmocka.h>
#include <netcdf.h>
#include <unistd.h>

#include "out/plot.h"
#include "out/sweepout.h"
#include "study/sweep.h"

enum { RUNS = 3 };

typedef struct fixture {
    cs_sweep_spec *spec;
    double *x;
    cs_sweep_result r[RUNS];
} fixture;

/* tests/sweep/grid.yaml's first three runs (pretension 4, 4, 5 kip; SD-STD-02.01, PU, SD-STD-02.01) with
 * results made up to the last digit; run 2 failed, and its summary's numbers must not show. */
static int setup(void **state) {
    fixture *f = calloc(1, sizeof *f);
    cs_units *u = cs_units_open(NULL);
    if (!f || !u) return -1;
    f->spec = cs_sweep_spec_read("tests/sweep/grid.yaml", u);
    cs_units_free(u);
    long n;
    if (!f->spec || f->spec->error_count || !(f->x = cs_sweep_samples(f->spec, &n))) return -1;
    cs_sweep_result *r = f->r;
    r[0].summary = (cs_summary){.outcome = CS_STOPPED,
                                .t_end_s = 0.5,
                                .max_50ms_decel_g = 3.25,
                                .t_max_50ms_decel_s = 0.125,
                                .max_dynamic_penetration_m = 1.2345678901234567,
                                .max_barrier_deflection_m = 2.25,
                                .working_width_m = 2.625,
                                .stop_time_s = 0.4375,
                                .exit_speed_mps = 7,
                                .first_contact_time_s = 0.003,
                                .posts_failed_left = 2,
                                .posts_failed_right = 3,
                                .initial_kinetic_energy_j = 1087776.7091234,
                                .energy_balance_error = -4.2595107761234e-05,
                                .max_cable_tension_n = 38621.246851234,
                                .final_position_m = {20.5, -3.25, 1},
                                .solver_warnings = 1,
                                .max_solver_residual = 0.0023941431861234};
    r[0].event_counts[CS_EVENT_POST_HINGE] = 2;
    snprintf(r[0].rating, sizeof r[0].rating, "M40/P2");
    r[0].astm_penetration = 1.5078125;
    snprintf(r[0].sd_std_rating, sizeof r[0].sd_std_rating, "K8/L2");
    /* run 1 as run 0 but broken through, before any contact was recorded */
    cs_summary *b = &r[1].summary;
    *b = r[0].summary;
    b->outcome = CS_BREAKTHROUGH, b->exit_speed_mps = 13.75, b->first_contact_time_s = -1;
    b->exit_angle_deg = 22.5, b->working_width_m = 5.5;
    b->max_50ms_decel_g = 2.875, b->max_dynamic_penetration_m = 4.03125, b->max_cable_tension_n = 1.5e6;
    b->energy_balance_error = 0, b->posts_failed_left = 0, b->cables_broken = 2;
    r[1].event_counts[CS_EVENT_CABLE_BREAK] = 2;
    r[1].event_counts[CS_EVENT_UNDERRIDE] = 1;
    snprintf(r[1].rating, sizeof r[1].rating, "PU40/P4");
    r[1].astm_penetration = NAN; /* through: P4 rests on no penetration */
    snprintf(r[1].sd_std_rating, sizeof r[1].sd_std_rating, "not rated");
    r[2].status = CS_RUN_FAILED;
    r[2].summary = r[0].summary;
    r[2].event_counts[CS_EVENT_CABLE_BREAK] = 5;
    snprintf(r[2].rating, sizeof r[2].rating, "none");
    r[2].astm_penetration = 0.75;
    snprintf(r[2].sd_std_rating, sizeof r[2].sd_std_rating, "K8/L3");
    snprintf(r[2].error, sizeof r[2].error, "the solve \"diverged\", at 0.1 s");
    *state = f;
    return 0;
}

static int teardown(void **state) {
    fixture *f = *state;
    free(f->x);
    cs_sweep_spec_free(f->spec);
    free(f);
    return 0;
}

static void test_runs_csv(void **state) {
    fixture *f = *state;
    char *text = NULL;
    size_t size = 0;
    cs_error err;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    assert_int_equal(cs_sweep_write_runs(out, f->spec, f->x, f->r, RUNS, &err), CS_OK);
    fclose(out);
    const char *want =
        "run,barrier.cables[0].pretension [N],vehicle,outcome,astm_f2656_as_run,astm_f2656_penetration "
        "[m],sd_std_02_01_as_run,time_reached [s],max_50ms_decel [g],"
        "t_max_50ms_decel [s],max_dynamic_penetration [m],penetration_beyond [m],max_barrier_deflection [m],"
        "working_width [m],"
        "stop_time [s],exit_speed [m/s],exit_angle [deg],first_contact_time "
        "[s],posts_failed_left,posts_failed_right,cables_broken,"
        "max_cable_tension [N],initial_kinetic_energy [J],energy_balance_error [1],solver_warnings,"
        "max_solver_residual [1],final_x [m],final_y [m],final_z [m],events_cable_break,"
        "events_termination_break,events_post_hinge,events_post_rotation_limit,events_post_shear,"
        "events_post_pullout,events_footing_rotation,events_anchor_pullout,events_anchor_yield,events_"
        "override,"
        "events_underride,events_cable_release,events_termination_slip,events_post_withdrawal,events_post_"
        "down,events_cable_pulled_off,events_termination_at_post,events_anchor_withdrawal,events_cable_"
        "struck_off,error\n"
        "0,17792.886461,SD-STD-02.01,stopped,M40/P2,1.5078125,K8/"
        "L2,0.5,3.25,0.125,1.23456789,,2.25,2.625,0.4375,,,0.003,2,3,0,"
        "38621.24685,1087776.709,-4.259510776e-05,1,0.002394143186,20.5,-3.25,1,0,0,2,0,0,0,0,0,0,0,0,0,0,0,"
        "0,0,0,0,0,"
        "\n"
        "1,17792.886461,PU,breakthrough,PU40/P4,,not "
        "rated,0.5,2.875,0.125,,4.03125,2.25,5.5,,13.75,22.5,,0,3,2,1500000,"
        "1087776.709,0,1,0.002394143186,20.5,-3.25,1,2,0,0,0,0,0,0,0,0,0,1,0,0,0,0,0,0,0,0,\n"
        "2,22241.1080763,SD-STD-02.01,failed,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,\"the solve "
        "\"\"diverged\"\", "
        "at "
        "0.1 s\"\n";
    assert_string_equal(text, want);
    free(text);
}

/* runs.csv read back (sweep --resume) from text: the rows read, or -1 with err filled. */
static long read_back(const fixture *f, const char *text, cs_sweep_result *r, cs_error *err) {
    FILE *in = fmemopen((void *)text, strlen(text), "r");
    assert_non_null(in);
    for (int i = 0; i < RUNS; i++)
        memset(&r[i], 0, sizeof r[i]), r[i].pending = 1;
    long got = cs_sweep_read_runs(in, "runs.csv", f->spec, f->x, r, RUNS, 0, err);
    fclose(in);
    return got;
}

/* A failed run's error with a line break in it is a quoted cell over two lines: read back whole, and the
 * places of the rows after it are their lines in the file (they were counted as rows, one line too few
 * each); a row the CSV reader cannot read is its own message at its place (it was "not a row of this
 * study"). */
static void test_runs_csv_read_back(void **state) {
    fixture *f = *state;
    snprintf(f->r[2].error, sizeof f->r[2].error, "the solve failed\nat 0.1 s, \"diverged\"");
    char *text = NULL;
    size_t size = 0;
    cs_error err;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    assert_int_equal(cs_sweep_write_runs(out, f->spec, f->x, f->r, RUNS, &err), CS_OK);
    fclose(out);
    assert_non_null(strstr(text, "\"the solve failed\nat 0.1 s, \"\"diverged\"\"\"\n")); /* lines 4-5 */
    cs_sweep_result back[RUNS];
    assert_int_equal(read_back(f, text, back, &err), RUNS);
    assert_string_equal(back[2].error, f->r[2].error);
    assert_int_equal(back[2].status, CS_RUN_FAILED);
    assert_int_equal(back[1].summary.outcome, CS_BREAKTHROUGH);
    /* the designations as run and the ASTM penetration, back as written; none where a run has none */
    assert_string_equal(back[0].rating, "M40/P2");
    assert_true(back[0].astm_penetration == 1.5078125 && isnan(back[1].astm_penetration));
    assert_true(isnan(back[2].astm_penetration));
    assert_string_equal(back[0].sd_std_rating, "K8/L2");
    assert_string_equal(back[1].sd_std_rating, "not rated");
    assert_string_equal(back[2].sd_std_rating, "");

    /* the runs' rows, then a bad one on line 6 (after the two lines of run 2's error) */
    size_t n = strlen(text);
    char *bad = malloc(2 * n + 64);
    assert_non_null(bad);
    snprintf(bad, 2 * n + 64, "%s2,x\n", text);
    assert_int_equal(read_back(f, bad, back, &err), -1);
    assert_string_equal(err.message, "runs.csv:6: not a row of this study (its fields)");
    /* run 2's row given twice, the second on line 6 */
    const char *row2 = strstr(text, "\n2,") + 1;
    snprintf(bad, 2 * n + 64, "%s%s", text, row2);
    assert_int_equal(read_back(f, bad, back, &err), -1);
    assert_string_equal(err.message, "runs.csv:6: not the next run of this study");
    /* a quote not closed on line 6, column 3: the reader's own message, at its place */
    snprintf(bad, 2 * n + 64, "%s2,\"open\n", text);
    assert_int_equal(read_back(f, bad, back, &err), -1);
    assert_string_equal(err.message,
                        "runs.csv:6:3: a quoted cell not closed (expected a closing \" before the end of "
                        "the file)");
    /* a runs.csv of a cablesim before the two columns: refused, naming them, not misread */
    const char *pen = strstr(text, ",astm_f2656_penetration [m],sd_std_02_01_as_run,");
    snprintf(bad, 2 * n + 64, "%.*s%s", (int)(pen - text), text,
             pen + strlen(",astm_f2656_penetration [m],sd_std_02_01_as_run"));
    assert_int_equal(read_back(f, bad, back, &err), -1);
    assert_string_equal(err.message, "runs.csv:1: written by an older cablesim, without the columns "
                                     "astm_f2656_penetration [m], sd_std_02_01_as_run: run the study again "
                                     "without --resume");
    /* another study's header, with every column: not this study's */
    snprintf(bad, 2 * n + 64, "run,x [m]%s", strstr(text, ",outcome,"));
    assert_int_equal(read_back(f, bad, back, &err), -1);
    assert_string_equal(err.message,
                        "runs.csv:1: not the header this study writes (another study's runs.csv?)");
    free(bad);
    free(text);
    snprintf(f->r[2].error, sizeof f->r[2].error, "the solve \"diverged\", at 0.1 s"); /* as setup made it */
}

/* A text attribute of a variable (NC_GLOBAL: of the file). */
static const char *att(int id, int varid, const char *name) {
    static char text[512];
    size_t len = 0;
    assert_int_equal(nc_inq_attlen(id, varid, name, &len), NC_NOERR);
    assert_true(len < sizeof text);
    assert_int_equal(nc_get_att_text(id, varid, name, text), NC_NOERR);
    text[len] = '\0';
    return text;
}

/* A whole file's bytes. */
static char *slurp(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    *size = (size_t)ftell(f);
    rewind(f);
    char *data = malloc(*size + 1);
    assert_non_null(data);
    assert_int_equal(fread(data, 1, *size, f), *size);
    fclose(f);
    return data;
}

static int var(int id, const char *name) {
    int varid = -1;
    assert_int_equal(nc_inq_varid(id, name, &varid), NC_NOERR);
    return varid;
}

/* A double variable's three values, as stored. */
static void doubles(int id, const char *name, double *v) {
    assert_int_equal(nc_get_var_double(id, var(id, name), v), NC_NOERR);
}

/* Run i's text in a char variable of width chars (NUL-padded). */
static void assert_text(int id, const char *name, size_t width, const char *const want[RUNS]) {
    char got[RUNS][64] = {{0}};
    int varid = var(id, name), dims[2];
    size_t len;
    assert_int_equal(nc_inq_vardimid(id, varid, dims), NC_NOERR);
    assert_int_equal(nc_inq_dimlen(id, dims[1], &len), NC_NOERR);
    assert_int_equal(len, width);
    for (size_t i = 0; i < RUNS; i++)
        assert_int_equal(nc_get_vara_text(id, varid, (size_t[]){i, 0}, (size_t[]){1, width}, got[i]),
                         NC_NOERR);
    for (int i = 0; i < RUNS; i++)
        assert_string_equal(got[i], want[i]);
}

static void test_runs_netcdf(void **state) {
    fixture *f = *state;
    char dir[] = "/tmp/cs-runs-nc-XXXXXX", path[64], again[64];
    cs_error err;
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/runs.nc", dir);
    snprintf(again, sizeof again, "%s/again.nc", dir);
    assert_int_equal(cs_sweep_write_netcdf(path, f->spec, f->x, f->r, RUNS, &err), CS_OK);
    int id, format, dim;
    size_t len;
    assert_int_equal(nc_open(path, NC_NOWRITE, &id), NC_NOERR);
    assert_int_equal(nc_inq_format(id, &format), NC_NOERR);
    assert_int_equal(format, NC_FORMAT_64BIT_OFFSET);
    assert_int_equal(nc_inq_dimid(id, "run", &dim), NC_NOERR);
    assert_int_equal(nc_inq_dimlen(id, dim, &len), NC_NOERR);
    assert_int_equal(len, RUNS);
    /* the file's attributes */
    assert_string_equal(att(id, NC_GLOBAL, "Conventions"), "CF-1.8");
    assert_string_equal(att(id, NC_GLOBAL, "source"), "cablesim " CS_VERSION_STRING);
    assert_string_equal(att(id, NC_GLOBAL, "spec"), "tests/sweep/grid.yaml");
    assert_string_equal(att(id, NC_GLOBAL, "method"), "grid");
    assert_string_equal(att(id, NC_GLOBAL, "seed"), "1");
    assert_string_equal(att(id, NC_GLOBAL, "title"),
                        "cablesim sweep tests/sweep/grid.yaml: one record per run");
    int runs = 0, index[RUNS];
    assert_int_equal(nc_get_att_int(id, NC_GLOBAL, "runs", &runs), NC_NOERR);
    assert_int_equal(runs, RUNS);
    assert_int_equal(nc_get_var_int(id, var(id, "run"), index), NC_NOERR);
    assert_true(index[0] == 0 && index[1] == 1 && index[2] == 2);
    /* the inputs: 4, 4 and 5 kip in N as runs.csv writes them (%.12g), the vehicles' names */
    double v[RUNS];
    doubles(id, "barrier_cables_0_pretension", v);
    assert_true(v[0] == 17792.886461 && v[1] == 17792.886461 && v[2] == 22241.1080763);
    assert_string_equal(att(id, var(id, "barrier_cables_0_pretension"), "long_name"),
                        "barrier.cables[0].pretension");
    assert_string_equal(att(id, var(id, "barrier_cables_0_pretension"), "units"), "N");
    assert_text(id, "vehicle", 12, (const char *const[]){"SD-STD-02.01", "PU", "SD-STD-02.01"});
    /* text results; the failed run's rating is empty, its error whole */
    assert_text(id, "outcome", 12, (const char *const[]){"stopped", "breakthrough", "failed"});
    assert_text(id, "astm_f2656_as_run", 7, (const char *const[]){"M40/P2", "PU40/P4", ""});
    assert_text(id, "sd_std_02_01_as_run", 9, (const char *const[]){"K8/L2", "not rated", ""});
    assert_text(id, "error", 30, (const char *const[]){"", "", "the solve \"diverged\", at 0.1 s"});
    /* numbers in full (runs.csv rounds to 10 digits), and the fill value where a run has none */
    double fill;
    assert_int_equal(nc_get_att_double(id, var(id, "max_dynamic_penetration"), "_FillValue", &fill),
                     NC_NOERR);
    assert_true(fill == NC_FILL_DOUBLE);
    /* the run that broke through has no penetration, only how far it got */
    doubles(id, "max_dynamic_penetration", v);
    assert_true(v[0] == 1.2345678901234567 && v[1] == NC_FILL_DOUBLE && v[2] == NC_FILL_DOUBLE);
    doubles(id, "penetration_beyond", v);
    assert_true(v[0] == NC_FILL_DOUBLE && v[1] == 4.03125 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "max_dynamic_penetration"), "units"), "m");
    assert_string_equal(att(id, var(id, "max_dynamic_penetration"), "long_name"),
                        "max dynamic penetration past the attack face (a vehicle the barrier held)");
    doubles(id, "astm_f2656_penetration", v); /* a P4 through the barrier rests on none */
    assert_true(v[0] == 1.5078125 && v[1] == NC_FILL_DOUBLE && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "astm_f2656_penetration"), "units"), "m");
    doubles(id, "energy_balance_error", v);
    assert_true(v[0] == -4.2595107761234e-05 && v[1] == 0 && v[2] == NC_FILL_DOUBLE);
    doubles(id, "stop_time", v);
    assert_true(v[0] == 0.4375 && v[1] == NC_FILL_DOUBLE && v[2] == NC_FILL_DOUBLE);
    doubles(id, "exit_speed", v);
    assert_true(v[0] == NC_FILL_DOUBLE && v[1] == 13.75 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "exit_speed"), "units"), "m/s");
    doubles(id, "exit_angle", v); /* degrees, as runs.csv */
    assert_true(v[0] == NC_FILL_DOUBLE && fabs(v[1] - 22.5) < 1e-12 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "exit_angle"), "units"), "degree"); /* UDUNITS' name */
    doubles(id, "working_width", v);
    assert_true(v[0] == 2.625 && v[1] == 5.5 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "working_width"), "units"), "m");
    doubles(id, "first_contact_time", v);
    assert_true(v[0] == 0.003 && v[1] == NC_FILL_DOUBLE && v[2] == NC_FILL_DOUBLE);
    doubles(id, "max_50ms_decel", v);
    assert_true(v[0] == 3.25 && v[1] == 2.875 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "max_50ms_decel"), "units"), "standard_free_fall"); /* g: gram */
    doubles(id, "max_cable_tension", v);
    assert_true(v[0] == 38621.246851234 && v[1] == 1.5e6 && v[2] == NC_FILL_DOUBLE);
    assert_string_equal(att(id, var(id, "max_cable_tension"), "units"), "N");
    /* counts as ints; the failed run's 5 cable breaks do not show */
    int n[RUNS], int_fill;
    assert_int_equal(nc_get_att_int(id, var(id, "posts_failed_left"), "_FillValue", &int_fill), NC_NOERR);
    assert_int_equal(int_fill, NC_FILL_INT);
    assert_int_equal(nc_get_var_int(id, var(id, "posts_failed_left"), n), NC_NOERR);
    assert_true(n[0] == 2 && n[1] == 0 && n[2] == NC_FILL_INT);
    assert_string_equal(att(id, var(id, "posts_failed_left"), "units"), "1");
    assert_int_equal(nc_get_var_int(id, var(id, "events_cable_break"), n), NC_NOERR);
    assert_true(n[0] == 0 && n[1] == 2 && n[2] == NC_FILL_INT);
    assert_int_equal(nc_get_var_int(id, var(id, "events_underride"), n), NC_NOERR);
    assert_true(n[0] == 0 && n[1] == 1 && n[2] == NC_FILL_INT);
    /* every column of runs.csv is a variable with its long name, and its unit where it is a number */
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int count = cs_sweep_columns(cols), nvars;
    for (int c = 0; c < count; c++) {
        int varid = var(id, cols[c].name);
        assert_string_equal(att(id, varid, "long_name"), cols[c].long_name);
        if (cols[c].kind == CS_COLUMN_TEXT) continue;
        const char *units = cols[c].cf_units ? cols[c].cf_units : cols[c].unit ? cols[c].unit : "1";
        assert_string_equal(att(id, varid, "units"), units);
    }
    assert_int_equal(nc_inq_nvars(id, &nvars), NC_NOERR);
    assert_int_equal(nvars, 1 + 2 + count); /* run, the inputs, the columns */
    assert_int_equal(nc_close(id), NC_NOERR);

    /* the same results, the same bytes */
    assert_int_equal(cs_sweep_write_netcdf(again, f->spec, f->x, f->r, RUNS, &err), CS_OK);
    size_t na, nb;
    char *a = slurp(path, &na), *b = slurp(again, &nb);
    assert_true(na > 0 && na == nb);
    assert_memory_equal(a, b, na);
    free(a), free(b);
    unlink(path), unlink(again), rmdir(dir);

    /* a file that cannot be created: nc_strerror's words */
    assert_int_equal(cs_sweep_write_netcdf("/nonexistent/runs.nc", f->spec, f->x, f->r, RUNS, &err),
                     CS_ERR_IO);
    assert_string_equal(err.message, "creating the file: No such file or directory");
}

/* Pixels of a PNG within 3 of an 8-bit colour (cairo's RGB24 is B, G, R in memory). */
static long pixels_of(const char *path, int r, int g, int b) {
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    assert_int_equal(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    assert_int_equal(cairo_image_surface_get_width(s), 1200);
    assert_int_equal(cairo_image_surface_get_height(s), 760);
    const unsigned char *px = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    long count = 0;
    for (int y = 0; y < 760; y++)
        for (int x = 0; x < 1200; x++) {
            const unsigned char *p = px + (size_t)y * (size_t)stride + 4 * (size_t)x;
            count += abs(p[2] - r) <= 3 && abs(p[1] - g) <= 3 && abs(p[0] - b) <= 3;
        }
    cairo_surface_destroy(s);
    return count;
}

/* Draw plot k of the fixture's runs to path. */
static void draw(const fixture *f, int k, const char *path) {
    cs_error err;
    FILE *out = fopen(path, "wb");
    assert_non_null(out);
    if (cs_sweep_write_plot(out, f->spec, k, f->x, f->r, RUNS, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(fclose(out), 0);
}

/* summary.md or summary.json (write) of the fixture's runs, as a string to free. */
typedef cs_status (*summary_fn)(FILE *, const cs_sweep_spec *, const double *, const cs_sweep_result *, long,
                                cs_error *);
static char *summary_text(const fixture *f, summary_fn write) {
    char *text = NULL;
    size_t size = 0;
    cs_error err;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    if (write(out, f->spec, f->x, f->r, RUNS, &err) != CS_OK) fail_msg("%s", err.message);
    fclose(out);
    return text;
}

/* The summaries' responses: the penetration over the run the barrier held (run 0, stopped) and how far
 * the one that broke through (run 1) had got beyond, each with its count; the rope tension in kN; the
 * exit speed of the run that left the barrier only (run 0's 7 m/s is no exit speed); run 2, failed, in
 * none. */
static void test_summary_responses(void **state) {
    fixture *f = *state;
    char *json = summary_text(f, cs_sweep_write_summary_json);
    static const char *const want_json[] = {
        "\"max_dynamic_penetration_m\":{\"runs\":1,\"over\":\"the runs the barrier held (stopped, redirected "
        "or "
        "never touched it)\",\"mean\":1.23456789,\"sd\":null,\"min\":1.23456789,\"p05\":1.23456789,"
        "\"median\":1.23456789,\"p95\":1.23456789,\"max\":1.23456789}",
        "\"penetration_beyond_m\":{\"runs\":1,\"over\":\"the runs it did not hold (through it, or still "
        "going "
        "when the run ended): how far past the attack face the vehicle had got when the run ended; its "
        "penetration is beyond that\",\"mean\":4.03125,",
        "\"max_cable_tension_kn\":{\"runs\":2,\"over\":\"the runs that ran to the end\",\"mean\":769.3106234,"
        "\"sd\":1033.350826,\"min\":38.62124685,",
        "\"exit_speed_mps\":{\"runs\":1,\"over\":\"the runs that left the barrier (broke through, rode over "
        "or "
        "ran under it, or were redirected)\",\"mean\":13.75,",
        "\"max_50ms_decel_g\":{\"runs\":2,\"over\":\"the runs that ran to the end\",\"mean\":3.0625,",
        "\"astm_f2656_as_run M40/P2\":{\"count\":1,",
        "\"astm_f2656_as_run PU40/P4\":{\"count\":1,",
        "\"sd_std_02_01_as_run K8/L2\":{\"count\":1,",
        "\"sd_std_02_01_as_run not rated\":{\"count\":1,",
        "\"spearman\":{\"max_50ms_decel_g\":{\"barrier.cables[0].pretension\":null,\"vehicle\":null},"
        "\"max_dynamic_penetration_m\":{",
    };
    for (size_t i = 0; i < sizeof want_json / sizeof want_json[0]; i++)
        if (!strstr(json, want_json[i])) fail_msg("summary.json lacks %s:\n%s", want_json[i], json);
    assert_null(strstr(json, "_n\""));
    free(json);
    char *md = summary_text(f, cs_sweep_write_summary_md);
    static const char *const want_md[] = {
        ("; max dynamic penetration (m) only over the runs the barrier held (stopped, redirected or never "
         "touched it); penetration beyond (m) only over the runs it did not hold"),
        ". Forces in kN.\n\n| response | runs | mean | sd | min | 5% | median | 95% | max |\n",
        "\n| max dynamic penetration (m) | 1 | 1.235 | n/a | 1.235 | 1.235 | 1.235 | 1.235 | 1.235 |\n",
        "\n| penetration beyond (m) | 1 | 4.031 | n/a | 4.031 |",
        "\n| max cable tension (kN) | 2 | 769.3 | 1033 | 38.62 |",
        "\n| exit speed (m/s) | 1 | 13.75 | n/a |",
        "\n| input | max 50-ms deceleration (g) | max dynamic penetration (m) | penetration beyond (m) |",
        "\n| ASTM F2656 designation as run M40/P2 | 1 | 0.5 |",
        "\n| SD-STD-02.01 designation as run not rated | 1 | 0.5 |",
    };
    for (size_t i = 0; i < sizeof want_md / sizeof want_md[0]; i++)
        if (!strstr(md, want_md[i])) fail_msg("summary.md lacks %s:\n%s", want_md[i], md);
    free(md);
}

/* The plots of the three runs against the pretension, a line per vehicle: their files, captions and
 * summary.md's lines; the lines in their colours, the run that broke through crossed out, and the cross
 * gone when it is said to have stopped; a y that runs.csv lacks refused at its place. */
static void test_plots(void **state) {
    fixture *f = *state;
    cs_sweep_spec *s = f->spec;
    assert_non_null(s->plots = calloc(2, sizeof *s->plots));
    s->plot_count = 2;
    s->plots[0] = (cs_sweep_plot){12, 5, 0, 1, strdup("max_barrier_deflection"), 13, 8, "png"};
    s->plots[1] = (cs_sweep_plot){15, 5, 0, 1, strdup("exit_speed"), 16, 8, "svg"};
    assert_int_equal(cs_sweep_plots_check(s), 0);
    char file[256], caption[1000];
    cs_sweep_plot_file(s, 0, file, sizeof file);
    assert_string_equal(file, "plots/max_barrier_deflection-vs-pretension.png");
    cs_sweep_plot_file(s, 1, file, sizeof file);
    assert_string_equal(file, "plots/exit_speed-vs-pretension.svg");
    cs_sweep_plot_caption(s, 0, f->r, RUNS, caption, sizeof caption);
    assert_string_equal(caption,
                        "max_barrier_deflection against barrier.cables[0].pretension, a line per vehicle: "
                        "2 of 3 runs shown, 1 broke through (marked with a cross); left out: 1 run that "
                        "did not run to the end");
    cs_sweep_plot_caption(s, 1, f->r, RUNS, caption, sizeof caption);
    assert_string_equal(caption,
                        "exit_speed against barrier.cables[0].pretension, a line per vehicle: 1 of 3 runs "
                        "shown, 1 broke through (marked with a cross); left out: 1 run that did not run "
                        "to the end, 1 run with no exit_speed");
    char *text = summary_text(f, cs_sweep_write_summary_md);
    assert_non_null(strstr(text,
                           "\n## Plots\n\n- `plots/max_barrier_deflection-vs-pretension.png`: "
                           "max_barrier_deflection against barrier.cables[0].pretension, a line per "
                           "vehicle: 2 of 3 runs shown, 1 broke through (marked with a cross); left out: 1 "
                           "run that did not run to the end.\n- `plots/exit_speed-vs-pretension.svg`: "));
    free(text);

    char dir[] = "/tmp/cs-plots-XXXXXX", png[64], svg[64];
    assert_non_null(mkdtemp(dir));
    snprintf(png, sizeof png, "%s/plot.png", dir);
    snprintf(svg, sizeof svg, "%s/plot.svg", dir);
    draw(f, 0, png);
    /* the first vehicle's line (palette 0), the second's (palette 1), the black cross of run 1 */
    assert_true(pixels_of(png, 31, 120, 181) > 50);
    assert_true(pixels_of(png, 230, 115, 13) > 30);
    assert_true(pixels_of(png, 26, 26, 26) > 30);
    f->r[1].summary.outcome = CS_STOPPED;
    draw(f, 0, png);
    assert_int_equal(pixels_of(png, 26, 26, 26), 0);
    f->r[1].summary.outcome = CS_BREAKTHROUGH;
    draw(f, 1, svg);
    size_t n;
    char *b = slurp(svg, &n);
    assert_true(n > 1000 && memcmp(b, "<?xml", 5) == 0 && strstr(b, "<svg"));
    free(b);
    unlink(png), unlink(svg), rmdir(dir);

    /* a response that runs.csv lacks, a text one: at y's place */
    free(s->plots[1].y);
    s->plots[1].y = strdup("max_deflection");
    free(s->plots[0].y);
    s->plots[0].y = strdup("outcome");
    assert_int_equal(cs_sweep_plots_check(s), -1);
    assert_int_equal(s->error_count, 2);
    assert_non_null(strstr(s->errors[0],
                           "tests/sweep/grid.yaml:13:8: plot: y: outcome is text (expected a number "
                           "column of runs.csv"));
    assert_non_null(strstr(s->errors[1],
                           "tests/sweep/grid.yaml:16:8: plot: y: unknown response 'max_deflection' "
                           "(expected a number column of runs.csv: astm_f2656_penetration, time_reached,"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runs_csv),    cmocka_unit_test(test_runs_csv_read_back),
        cmocka_unit_test(test_runs_netcdf), cmocka_unit_test(test_summary_responses),
        cmocka_unit_test(test_plots),
    };
    int rc = cmocka_run_group_tests(tests, setup, teardown);
    cs_plot_release();
    return rc;
}
