/* SPDX-License-Identifier: MIT */
/* A shared object's functions by name (dynlib.h). */
#include "dynlib.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "status.h"

/* CABLESIM_TEST_NO_LIB=WHAT[,WHAT...] (for tests): the library WHAT ("cairo", "netCDF") is not found,
 * as on a machine without its package. */
static int hidden(const char *what) {
    const char *list = getenv("CABLESIM_TEST_NO_LIB");
    size_t n = strlen(what);
    for (const char *p = list; p && *p; p += strcspn(p, ","), p += *p == ',')
        if (strncmp(p, what, n) == 0 && (p[n] == ',' || p[n] == '\0')) return 1;
    return 0;
}

cs_status cs_dynlib_bind(const char *what, const char *soname, const char *const *names, void *table, int n,
                         cs_error *err) {
    char message[CS_MESSAGE_SIZE];
    if (hidden(what)) {
        snprintf(message, sizeof message, "%s (%s) could not be loaded: hidden by CABLESIM_TEST_NO_LIB", what,
                 soname);
        return cs_status_set(err, CS_ERR_IO, message);
    }
    void *h = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(message, sizeof message, "%s (%s) could not be loaded: %s", what, soname, dlerror());
        return cs_status_set(err, CS_ERR_IO, message);
    }
    for (int i = 0; i < n; i++) {
        void *sym = dlsym(h, names[i]);
        if (!sym) {
            snprintf(message, sizeof message, "%s (%s) has no %s", what, soname, names[i]);
            dlclose(h);
            return cs_status_set(err, CS_ERR_IO, message);
        }
        /* POSIX: dlsym's object pointer converts to the function's; the table's fields are such pointers */
        memcpy((char *)table + (size_t)i * sizeof sym, &sym, sizeof sym);
    }
    return CS_OK;
}
