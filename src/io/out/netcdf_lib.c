/* SPDX-License-Identifier: MIT */
/* netCDF by dlopen(3) on first use (netcdf_lib.h): the shared object the build found (CS_NETCDF_SONAME,
 * its SONAME, so the installed runtime package's file), each function resolved by name. */
#include "netcdf_lib.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

static cs_netcdf lib;
static char failure[512];
static pthread_once_t once = PTHREAD_ONCE_INIT;

/* dlsym returns an object pointer; POSIX guarantees it converts to the function's pointer. */
#define CS_NC_BIND(h, field, name)                                                                           \
    do {                                                                                                     \
        void *sym = dlsym(h, name);                                                                          \
        if (!sym) return name;                                                                               \
        memcpy(&lib.field, &sym, sizeof sym);                                                                \
    } while (0)

static const char *bind(void *h) {
    CS_NC_BIND(h, create, "nc_create");
    CS_NC_BIND(h, def_dim, "nc_def_dim");
    CS_NC_BIND(h, def_var, "nc_def_var");
    CS_NC_BIND(h, put_att_text, "nc_put_att_text");
    CS_NC_BIND(h, put_att_int, "nc_put_att_int");
    CS_NC_BIND(h, put_att_double, "nc_put_att_double");
    CS_NC_BIND(h, enddef, "nc_enddef");
    CS_NC_BIND(h, put_var_text, "nc_put_var_text");
    CS_NC_BIND(h, put_var_int, "nc_put_var_int");
    CS_NC_BIND(h, put_var_double, "nc_put_var_double");
    CS_NC_BIND(h, close, "nc_close");
    CS_NC_BIND(h, abort, "nc_abort");
    CS_NC_BIND(h, strerror, "nc_strerror");
    return NULL;
}

static void load(void) {
    void *h = dlopen(CS_NETCDF_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(failure, sizeof failure, "the netCDF library (%s) could not be loaded: %s", CS_NETCDF_SONAME,
                 dlerror());
        return;
    }
    const char *missing = bind(h);
    if (missing) {
        snprintf(failure, sizeof failure, "the netCDF library (%s) has no %s", CS_NETCDF_SONAME, missing);
        dlclose(h);
    }
}

const cs_netcdf *cs_netcdf_load(char *why, size_t why_size) {
    pthread_once(&once, load);
    if (!failure[0]) return &lib;
    snprintf(why, why_size, "%s", failure);
    return NULL;
}
