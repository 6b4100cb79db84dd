/* SPDX-License-Identifier: MIT */
/* cairo's functions and fontconfig's from the shared objects the build found (CS_CAIRO_SONAME,
 * CS_FONTCONFIG_SONAME: their SONAMEs, so the runtime packages' files). */
#include "cairo_lib.h"

#include <pthread.h>
#include <stdio.h>

#include "status.h"

cs_cairo_lib cs_cairo;
cs_fontconfig_lib cs_fontconfig;

static const char *const cairo_names[] = {CS_CAIRO_FUNCTIONS(CS_DYNLIB_NAME)};
static const char *const fontconfig_names[] = {"FcFini"};
static cs_error failure;   /* why they could not be loaded */
static _Atomic int loaded; /* set once by load */
static pthread_once_t once = PTHREAD_ONCE_INIT;

_Static_assert(sizeof cs_cairo == sizeof cairo_names / sizeof *cairo_names * sizeof(void *),
               "a table of pointers");
_Static_assert(sizeof cs_fontconfig == sizeof(void *), "a table of pointers");

static void load(void) {
    loaded = cs_dynlib_bind("cairo", CS_CAIRO_SONAME, cairo_names, &cs_cairo,
                            (int)(sizeof cairo_names / sizeof *cairo_names), &failure) == CS_OK &&
             cs_dynlib_bind("fontconfig", CS_FONTCONFIG_SONAME, fontconfig_names, &cs_fontconfig, 1,
                            &failure) == CS_OK;
}

cs_status cs_cairo_load(cs_error *err) {
    pthread_once(&once, load);
    if (loaded) return CS_OK;
    if (err) *err = failure;
    return failure.status;
}

int cs_cairo_loaded(void) {
    return loaded;
}
