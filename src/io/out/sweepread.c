/* SPDX-License-Identifier: MIT */
/* A sweep's runs.csv read back (sweep --resume): its header checked against the study's, each row's
 * inputs against the study's, its cells back into the runs' results. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "load/csvread.h"
#include "status.h"
#include "sweepout.h"
#include "sweepout_int.h"
#include "writers.h"

/* A column's text back into a result (cs_sweep_column_number and _text read it out). */
static int set_column(const cs_sweep_column *c, cs_sweep_result *r, const char *text) {
    cs_summary *m = &r->summary;
    if (c->what == C_OUTCOME) {
        r->status = strcmp(text, "bad_model") == 0 ? CS_RUN_BAD_MODEL
                    : strcmp(text, "failed") == 0  ? CS_RUN_FAILED
                                                   : CS_RUN_OK;
        for (int o = 0; r->status == CS_RUN_OK && o < 64; o++)
            if (strcmp(cs_outcome_name((cs_outcome)o), text) == 0) {
                m->outcome = (cs_outcome)o;
                return 0;
            }
        return r->status == CS_RUN_OK ? -1 : 0;
    }
    if (c->kind == CS_COLUMN_TEXT) {
        char *to = c->what == C_RATING ? r->rating : c->what == C_SD_STD ? r->sd_std_rating : r->error;
        size_t size = c->what == C_RATING   ? sizeof r->rating
                      : c->what == C_SD_STD ? sizeof r->sd_std_rating
                                            : sizeof r->error;
        if (strlen(text) >= size) return -1;
        snprintf(to, size, "%s", text);
        return 0;
    }
    char *end;
    double v = *text ? strtod(text, &end) : NAN;
    if (*text && *end) return -1;
    if (c->what >= C_EVENTS) {
        r->event_counts[c->what - C_EVENTS] = isnan(v) ? 0 : (int)v;
        return 0;
    }
    switch (c->what) {
    case C_ASTM_PEN:
        r->astm_penetration = v;
        break;
    case C_T:
        m->t_end_s = v;
        break;
    case C_DECEL:
        m->max_50ms_decel_g = v;
        break;
    case C_T_DECEL:
        m->t_max_50ms_decel_s = v;
        break;
    case C_PEN:
    case C_BEYOND: /* one of the two has it */
        if (!isnan(v)) m->max_dynamic_penetration_m = v;
        break;
    case C_DEFL:
        m->max_barrier_deflection_m = v;
        break;
    case C_WIDTH:
        m->working_width_m = v;
        break;
    case C_STOP:
        m->stop_time_s = isnan(v) ? 0 : v;
        break;
    case C_EXIT:
        m->exit_speed_mps = isnan(v) ? 0 : v;
        break;
    case C_EXIT_ANGLE:
        m->exit_angle_deg = isnan(v) ? 0 : v;
        break;
    case C_CONTACT:
        m->first_contact_time_s = isnan(v) ? -1 : v;
        break;
    case C_POSTS_LEFT:
        m->posts_failed_left = isnan(v) ? 0 : (int)v;
        break;
    case C_POSTS_RIGHT:
        m->posts_failed_right = isnan(v) ? 0 : (int)v;
        break;
    case C_CABLES:
        m->cables_broken = isnan(v) ? 0 : (int)v;
        break;
    case C_TENSION:
        m->max_cable_tension_n = v;
        break;
    case C_KE:
        m->initial_kinetic_energy_j = v;
        break;
    case C_ENERGY:
        m->energy_balance_error = v;
        break;
    case C_WARNINGS:
        m->solver_warnings = isnan(v) ? 0 : (int)v;
        break;
    case C_RESIDUAL:
        m->max_solver_residual = v;
        break;
    case C_X:
    case C_Y:
    case C_Z:
        m->final_position_m[c->what - C_X] = v;
        break;
    default:
        return -1;
    }
    return 0;
}

/* The headings of cols that a header line lacks, comma-separated, into buf ("" if it has them all): those
 * of the columns added to runs.csv since an older cablesim wrote it. */
