/* SPDX-License-Identifier: MIT */
/* netCDF, loaded when a sweep first writes runs.nc. Linked into the command, libnetcdf would bring HDF5,
 * curl, TLS and Kerberos with it: 37 of the 46 shared objects a process of cablesim maps, loaded and
 * relocated at every start, about half of a whole run's time, for a file only a sweep writes. */
#ifndef CS_IO_NETCDF_LIB_H
#define CS_IO_NETCDF_LIB_H

#include <netcdf.h>
#include <stddef.h>

/* The netCDF functions runs.nc needs, as the library declares them. */
typedef struct cs_netcdf {
    __typeof__(nc_create) *create;
    __typeof__(nc_def_dim) *def_dim;
    __typeof__(nc_def_var) *def_var;
    __typeof__(nc_put_att_text) *put_att_text;
    __typeof__(nc_put_att_int) *put_att_int;
    __typeof__(nc_put_att_double) *put_att_double;
    __typeof__(nc_enddef) *enddef;
    __typeof__(nc_put_var_text) *put_var_text;
    __typeof__(nc_put_var_int) *put_var_int;
    __typeof__(nc_put_var_double) *put_var_double;
    __typeof__(nc_close) *close;
    __typeof__(nc_abort) *abort;
    __typeof__(nc_strerror) *strerror;
} cs_netcdf;

/* The library's functions, loaded once (thread-safe); NULL with the reason in why if it cannot be. */
const cs_netcdf *cs_netcdf_load(char *why, size_t why_size);

#endif
