/* SPDX-License-Identifier: MIT */
/* Where the parts library is: the one place that decides. In order:
 *   1. $CABLESIM_DATA, when set and not empty;
 *   2. an installed tree: <prefix>/share/cablesim beside the code that runs, found from the shared library
 *      libcablesim.so when this code is in it (<libdir>/../share/cablesim), else from the executable it is
 *      linked into (<bindir>/../share/cablesim), when that folder exists;
 *   3. the source tree's data/, for the build tree's own programs (the code runs from inside the build
 *      folder it was built in).
 * The relative paths and the two folders of 3 are set by CMakeLists.txt. */
#define _GNU_SOURCE /* dladdr1, the link map of the object holding an address */
#include <dlfcn.h>
#include <limits.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "loader_int.h"

#ifndef CS_DATA_FROM_BIN
#define CS_DATA_FROM_BIN "../share/cablesim"
#endif
#ifndef CS_DATA_FROM_LIB
#define CS_DATA_FROM_LIB "../share/cablesim"
#endif

static const char here = 0; /* an address in the object this code is linked into */

static int is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* The real path of the shared library holding this code (*shared = 1), or of the running executable. */
static int code_path(char *out, int *shared) {
    Dl_info info;
    struct link_map *map = NULL;
    if (dladdr1(&here, &info, (void **)&map, RTLD_DL_LINKMAP) && map && map->l_name && map->l_name[0] &&
        realpath(map->l_name, out)) {
        *shared = 1;
        return 0;
    }
    *shared = 0;
    return realpath("/proc/self/exe", out) ? 0 : -1;
}

/* path's folder, then rel under it, into out. Returns whether it fits. */
static int beside(char *out, size_t size, const char *path, const char *rel) {
    const char *slash = strrchr(path, '/');
    int n = slash ? (int)(slash - path) : 0;
    return snprintf(out, size, "%.*s/%s", n, path, rel) < (int)size;
}

int cs_data_dir_find(char *dir, size_t size, char *note, size_t note_size) {
    const char *env = getenv("CABLESIM_DATA");
    if (env && *env) {
        snprintf(dir, size, "%s", env);
        snprintf(note, note_size, "CABLESIM_DATA");
        return 0;
    }
    char self[PATH_MAX], installed[PATH_MAX + 32], real[PATH_MAX];
    int shared = 0;
    if (code_path(self, &shared) != 0) {
        snprintf(note, note_size, "CABLESIM_DATA is not set and the running program's path is unknown");
        dir[0] = '\0';
        return -1;
    }
    if (beside(installed, sizeof installed, self, shared ? CS_DATA_FROM_LIB : CS_DATA_FROM_BIN) &&
        is_dir(installed) && realpath(installed, real)) {
        snprintf(dir, size, "%s", real);
        snprintf(note, note_size, "installed beside %s", self);
        return 0;
    }
#if defined(CS_BUILD_DIR) && defined(CS_BUILD_DATA)
    char build[PATH_MAX];
    size_t n = realpath(CS_BUILD_DIR, build) ? strlen(build) : 0;
    if (n && strncmp(self, build, n) == 0 && self[n] == '/') {
        snprintf(dir, size, "%s", CS_BUILD_DATA);
        snprintf(note, note_size, "the build tree's");
        return 0;
    }
#endif
    snprintf(note, note_size, "CABLESIM_DATA is not set and %s does not exist", installed);
    dir[0] = '\0';
    return -1;
}
