/* SPDX-License-Identifier: MIT */
/* netCDF, loaded when a sweep first writes runs.nc (dynlib.h): include this in place of <netcdf.h>, call
 * cs_netcdf_load, then nc_* as usual. */
#ifndef CS_IO_NETCDF_LIB_H
#define CS_IO_NETCDF_LIB_H

#include <netcdf.h>

#include "dynlib.h"

#define CS_NETCDF_FUNCTIONS(X)                                                                               \
    X(nc_create)                                                                                             \
    X(nc_def_dim) X(nc_def_var) X(nc_put_att_text) X(nc_put_att_int) X(nc_put_att_double) X(nc_enddef)       \
        X(nc_put_var_text) X(nc_put_var_int) X(nc_put_var_double) X(nc_close) X(nc_abort) X(nc_strerror)

typedef struct cs_netcdf_lib {
    CS_NETCDF_FUNCTIONS(CS_DYNLIB_FIELD)
} cs_netcdf_lib;

extern cs_netcdf_lib cs_netcdf;

/* netCDF's functions, loaded once (thread-safe): CS_OK; CS_ERR_IO with err filled (dynlib.h). */
cs_status cs_netcdf_load(cs_error *err);

#define nc_create (cs_netcdf.nc_create)
#define nc_def_dim (cs_netcdf.nc_def_dim)
#define nc_def_var (cs_netcdf.nc_def_var)
#define nc_put_att_text (cs_netcdf.nc_put_att_text)
#define nc_put_att_int (cs_netcdf.nc_put_att_int)
#define nc_put_att_double (cs_netcdf.nc_put_att_double)
#define nc_enddef (cs_netcdf.nc_enddef)
#define nc_put_var_text (cs_netcdf.nc_put_var_text)
#define nc_put_var_int (cs_netcdf.nc_put_var_int)
#define nc_put_var_double (cs_netcdf.nc_put_var_double)
#define nc_close (cs_netcdf.nc_close)
#define nc_abort (cs_netcdf.nc_abort)
#define nc_strerror (cs_netcdf.nc_strerror)

#endif
