/* SPDX-License-Identifier: MIT */
/* Libraries loaded by dlopen(3) when first used, not linked: cairo (and fontconfig) when a plot is drawn,
 * netCDF when a sweep writes runs.nc. Linked, they would be mapped and relocated at every start of the
 * command (netCDF brings HDF5, curl, TLS and Kerberos, cairo the X and font libraries: 57 of the 66
 * shared objects a run mapped), about a third of the CPU time of a whole run that draws no plot and
 * writes no runs.nc. Each library's header (cairo_lib.h, netcdf_lib.h) lists the functions cablesim
 * calls, in a table of pointers with the library's own types, and names each function as its pointer in
 * the table, so the code calls cairo and netCDF as it would if they were linked; it must load its
 * library first. */
#ifndef CS_IO_DYNLIB_H
#define CS_IO_DYNLIB_H

#include <stddef.h>

#include "cablesim/sim.h"

/* A table's field: a pointer to the function of that name, of its declared type. */
#define CS_DYNLIB_FIELD(name) __typeof__(name) *name;
/* A table's entry in the list of names bound. */
#define CS_DYNLIB_NAME(name) #name,

/* Loads the shared object soname (RTLD_NOW | RTLD_LOCAL, never unloaded) and fills the n function
 * pointers of table, in the order of names. CS_OK; CS_ERR_IO with err filled ("cairo
 * (libcairo.so.2) ...: dlerror's reason", or the missing function). For tests,
 * CABLESIM_TEST_NO_LIB=WHAT[,WHAT...] makes the libraries named WHAT fail so, as on a machine without their
 * packages. */
cs_status cs_dynlib_bind(const char *what, const char *soname, const char *const *names, void *table, int n,
                         cs_error *err);

#endif
