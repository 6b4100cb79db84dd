/* SPDX-License-Identifier: MIT */
/* netCDF's functions from the shared object the build found (CS_NETCDF_SONAME: its SONAME, so the
 * runtime package's file). */
#include "netcdf_lib.h"

#include <pthread.h>
#include <stdio.h>

cs_netcdf_lib cs_netcdf;

static const char *const names[] = {CS_NETCDF_FUNCTIONS(CS_DYNLIB_NAME)};
static cs_error failure; /* CS_OK, or why it could not be loaded */
static pthread_once_t once = PTHREAD_ONCE_INIT;

_Static_assert(sizeof cs_netcdf == sizeof names / sizeof *names * sizeof(void *), "a table of pointers");

static void load(void) {
    cs_dynlib_bind("netCDF", CS_NETCDF_SONAME, names, &cs_netcdf, (int)(sizeof names / sizeof *names),
                   &failure);
}

cs_status cs_netcdf_load(cs_error *err) {
    pthread_once(&once, load);
    if (failure.status == CS_OK) return CS_OK;
    if (err) *err = failure;
    return failure.status;
}
