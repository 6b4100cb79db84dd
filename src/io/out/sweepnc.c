/* SPDX-License-Identifier: MIT */
/* runs.nc: runs.csv's table as netCDF (CF-1.8), from the same results through the same columns: a
 * dimension `run`, the run index, one variable per varied input (named from its path, the path itself in
 * long_name, its SI unit in units) and one per result column; text as char arrays padded with NULs, a
 * missing number as the variable's _FillValue. The 64-bit-offset format (netCDF-3: no HDF5) stores no
 * times or library state, so the same results give the same bytes, as runs.csv does. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cairo_lib.h"
#include "netcdf_lib.h"
#include "status.h"
#include "sweepout.h"

/* A variable of runs.nc: a varied input (in), a result column (col), or, with neither, the run index. */
typedef struct ncvar {
    const cs_sweep_var *in;
    const cs_sweep_column *col;
    int input;           /* in: its index among the inputs */
    cs_column_kind kind; /* the run index: COUNT */
    char name[NC_MAX_NAME + 1];
    size_t width; /* TEXT: the longest text, at least 1 */
    int id;
} ncvar;

/* The file being written, and its first failure (later calls are skipped). */
typedef struct ncfile {
    int id, status;
    char doing[NC_MAX_NAME + 32];
} ncfile;

static int check(ncfile *f, int status, const char *doing, const char *name) {
    if (status != NC_NOERR && f->status == NC_NOERR) {
        f->status = status;
        snprintf(f->doing, sizeof f->doing, "%s %s", doing, name);
    }
    return f->status == NC_NOERR;
}

static void text_att(ncfile *f, int varid, const char *name, const char *value) {
    if (f->status == NC_NOERR)
        check(f, nc_put_att_text(f->id, varid, name, strlen(value), value), "writing attribute", name);
}

void cs_sweep_name(const char *path, char *name, size_t size) {
    size_t n = 0;
    for (const char *p = path; *p && n + 1 < size; p++) {
        if (isalnum((unsigned char)*p))
            name[n++] = *p;
        else if (n > 0 && name[n - 1] != '_')
            name[n++] = '_';
    }
    while (n > 0 && name[n - 1] == '_')
        n--;
    name[n] = '\0';
}

static const char *text_of(const ncvar *v, const double *x, int k, const cs_sweep_result *r, long i,
                           char *buf, size_t size) {
    if (v->col) return cs_sweep_column_text(v->col, &r[i]);
    cs_sweep_value_text(v->in, x[i * k + v->input], buf, size);
    return buf;
}

/* An input as the run used it (runs.csv's value), a result in full, the run index; NaN: missing. */
static double number_of(const ncvar *v, const double *x, int k, const cs_sweep_result *r, long i) {
    if (v->col) return cs_sweep_column_number(v->col, &r[i]);
    if (v->in) return cs_sweep_value_used(v->in, x[i * k + v->input]);
    return (double)i;
}

static void define(ncfile *f, ncvar *v, int run_dim) {
    int dims[2] = {run_dim, 0};
    if (v->kind == CS_COLUMN_TEXT) {
        char dim[NC_MAX_NAME + 1];
        int len = snprintf(dim, sizeof dim, "%s_strlen", v->name); /* its length's dimension */
        if (!check(f, len < (int)sizeof dim ? NC_NOERR : NC_EMAXNAME, "naming", v->name)) return;
        if (!check(f, nc_def_dim(f->id, dim, v->width, &dims[1]), "defining", dim)) return;
    }
    nc_type type = v->kind == CS_COLUMN_TEXT ? NC_CHAR : v->kind == CS_COLUMN_COUNT ? NC_INT : NC_DOUBLE;
    if (!check(f, nc_def_var(f->id, v->name, type, v->kind == CS_COLUMN_TEXT ? 2 : 1, dims, &v->id),
               "defining", v->name))
        return;
    text_att(f, v->id, "long_name", v->in ? v->in->path : v->col ? v->col->long_name : "run index");
    if (v->kind == CS_COLUMN_TEXT) return;
    const char *units = v->in              ? v->in->unit
                        : !v->col          ? "1"
                        : v->col->cf_units ? v->col->cf_units
                                           : v->col->unit;
    text_att(f, v->id, "units", units ? units : "1");
    if (!v->col || f->status != NC_NOERR) return; /* inputs and the index are never missing */
    static const double fill_double = NC_FILL_DOUBLE;
    static const int fill_int = NC_FILL_INT;
    check(f,
          type == NC_INT ? nc_put_att_int(f->id, v->id, "_FillValue", NC_INT, 1, &fill_int)
                         : nc_put_att_double(f->id, v->id, "_FillValue", NC_DOUBLE, 1, &fill_double),
          "writing _FillValue of", v->name);
}

