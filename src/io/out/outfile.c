#define _POSIX_C_SOURCE 200809L
#include "outfile.h"

#include <dirent.h>
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
        if ((dir[i] != '/' && dir[i] != '\0') || dir[i - 1] == '/') continue;
        snprintf(part, sizeof part, "%.*s", (int)i, dir);
        if (mkdir(part, 0777) == 0) {
            out->made++;
        } else if (errno != EEXIST) {
            snprintf(why, why_size, "%s: %s", part, strerror(errno));
            cs_out_abort(out);
            return -1;
        } else {
            out->made = 0; /* only a trailing run of made folders is ours to remove */
        }
    }
    /* a file can be made there (a read-only file system, a folder without write permission) */
    snprintf(part, sizeof part, "%s/.cablesim-%ld.tmp", dir, (long)getpid());
    int fd = open(part, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0) {
        snprintf(why, why_size, "%s: cannot write there: %s", dir, strerror(errno));
        cs_out_abort(out);
        return -1;
    }
    close(fd);
    unlink(part);
    return 0;
}

void cs_out_own(cs_outdir *out, const char *const *names, int count) {
    out->owned = names;
    out->owned_count = count;
}

static int written(const cs_outdir *out, const char *name) {
    for (int i = 0; i < out->count; i++)
        if (strcmp(out->names[i], name) == 0) return 1;
    return 0;
}

/* Remove the file DIR/name if there is one; -1 with why filled if it cannot be. */
static int remove_stale(const cs_outdir *out, const char *name, char *why, size_t why_size) {
    char path[1200];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", out->dir, name);
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode)) return 0; /* missing, or not a file cablesim wrote */
    if (unlink(path) == 0 || errno == ENOENT) return 0;
    snprintf(why, why_size, "%s: an earlier run's file, cannot be removed: %s", path, strerror(errno));
    return -1;
}

/* Whether name ends in ext, or in ext and ".tmp". */
static int has_ext(const char *name, const char *ext) {
    size_t n = strlen(name), e = strlen(ext);
    if (n > e && strcmp(name + n - e, ext) == 0) return 1;
    return n > e + 4 && strcmp(name + n - 4, ".tmp") == 0 && strncmp(name + n - 4 - e, ext, e) == 0;
}

/* The owned names this run did not write (and stale temporaries of them) removed. */
static int prune(const cs_outdir *out, char *why, size_t why_size) {
    for (int k = 0; k < out->owned_count; k++) {
        const char *own = out->owned[k], *star = strstr(own, "/*");
        char name[300];
        if (!star) {
            snprintf(name, sizeof name, "%s.tmp", own);
            if ((!written(out, own) && remove_stale(out, own, why, why_size) != 0) ||
                remove_stale(out, name, why, why_size) != 0)
                return -1;
            continue;
        }
        char sub[1200];
        snprintf(sub, sizeof sub, "%s/%.*s", out->dir, (int)(star - own), own);
        DIR *d = opendir(sub);
        if (!d) continue; /* none there */
        int rc = 0;
        struct dirent *e;
        while (rc == 0 && (e = readdir(d)) != NULL) {
            snprintf(name, sizeof name, "%.*s/%s", (int)(star - own), own, e->d_name);
            if (e->d_name[0] == '.' || !has_ext(e->d_name, star + 2) || written(out, name)) continue;
            rc = remove_stale(out, name, why, why_size);
        }
        closedir(d);
        if (rc != 0) return -1;
        rmdir(sub); /* if nothing is left in it */
    }
    return 0;
}

int cs_out_subdir(cs_outdir *out, const char *subdir, char *why, size_t why_size) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", out->dir, subdir);
    if (mkdir(path, 0777) != 0 && errno != EEXIST) {
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

static int end_failed(const cs_outdir *out, int i, int err, char *why, size_t why_size) {
    snprintf(why, why_size, "%s/%s: %s", out->dir, out->names[i], strerror(err));
    return -1;
}

int cs_out_end_at(cs_outdir *out, int i, FILE *f, char *why, size_t why_size) {
    int bad = fflush(f) != 0 || ferror(f) || fsync(fileno(f)) != 0;
    int err = errno;
    bad |= fclose(f) != 0;
    return bad ? end_failed(out, i, err ? err : errno, why, why_size) : 0;
}

int cs_out_end(cs_outdir *out, FILE *f, char *why, size_t why_size) {
    return cs_out_end_at(out, out->count - 1, f, why, why_size);
}

int cs_out_end_path(cs_outdir *out, char *why, size_t why_size) {
    char path[1200];
    path_of(out, out->count - 1, 1, path, sizeof path);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return end_failed(out, out->count - 1, errno, why, why_size);
    int bad = fsync(fd) != 0, err = errno;
    close(fd);
    return bad ? end_failed(out, out->count - 1, err, why, why_size) : 0;
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
    if (prune(out, why, why_size) != 0) return -1;
    int fd = open(out->dir, O_RDONLY);
    if (fd >= 0) { /* make the renames durable */
        fsync(fd);
        close(fd);
    }
    out->made = 0; /* the folders hold a result now */
    return 0;
}

void cs_out_abort(cs_outdir *out) {
    char tmp[1200];
    for (int i = 0; i < out->count; i++) {
        path_of(out, i, 1, tmp, sizeof tmp);
        unlink(tmp);
    }
    for (int i = 0; i < out->count; i++) { /* a subfolder (plots/) this left empty */
        const char *slash = strrchr(out->names[i], '/');
        if (!slash) continue;
        snprintf(tmp, sizeof tmp, "%s/%.*s", out->dir, (int)(slash - out->names[i]), out->names[i]);
        rmdir(tmp);
    }
    out->count = 0;
    /* the folders cs_out_open made, deepest first, while they are empty */
    char part[1024];
    snprintf(part, sizeof part, "%s", out->dir);
    for (int k = 0; k < out->made; k++) {
        size_t n = strlen(part);
        while (n > 1 && part[n - 1] == '/')
            part[--n] = '\0';
        if (rmdir(part) != 0) break;
        char *slash = strrchr(part, '/');
        if (!slash) break;
        *slash = '\0';
    }
    out->made = 0;
}