static void missing_columns(const char *line, const cs_sweep_column *cols, int nc, char *buf, size_t size) {
    size_t used = 0;
    buf[0] = '\0';
    for (int c = 0; c < nc; c++) {
        char head[80] = ",";
        size_t len = 1 + (size_t)cs_sweep_column_heading(&cols[c], head + 1, sizeof head - 1);
        const char *at = line;
        while ((at = strstr(at, head)) && at[len] != ',' && at[len] != '\n' && at[len] != '\0')
            at += len;
        if (!at && used < size)
            used += (size_t)snprintf(buf + used, size - used, "%s%s", used ? ", " : "", head + 1);
    }
}

long cs_sweep_read_runs(FILE *f, const char *name, const cs_sweep_spec *s, const double *x,
                        cs_sweep_result *r, long n, int any_order, cs_error *err) {
    int k = s->var_count;
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int nc = cs_sweep_columns(cols), max = 1 + k + nc;
    char *want = NULL, *line = NULL;
    size_t want_size = 0, line_size = 0;
    FILE *h = open_memstream(&want, &want_size);
    long count = -1, last = -1;
    cs_csv rows; /* quoted cells, and the ' before a text that looks like a formula undone */
    cs_csv_open_file(&rows, f, CS_CSV_QUOTED | CS_CSV_UNTEXT, max);
    rows.max_line = 65534;
    if (!h) {
        cs_out_of_memory(err);
        goto done;
    }
    cs_sweep_write_runs(h, s, x, r, 0, NULL); /* its first line alone */
    fclose(h);
    h = NULL;
    if (getline(&line, &line_size, f) < 0 || strcmp(line, want) != 0) {
        char missing[512] = "";
        if (line && strncmp(line, "run,", 4) == 0) missing_columns(line, cols, nc, missing, sizeof missing);
        if (missing[0])
            cs_error_set(err, CS_ERR_INVALID,
                         "%s:1: written by an older cablesim, without the columns %s: run the study again "
                         "without --resume",
                         name, missing);
        else
            cs_error_set(err, CS_ERR_INVALID,
                         "%s:1: not the header this study writes (another study's runs.csv?)", name);
        goto done;
    }
    count = 0;
    for (;;) {
        /* the reader began after the header: its line k is the file's k + 1, and a row begins on the line
         * its first cell does (a quoted cell may hold line breaks) */
        int got = cs_csv_next(&rows);
        if (got == 0 || (got < 0 && ferror(f))) break;
        if (got < 0) { /* the reader's own problem, at its place */
            if (rows.why_col > 0)
                cs_error_set(err, CS_ERR_INVALID, "%s:%ld:%d: %s", name, rows.why_line + 1, rows.why_col,
                             rows.why);
            else
                cs_error_set(err, CS_ERR_INVALID, "%s:%ld: %s", name, rows.why_line + 1, rows.why);
            count = -1;
            break;
        }
        long at = rows.line + 1;
        got = rows.count;
        char **field = rows.cell;
        char *end;
        long i = got == max ? strtol(field[0], &end, 10) : -1;
        if (got != max || *end || i < 0 || i >= n || (any_order ? !r[i].pending : i <= last)) {
            cs_error_set(err, CS_ERR_INVALID, "%s:%ld: %s", name, at,
                         got != max  ? "not a row of this study (its fields)"
                         : any_order ? "not a run of this study, or one given twice"
                                     : "not the next run of this study");
            count = -1;
            break;
        }
        last = i;
        int bad = 0;
        for (int j = 0; j < k && !bad; j++) {
            char value[256];
            cs_sweep_value_text(&s->vars[j], x[i * k + j], value, sizeof value);
            bad = strcmp(value, field[1 + j]) != 0;
        }
        if (bad) {
            cs_error_set(err, CS_ERR_INVALID,
                         "%s:%ld: run %ld's inputs are not this study's (the spec or its seed changed)", name,
                         at, i);
            count = -1;
            break;
        }
        cs_sweep_result *ri = &r[i];
        memset(ri, 0, sizeof *ri);
        for (int c = 0; c < nc && !bad; c++)
            bad = set_column(&cols[c], ri, field[1 + k + c]) != 0;
        if (bad) {
            cs_error_set(err, CS_ERR_INVALID, "%s:%ld: run %ld: a value this study's runs.csv does not hold",
                         name, at, i);
            ri->pending = 1;
            count = -1;
            break;
        }
        count++;
    }
    if (count >= 0 && ferror(f)) {
        cs_error_set(err, CS_ERR_IO, "%s: %s", name, strerror(errno));
        count = -1;
    }
done:
    free(want), free(line);
    cs_csv_close(&rows);
    return count;
}
