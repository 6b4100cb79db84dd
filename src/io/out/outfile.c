#define _POSIX_C_SOURCE 200809L
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void path_of(const cs_outdir *out, int i, int tmp, char *buf, size_t size) {
    snprintf(buf, size, "%s/%s%s", out->dir, out->names[i], tmp ? ".tmp" : "");
}

int cs_out_open(cs_outdir *out, const char *dir, char *why, size_t why_size) {
    memset(out, 0, sizeof *out);
    if (strlen(dir) >= sizeof out->dir - 80) {
        snprintf(why, why_size, "%s: output path too long", dir);
        return -1;
    }
    snprintf(out->dir, sizeof out->dir, "%s", dir);
    char part[1024];
    for (size_t i = 1; i <= strlen(dir); i++) {
        if (dir[i] != '/' && dir[i] != '\0') continue;
        snprintf(part, sizeof part, "%.*s", (int)i, dir);
        if (mkdir(part, 0777) != 0 && errno != EEXIST) {
            snprintf(why, why_size, "%s: %s", part, strerror(errno));
            return -1;
        }
    }
    return 0;
}

int cs_out_subdir(cs_outdir *out, const char *subdir, char *why, size_t why_size) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", out->dir, subdir);
    if (mkdir(path, 0777) == 0) {
        if (out->created_count < 4 && strlen(subdir) < sizeof out->created[0])
            snprintf(out->created[out->created_count++], sizeof out->created[0], "%s", subdir);
    } else if (errno != EEXIST) {
        snprintf(why, why_size, "%s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

int cs_out_begin_path(cs_outdir *out, const char *name, char *path, size_t path_size, char *why,
                      size_t why_size) {
    if (out->count == CS_OUT_MAX_FILES) {
        snprintf(why, why_size, "too many output files");
        return -1;
    }
    if (strlen(name) >= sizeof out->names[0]) {
        snprintf(why, why_size, "%s/%s: output file name too long", out->dir, name);
        return -1;
    }
    snprintf(out->names[out->count], sizeof out->names[0], "%s", name);
    path_of(out, out->count++, 1, path, path_size);
    return 0;
}

FILE *cs_out_begin(cs_outdir *out, const char *name, char *why, size_t why_size) {
    char path[1200];
    if (cs_out_begin_path(out, name, path, sizeof path, why, why_size) != 0) return NULL;
    FILE *f = fopen(path, "w");
    if (!f) snprintf(why, why_size, "%s: %s", path, strerror(errno));
    return f;
}

static int end_failed(const cs_outdir *out, int err, char *why, size_t why_size) {
    snprintf(why, why_size, "%s/%s: %s", out->dir, out->names[out->count - 1], strerror(err));
    return -1;
}

int cs_out_end(cs_outdir *out, FILE *f, char *why, size_t why_size) {
    int bad = fflush(f) != 0 || ferror(f) || fsync(fileno(f)) != 0;
    int err = errno;
    bad |= fclose(f) != 0;
    return bad ? end_failed(out, err ? err : errno, why, why_size) : 0;
}

int cs_out_end_path(cs_outdir *out, char *why, size_t why_size) {
    char path[1200];
    path_of(out, out->count - 1, 1, path, sizeof path);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return end_failed(out, errno, why, why_size);
    int bad = fsync(fd) != 0, err = errno;
    close(fd);
    return bad ? end_failed(out, err, why, why_size) : 0;
}

int cs_out_commit(cs_outdir *out, char *why, size_t why_size) {
    char tmp[1200], final[1200];
    for (int i = 0; i < out->count; i++) {
        path_of(out, i, 1, tmp, sizeof tmp);
        path_of(out, i, 0, final, sizeof final);
        if (rename(tmp, final) != 0) {
            snprintf(why, why_size, "%s: %s", final, strerror(errno));
            return -1;
        }
    }
    int fd = open(out->dir, O_RDONLY);
    if (fd >= 0) { /* make the renames durable */
        fsync(fd);
        close(fd);
    }
    return 0;
}

void cs_out_abort(cs_outdir *out) {
    char tmp[1200];
    for (int i = 0; i < out->count; i++) {
        path_of(out, i, 1, tmp, sizeof tmp);
        unlink(tmp);
    }
    for (int i = out->created_count; i-- > 0;) { /* a folder it made, if nothing else is in it */
        snprintf(tmp, sizeof tmp, "%s/%s", out->dir, out->created[i]);
        rmdir(tmp);
    }
    out->count = out->created_count = 0;
}