static void put(ncfile *f, const ncvar *v, const double *x, int k, const cs_sweep_result *r, long n) {
    size_t count = (size_t)n * (v->kind == CS_COLUMN_TEXT ? v->width : 1);
    void *data = calloc(count, v->kind == CS_COLUMN_TEXT ? 1 : sizeof(double));
    if (!data) {
        check(f, NC_ENOMEM, "writing", v->name);
        return;
    }
    for (long i = 0; i < n; i++) {
        char buf[256];
        if (v->kind == CS_COLUMN_TEXT) {
            strncpy((char *)data + (size_t)i * v->width, text_of(v, x, k, r, i, buf, sizeof buf), v->width);
            continue;
        }
        double d = number_of(v, x, k, r, i);
        if (v->kind == CS_COLUMN_COUNT)
            ((int *)data)[i] = isfinite(d) ? (int)d : NC_FILL_INT;
        else
            ((double *)data)[i] = isfinite(d) ? d : NC_FILL_DOUBLE;
    }
    int status = v->kind == CS_COLUMN_TEXT    ? nc_put_var_text(f->id, v->id, data)
                 : v->kind == CS_COLUMN_COUNT ? nc_put_var_int(f->id, v->id, data)
                                              : nc_put_var_double(f->id, v->id, data);
    check(f, status, "writing", v->name);
    free(data);
}

cs_status cs_sweep_write_netcdf(const char *path, const cs_sweep_spec *s, const double *x,
                                const cs_sweep_result *r, long n, cs_error *err) {
    int k = s->var_count;
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int nc = cs_sweep_columns(cols), count = 0;
    ncvar vars[1 + CS_SWEEP_MAX_VARS + CS_SWEEP_MAX_COLUMNS];
    vars[count++] = (ncvar){.kind = CS_COLUMN_COUNT, .name = "run"};
    for (int j = 0; j < k; j++) {
        ncvar *v = &vars[count++];
        *v = (ncvar){
            .in = &s->vars[j], .input = j, .kind = s->vars[j].numeric ? CS_COLUMN_REAL : CS_COLUMN_TEXT};
        cs_sweep_name(s->vars[j].path, v->name, sizeof v->name);
    }
    for (int c = 0; c < nc; c++) {
        ncvar *v = &vars[count++];
        *v = (ncvar){.col = &cols[c], .kind = cols[c].kind};
        strcpy(v->name, cols[c].name); /* 48 bytes into NC_MAX_NAME + 1 */
    }
    for (int m = 0; m < count; m++) {
        if (vars[m].kind != CS_COLUMN_TEXT) continue;
        vars[m].width = 1;
        for (long i = 0; i < n; i++) {
            char buf[256];
            size_t len = strlen(text_of(&vars[m], x, k, r, i, buf, sizeof buf));
            if (len > vars[m].width) vars[m].width = len;
        }
    }
    cs_status loaded = cs_netcdf_load(err);
    if (loaded != CS_OK) return loaded;
    ncfile f = {0, NC_NOERR, ""};
    if (!check(&f, nc_create(path, NC_CLOBBER | NC_64BIT_OFFSET, &f.id), "creating", "the file"))
        return cs_error_set(err, CS_ERR_IO, "%s: %s", f.doing, nc_strerror(f.status));
    char title[1200], seed[24];
    snprintf(title, sizeof title, "cablesim sweep %s: one record per run", s->file);
    /* the seed as text: netCDF-3 has no 64-bit integer */
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)s->seed);
    text_att(&f, NC_GLOBAL, "title", title);
    text_att(&f, NC_GLOBAL, "Conventions", "CF-1.8");
    text_att(&f, NC_GLOBAL, "source", "cablesim " CS_VERSION_STRING);
    text_att(&f, NC_GLOBAL, "spec", s->file);
    text_att(&f, NC_GLOBAL, "model", s->model);
    text_att(&f, NC_GLOBAL, "method", cs_sweep_method_name(s->method));
    text_att(&f, NC_GLOBAL, "seed", seed);
    int runs = (int)n, run_dim = -1;
    if (f.status == NC_NOERR)
        check(&f, nc_put_att_int(f.id, NC_GLOBAL, "runs", NC_INT, 1, &runs), "writing attribute", "runs");
    if (f.status == NC_NOERR) check(&f, nc_def_dim(f.id, "run", (size_t)n, &run_dim), "defining", "run");
    for (int m = 0; m < count && f.status == NC_NOERR; m++)
        define(&f, &vars[m], run_dim);
    if (f.status == NC_NOERR) check(&f, nc_enddef(f.id), "defining", "the variables");
    for (int m = 0; m < count && f.status == NC_NOERR; m++)
        put(&f, &vars[m], x, k, r, n);
    if (f.status == NC_NOERR && check(&f, nc_close(f.id), "closing", "the file"))
        return cs_status_set(err, CS_OK, "");
    if (f.status != NC_NOERR) nc_abort(f.id); /* the caller removes what is left */
    return cs_error_set(err, CS_ERR_IO, "%s: %s", f.doing, nc_strerror(f.status));
}

cs_status cs_sweep_outputs_loadable(const cs_sweep_spec *spec, cs_error *err) {
    cs_error lib;
    if (cs_cairo_load(&lib) != CS_OK)
        return cs_error_set(err, lib.status,
                            "%s: a study draws its figures with it (plots/study-*.png); install its package",
                            lib.message);
    if (spec->netcdf && cs_netcdf_load(&lib) != CS_OK)
        return cs_error_set(err, lib.status,
                            "%s: runs.nc (--netcdf, or `netcdf: true` in the spec) needs it; install its "
                            "package or leave runs.nc out",
                            lib.message);
    return cs_status_set(err, CS_OK, "");
}
