/* SPDX-License-Identifier: MIT */
/* A shared object's functions by name (dynlib.h). */
#include "dynlib.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* CABLESIM_TEST_NO_LIB=WHAT[,WHAT...] (for tests): the library WHAT ("cairo", "netCDF") is not found,
 * as on a machine without its package. */
static int hidden(const char *what) {
    const char *list = getenv("CABLESIM_TEST_NO_LIB");
    size_t n = strlen(what);
    for (const char *p = list; p && *p; p += strcspn(p, ","), p += *p == ',')
        if (strncmp(p, what, n) == 0 && (p[n] == ',' || p[n] == '\0')) return 1;
    return 0;
}

int cs_dynlib_bind(const char *what, const char *soname, const char *const *names, void *table, int n,
                   char *why, size_t why_size) {
    if (hidden(what)) {
        snprintf(why, why_size, "%s (%s) could not be loaded: hidden by CABLESIM_TEST_NO_LIB", what, soname);
        return -1;
    }
    void *h = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(why, why_size, "%s (%s) could not be loaded: %s", what, soname, dlerror());
        return -1;
    }
    for (int i = 0; i < n; i++) {
        void *sym = dlsym(h, names[i]);
        if (!sym) {
            snprintf(why, why_size, "%s (%s) has no %s", what, soname, names[i]);
            dlclose(h);
            return -1;
        }
        /* POSIX: dlsym's object pointer converts to the function's; the table's fields are such pointers */
        memcpy((char *)table + (size_t)i * sizeof sym, &sym, sizeof sym);
    }
    return 0;
}
