/* SPDX-License-Identifier: MIT */
/* The folders a model may read from, and the one way an input file is read (confine.h). */
#define _XOPEN_SOURCE 700 /* realpath */
#include "confine.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grow.h"
#include "status.h"

static int add_real(cs_allow *a, const char *real) {
    for (int i = 0; i < a->count; i++)
        if (strcmp(a->dirs[i], real) == 0) return 0;
    char *d = strdup(real);
    if (!d || cs_grow(&a->dirs, &a->capacity, a->count, sizeof *a->dirs) != 0) {
        free(d);
        return -1;
    }
    a->dirs[a->count++] = d;
    return 0;
}

cs_status cs_allow_add(cs_allow *a, const char *dir, cs_error *err) {
    char real[PATH_MAX];
    struct stat st;
    if (!realpath(dir, real) || stat(real, &st) != 0)
        return cs_error_set(err, CS_ERR_INVALID, "%s: %s (expected a folder)", dir, strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return cs_error_set(err, CS_ERR_INVALID, "%s: not a folder (expected a folder)", dir);
    if (add_real(a, real) != 0) return cs_error_set(err, CS_ERR_MEMORY, "out of memory");
    return CS_OK;
}

cs_status cs_allow_add_folder_of(cs_allow *a, const char *file, cs_error *err) {
    char real[PATH_MAX];
    if (!realpath(file, real)) return cs_error_set(err, CS_ERR_INVALID, "%s: %s", file, strerror(errno));
    char *slash = strrchr(real, '/');
    if (slash == real)
        slash[1] = '\0'; /* a file in / */
    else if (slash)
        *slash = '\0';
    return cs_allow_add(a, real, err);
}

int cs_allow_copy(cs_allow *to, const cs_allow *from) {
    for (int i = 0; i < from->count; i++)
        if (add_real(to, from->dirs[i]) != 0) return -1;
    return 0;
}

int cs_allow_has(const cs_allow *a, const char *real) {
    for (int i = 0; i < a->count; i++) {
        size_t n = strlen(a->dirs[i]);
        if (strncmp(real, a->dirs[i], n) != 0) continue;
        if (real[n] == '\0' || real[n] == '/' || (n > 0 && a->dirs[i][n - 1] == '/')) return 1;
    }
    return 0;
}

void cs_allow_list(const cs_allow *a, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < a->count && n < size; i++) {
        const char *sep = i == 0 ? "" : i + 1 == a->count ? " or " : ", ";
        int w = snprintf(buf + n, size - n, "%s%s", sep, a->dirs[i]);
        n += w > 0 ? (size_t)w : 0;
    }
}

void cs_allow_free(cs_allow *a) {
    for (int i = 0; i < a->count; i++)
        free(a->dirs[i]);
    free(a->dirs);
    memset(a, 0, sizeof *a);
}

static const char *kind_of(mode_t m) {
    return S_ISFIFO(m)   ? "a FIFO"
           : S_ISCHR(m)  ? "a character device"
           : S_ISBLK(m)  ? "a block device"
           : S_ISSOCK(m) ? "a socket"
                         : "not a regular file";
}

cs_status cs_input_load(const char *path, size_t limit, char **data, size_t *size, int *errnum,
                        cs_error *err) {
    *data = NULL;
    *size = 0;
    *errnum = 0;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC); /* a FIFO opens without a writer */
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        *errnum = errno;
        if (fd >= 0) close(fd);
        return cs_error_set(err, CS_ERR_IO, "cannot open the file: %s", strerror(*errnum));
    }
    if (S_ISDIR(st.st_mode)) { /* the system's own word for it */
        *errnum = EISDIR;
        close(fd);
        return cs_error_set(err, CS_ERR_IO, "cannot open the file: %s", strerror(EISDIR));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return cs_error_set(err, CS_ERR_INVALID, "%s, not a regular file", kind_of(st.st_mode));
    }
    if ((unsigned long long)st.st_size > limit) {
        close(fd);
        return cs_error_set(err, CS_ERR_INVALID, "%lld bytes, larger than the %zu MB an input file may hold",
                            (long long)st.st_size, limit >> 20);
    }
    size_t cap = (size_t)st.st_size + 2, n = 0; /* room for the NUL, and to see the end without growing */
    char *buf = malloc(cap);
    while (buf) {
        if (n + 1 >= cap) { /* it grew since fstat: read on, up to the limit */
            char *more = cap > limit ? NULL : realloc(buf, 2 * cap);
            if (!more) break;
            buf = more, cap *= 2;
        }
        ssize_t got = read(fd, buf + n, cap - 1 - n);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            *errnum = errno;
            free(buf);
            close(fd);
            return cs_error_set(err, CS_ERR_IO, "cannot read the file: %s", strerror(*errnum));
        }
        if (got == 0) {
            close(fd);
            buf[n] = '\0';
            *data = buf;
            *size = n;
            return CS_OK;
        }
        n += (size_t)got;
    }
    free(buf);
    close(fd);
    return cap > limit ? cs_error_set(err, CS_ERR_INVALID, "larger than an input file may be")
                       : cs_error_set(err, CS_ERR_MEMORY, "out of memory");
}
