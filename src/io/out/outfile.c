/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* fopencookie */
#include "outfile.h"

#include "fnv.h"
#include "load/confine.h"
#include "status.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

enum { PATH_SIZE = 1400, MAX_DEPTH = 32 };
/* More than any manifest of cablesim's holds: a commit's files and, until its end, the earlier run's. */
enum { MANIFEST_MAX_FILES = 4 * CS_OUT_MAX_FILES, MANIFEST_MAX_BYTES = 1 << 20 };

static const char tmp_prefix[] = CS_OUT_TMP_PREFIX;

/* DIR/ and the first r characters of rel into buf; 0 if it does not fit (buf then empty: no file).
 * Async-signal-safe, as remove_uncommitted needs. */
static int join(const cs_outdir *out, const char *rel, size_t r, char *buf, size_t size) {
    size_t d = strlen(out->dir);
    if (d + 1 + r >= size) {
        buf[0] = '\0';
        return 0;
    }
    memcpy(buf, out->dir, d);
    buf[d] = '/';
    memcpy(buf + d + 1, rel, r);
    buf[d + 1 + r] = '\0';
    return 1;
}

/* DIR/rel into buf; 0 if it does not fit (buf then empty: no file). */
static int full_path(const cs_outdir *out, const char *rel, char *buf, size_t size) {
    return join(out, rel, strlen(rel), buf, size);
}

/* ---- a signal's cleanup ---- */

/* The folders open, from cs_out_open to cs_out_commit or cs_out_abort, for cs_out_signal_cleanup. A slot
 * is taken and given back atomically, so threads writing folders of their own share the list; a folder
 * past OPEN_MAX is not in it (a signal then leaves it as a kill -9 would). */
enum { OPEN_MAX = 8 };
static _Atomic(cs_outdir *) open_dirs[OPEN_MAX];

static void enlist(cs_outdir *out) {
    for (int i = 0; i < OPEN_MAX; i++) {
        cs_outdir *none = NULL;
        if (atomic_compare_exchange_strong(&open_dirs[i], &none, out)) return;
    }
}

static void delist(cs_outdir *out) {
    for (int i = 0; i < OPEN_MAX; i++) {
        cs_outdir *self = out;
        atomic_compare_exchange_strong(&open_dirs[i], &self, NULL);
    }
}

/* SIGINT and SIGTERM held back in this thread, the mask before into old: whatever changes the record of what
 * a folder holds (the temporaries, the folders made, the lock) does it between hold_signals and
 * let_signals, so that a handler calling cs_out_signal_cleanup finds that record whole. */
static void hold_signals(sigset_t *old) {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, old);
}

static void let_signals(const sigset_t *old) {
    pthread_sigmask(SIG_SETMASK, old, NULL);
}

static void unlink_lock(const cs_outdir *out) {
    char path[PATH_SIZE];
    full_path(out, CS_OUT_LOCK, path, sizeof path);
    unlink(path);
}

/* Remove what a run began and did not commit: its temporaries (its files' and its manifest's or journal's),
 * the subfolders cs_out_subdir made, when that leaves them empty (one that was there before stays), the
 * lock if it is held, then the folders cs_out_open made, deepest first, while they are empty. Only system
 * calls on paths put together with memcpy: async-signal-safe. A temporary renamed into place since is no
 * longer under its name: its unlink fails, the file stays. */
static void remove_uncommitted(const cs_outdir *out) {
    char path[PATH_SIZE];
    for (int i = 0; i < out->count; i++) {
        full_path(out, out->tmps[i], path, sizeof path);
        unlink(path);
    }
    if (out->aside[0]) {
        full_path(out, out->aside, path, sizeof path);
        unlink(path);
    }
    for (int i = 0; i < out->subdir_count; i++) { /* a subfolder (plots/) this made, left empty */
        full_path(out, out->subdirs[i], path, sizeof path);
        rmdir(path);
    }
    if (out->lock >= 0) unlink_lock(out);      /* while it is held: a run waiting on this file tries again */
    for (int k = out->made - 1; k >= 0; k--) { /* the last made first: each inside those before it */
        memcpy(path, out->dir, out->made_at[k]);
        path[out->made_at[k]] = '\0';
        rmdir(path);
    }
}

void cs_out_signal_cleanup(void) {
    for (int i = 0; i < OPEN_MAX; i++) {
        const cs_outdir *out = atomic_load(&open_dirs[i]);
        if (out) remove_uncommitted(out);
    }
}

void cs_out_end_by_signal(int sig) {
    cs_out_signal_cleanup();
    signal(sig, SIG_DFL);
    raise(sig); /* delivered when this handler returns */
}

/* Whether rel names a file inside the folder: not empty, not absolute, no "." or ".." or empty part, no
 * control character (a manifest's line or a command's name). */
static int inside(const char *rel) {
    if (!rel[0] || rel[0] == '/') return 0;
    for (const unsigned char *p = (const unsigned char *)rel; *p; p++)
        if (*p < 0x20 || *p == 0x7f) return 0;
    for (const char *p = rel; *p;) {
        size_t n = strcspn(p, "/");
        if (n == 0 || (n == 1 && p[0] == '.') || (n == 2 && p[0] == '.' && p[1] == '.')) return 0;
        p += n + (p[n] == '/');
        if (p[-1] == '/' && !*p) return 0; /* a trailing slash */
    }
    return 1;
}

/* The earlier manifest's line naming rel, or NULL. */
static cs_out_listed *find(const cs_outdir *out, const char *rel) {
    for (int i = 0; i < out->prev_count; i++)
        if (strcmp(out->prev[i].name, rel) == 0) return &out->prev[i];
    return NULL;
}

/* Whether rel is cablesim's: the earlier manifest lists it and it is as that run wrote it (or gone). */
static int listed(const cs_outdir *out, const char *rel) {
    const cs_out_listed *e = find(out, rel);
    return e && e->ours == 1;
}

/* Why the file rel, which is there and not this command's, is not: the end of "DIR holds rel, which "
 * for a message, into buf. */
static const char *not_ours(const cs_outdir *out, const char *rel, char *buf, size_t size) {
    const cs_out_listed *e = find(out, rel);
    if (strcmp(rel, CS_OUT_JOURNAL) == 0)
        snprintf(buf, size,
                 "a `cablesim sweep` stopped before its outputs left there (its runs, which `cablesim sweep "
                 "--resume` finishes)");
    else if (!e)
        snprintf(buf, size, "no cablesim run wrote there (no %s lists it)", CS_OUT_MANIFEST);
    else if (e->ours == 0)
        snprintf(buf, size, "has changed since cablesim wrote it there (its size or hash is not %s's)",
                 CS_OUT_MANIFEST);
    else if (e->ours == -1 && !out->prev_command[0]) /* a manifest of names alone: an earlier version's */
        snprintf(buf, size,
                 "an earlier version of cablesim may have written there, but its %s gives no size and hash "
                 "to tell its files from yours, so none is taken for cablesim's (move or remove them "
                 "yourself)",
                 CS_OUT_MANIFEST);
    else if (e->ours == -1)
        snprintf(buf, size, "%s lists without the size and hash cablesim gives its files", CS_OUT_MANIFEST);
    else if (!out->prev_command[0])
        snprintf(buf, size,
                 "a cablesim command wrote there that %s does not name (its \"# written by\" line): that "
                 "command's results, which `cablesim %s` does not replace",
                 CS_OUT_MANIFEST, out->command);
    else
        snprintf(buf, size,
                 "`cablesim %s` wrote there: that command's results, which `cablesim %s` does not "
                 "replace",
                 out->prev_command, out->command);
    return buf;
}

/* The size and hash of the regular file at path (not through a link at its end) into p. 0, or -1 (errno
 * set) when it is not a regular file or cannot be read. */
static int fingerprint(const char *path, cs_out_print *p) {
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return -1;
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        errno = EINVAL;
        return -1;
    }
    unsigned long long h = CS_IO_FNV_BASIS;
    long long size = 0;
    char buf[1 << 16];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) != 0) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        h = cs_io_fnv(h, buf, (size_t)n);
        size += n;
    }
    int errnum = errno;
    close(fd);
    if (n < 0) {
        errno = errnum;
        return -1;
    }
    p->size = size;
    p->hash = h;
    return 0;
}

/* A manifest line's "SIZE<tab>HASH" into p, read strictly as write_manifest writes it: the size in decimal
 * digits (no sign, space or leading zero but that of "0"), the hash in 16 lowercase hex digits. 1, else 0:
 * another text there is not cablesim's. */
static int read_print(const char *text, cs_out_print *p) {
    size_t digits = strspn(text, "0123456789");
    const char *h = text + digits + 1;
    if (digits == 0 || (text[0] == '0' && digits > 1) || text[digits] != '\t' ||
        strspn(h, "0123456789abcdef") != 16 || h[16])
        return 0;
    errno = 0;
    long long size = strtoll(text, NULL, 10);
    if (errno) return 0; /* past a long long */
    p->size = size;
    p->hash = strtoull(h, NULL, 16);
    return 1;
}

/* Whether the earlier run's file e is as that run wrote it (its size and hash), or gone: 1, else 0. A file
 * of another size is not read (a file of terabytes, or a sparse one, in its place is judged at once). */
static int as_written(const cs_outdir *out, const cs_out_listed *e) {
    char file[PATH_SIZE];
    struct stat st;
    cs_out_print now;
    full_path(out, e->name, file, sizeof file);
    if (lstat(file, &st) != 0) return 1; /* gone: nothing of the user's to keep */
    if (!S_ISREG(st.st_mode) || st.st_size != e->print.size) return 0;
    return fingerprint(file, &now) == 0 && now.size == e->print.size && now.hash == e->print.hash;
}

static int written(const cs_outdir *out, const char *rel) {
    for (int i = 0; i < out->count; i++)
        if (strcmp(out->names[i], rel) == 0) return 1;
    return 0;
}

/* ---- the lock ---- */

/* The lock file's text, the whole of it: LOCK_HEAD, "pid N" and "host NAME" (its holder's), a line each. A
 * file of that name holding anything else is not cablesim's: it is neither truncated nor removed. */
#define LOCK_HEAD "cablesim lock\n"
enum { LOCK_TEXT_SIZE = 512, HOST_SIZE = 256, PID_DIGITS = 9 };

/* What a lock file's text is: the whole of cablesim's, the beginning of one (a lock being written, between
 * its file's making and its text), or another's. */
typedef enum { LOCK_WHOLE, LOCK_BEGUN, LOCK_OTHER } lock_kind;

/* This machine's name into host (HOST_SIZE), as the lock's text holds it: a byte outside '!'..'~' as '?'. */
static void host_name(char *host) {
    if (gethostname(host, HOST_SIZE) != 0 || !host[0]) snprintf(host, HOST_SIZE, "?");
    host[HOST_SIZE - 1] = '\0';
    for (char *c = host; *c; c++)
        if (*c < '!' || *c > '~') *c = '?';
}

/* Whether t (n bytes) goes on at *i with the text s: 1 (*i past it), 0 t ends before s does, -1 not. */
static int lock_word(const char *t, size_t n, size_t *i, const char *s) {
    for (; *s; s++, ++*i) {
        if (*i == n) return 0;
        if (t[*i] != *s) return -1;
    }
    return 1;
}

/* Whether t goes on at *i with 1 to max bytes from lo to hi (the first not zero when zero_first is 0) and
 * '\n', as lock_word says; the bytes into field (max + 1). */
static int lock_field(const char *t, size_t n, size_t *i, char lo, char hi, int zero_first, size_t max,
                      char *field) {
    size_t k = 0;
    for (; *i < n && t[*i] >= lo && t[*i] <= hi; ++*i) {
        if (k == max || (k == 0 && !zero_first && t[*i] == '0')) return -1;
        field[k++] = t[*i];
    }
    field[k] = '\0';
    if (*i == n) return 0;
    return k > 0 && t[(*i)++] == '\n' ? 1 : -1;
}

/* What the lock file's text t (n bytes) is; a whole one's pid and host into pid and host (HOST_SIZE). */
static lock_kind lock_text(const char *t, size_t n, long *pid, char *host) {
    char digits[PID_DIGITS + 1];
    size_t i = 0;
    int r = lock_word(t, n, &i, LOCK_HEAD "pid ");
    if (r > 0) r = lock_field(t, n, &i, '0', '9', 0, PID_DIGITS, digits);
    if (r > 0) r = lock_word(t, n, &i, "host ");
    if (r > 0) r = lock_field(t, n, &i, '!', '~', 1, HOST_SIZE - 1, host);
    if (r < 0 || (r > 0 && i < n)) return LOCK_OTHER;
    if (r == 0) return LOCK_BEGUN;
    *pid = strtol(digits, NULL, 10);
    return LOCK_WHOLE;
}

static int same_file(const struct stat *a, const struct stat *b) {
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

/* The pid of the process holding the lock file fd's fcntl lock; 0 if none does; -1 if the system cannot
 * say (no locks on this file system). */
static long lock_holder(int fd) {
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    if (fcntl(fd, F_GETLK, &fl) != 0) return -1;
    return fl.l_type != F_UNLCK && fl.l_pid > 0 ? (long)fl.l_pid : 0;
}

/* DIR/.cablesim-lock just made (fd, O_EXCL), held: locked (fcntl) and given this process's text. */
static cs_status hold_lock(cs_outdir *out, int fd, const char *path, const char *host, cs_error *err) {
    char text[LOCK_TEXT_SIZE];
    int n = snprintf(text, sizeof text, LOCK_HEAD "pid %ld\nhost %s\n", (long)getpid(), host);
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    out->lock = fd; /* signals are held: the handler knows the file at once */
    if (fcntl(fd, F_SETLK, &fl) == 0 || errno == ENOLCK) { /* ENOLCK: no locks on this file system */
        ssize_t w = pwrite(fd, text, (size_t)n, 0);
        if (w == n) return CS_OK;
        if (w >= 0) errno = ENOSPC;
    }
    int errnum = errno;
    unlink(path);
    close(fd);
    out->lock = -1;
    return cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errnum));
}

/* Remove the lock file named (as lstat found it) whose text was t (n bytes), a lock whose holder has ended,
 * while holding its fcntl lock (of two runs taking it over, one removes it) and only while the name holds
 * that file with that text. 0: removed, or gone since; -1 with errno set. */
static int remove_ended(const char *path, const struct stat *named, const char *t, ssize_t n) {
    int fd = open(path, O_RDWR | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return errno == ENOENT || errno == ELOOP ? 0 : -1;
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    struct stat held, now;
    char again[LOCK_TEXT_SIZE];
    int rc = 0;
    if (fstat(fd, &held) == 0 && same_file(&held, named) &&
        (fcntl(fd, F_SETLK, &fl) == 0 || errno == ENOLCK) && pread(fd, again, sizeof again, 0) == n &&
        memcmp(again, t, (size_t)n) == 0 && lstat(path, &now) == 0 && same_file(&now, &held))
        rc = unlink(path);
    int errnum = errno;
    close(fd);
    errno = errnum;
    return rc == 0 || errnum == ENOENT ? 0 : -1;
}

/* DIR/.cablesim-lock made (O_EXCL: of two runs, one makes it), locked (fcntl) and holding this process's
 * text. One there already is another cablesim's while the system says a process holds it, or its text names
 * another machine, or (where the system cannot say: no locks on the file system) a process still running;
 * one whose holder has ended (a kill -9) is removed and made anew. A file of that name whose text is not a
 * lock's is the user's, and the folder is refused. */
static cs_status take_lock(cs_outdir *out, const char *force, cs_error *err) {
    char path[PATH_SIZE], host[HOST_SIZE], held_host[HOST_SIZE], text[LOCK_TEXT_SIZE];
    full_path(out, CS_OUT_LOCK, path, sizeof path);
    host_name(host);
    for (int tries = 0, waits = 0; tries < 64; tries++) {
        int fd = open(path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
        if (fd >= 0) return hold_lock(out, fd, path, host, err);
        if (errno != EEXIST) {
            return cs_error_set(err, CS_ERR_IO, "%s: cannot write there: %s", out->dir, strerror(errno));
        }
        struct stat named, held;
        if (lstat(path, &named) != 0) continue; /* gone since: make it */
        ssize_t n = -1;
        long holder = -1, pid = 0;
        if (S_ISREG(named.st_mode) && named.st_nlink == 1) {
            fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
            if (fd < 0 && errno != ENOENT && errno != ELOOP) {
                return cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errno));
            }
            if (fd < 0) continue; /* gone or replaced since */
            int errnum = 0;
            if (fstat(fd, &held) == 0 && same_file(&held, &named)) {
                holder = lock_holder(fd);
                n = pread(fd, text, sizeof text, 0);
                errnum = n < 0 ? errno : 0;
            }
            close(fd);
            if (errnum) return cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errnum));
            if (n < 0) continue; /* replaced since */
        }
        lock_kind kind = n < 0 ? LOCK_OTHER : lock_text(text, (size_t)n, &pid, held_host);
        if (kind == LOCK_BEGUN && holder <= 0 && waits++ < 20) { /* its maker writes it within microseconds */
            nanosleep(&(struct timespec){0, 5000000}, NULL);
            continue;
        }
        if (kind != LOCK_WHOLE && !(kind == LOCK_BEGUN && holder > 0)) {
            return cs_error_set(
                err, CS_ERR_IO,
                "%s: not a lock of cablesim's (a file of yours, or a link to one): it is kept, "
                "and the folder cannot be locked beside it%s%s: move it away, or write elsewhere",
                path, force ? ", even with " : "", force ? force : "");
        }
        /* a running cablesim holds its lock's fcntl lock, which ends with it: where the system can say, no
         * holder means the run has ended (its pid may still be a zombie, or another process's since); only
         * where it cannot is the pid asked */
        int other_host = holder <= 0 && strcmp(held_host, host) != 0;
        if (holder > 0 || other_host || (holder < 0 && (kill((pid_t)pid, 0) == 0 || errno == EPERM))) {
            return cs_error_set(
                err, CS_ERR_IO,
                "%s is in use by another cablesim (pid %ld%s%s holds %s): wait for it to end, or "
                "write elsewhere%s",
                out->dir, holder > 0 ? holder : pid, other_host ? " on " : "", other_host ? held_host : "",
                path, holder > 0 ? "" : " (if it has ended, remove that file)");
        }
        if (remove_ended(path, &named, text, n) != 0) {
            return cs_error_set(err, CS_ERR_IO,
                                "%s: the lock of an ended cablesim (pid %ld), cannot be removed: %s", path,
                                pid, strerror(errno));
        }
    }
    return cs_error_set(err, CS_ERR_IO, "%s: cannot take the lock: other cablesim runs keep taking it", path);
}

/* Close the journal and the lock, removing the lock's file first (while it is held: a run waiting on this
 * file tries again). With signals held: a handler never removes the lock's file again once this did (another
 * run's by then). */
static void release(cs_outdir *out) {
    if (out->journal >= 0) close(out->journal);
    out->journal = -1;
    if (out->lock >= 0) {
        unlink_lock(out);
        close(out->lock);
        out->lock = -1;
    }
    free(out->prev);
    out->prev = NULL;
    out->prev_count = 0;
}

/* ---- temporaries ---- */

/* mkstemp of the template DIR/rel (ending in XXXXXX), and the name it chose into rel (as long as the
 * template). Its descriptor, or -1 with errno set. The caller holds signals until rel is where
 * cs_out_signal_cleanup looks. */
static int make_temp(const cs_outdir *out, char *rel) {
    char path[PATH_SIZE];
    if (!full_path(out, rel, path, sizeof path)) {
        errno = ENAMETOOLONG;
        return -1;
    }
    int fd = mkstemp(path);
    if (fd >= 0) memcpy(rel, path + strlen(out->dir) + 1, strlen(rel));
    return fd;
}

/* A temporary of the folder's own (what: "manifest", "journal"), named in out->aside until end_aside, its
 * path into path (PATH_SIZE). Its descriptor, or -1 with errno set. */
static int begin_aside(cs_outdir *out, const char *what, char *path) {
    snprintf(out->aside, sizeof out->aside, "%s%s.XXXXXX", tmp_prefix, what);
    sigset_t old;
    hold_signals(&old);
    int fd = make_temp(out, out->aside);
    let_signals(&old);
    full_path(out, out->aside, path, PATH_SIZE);
    if (fd < 0) out->aside[0] = '\0';
    return fd;
}

/* The temporary of begin_aside renamed or removed. */
static void end_aside(cs_outdir *out) {
    out->aside[0] = '\0';
}

/* ---- the manifest ---- */

/* The first line of every manifest cablesim writes, and has written: a file of that name that does not
 * begin with it is not one. */
#define MANIFEST_HEAD "# cablesim: the files its last run wrote in this folder"

/* The earlier run's manifest into out->prev (none: empty), each listed file checked against its size
 * and hash. Lines that name no file inside the folder are skipped: a manifest never sends a removal
 * outside. A file of that name that does not begin as cablesim's do is the user's: kept, and the folder
 * refused, even with force (the commit writes its manifest there), whose name the message gives. */
static cs_status read_manifest(cs_outdir *out, const char *force, cs_error *err) {
    char path[PATH_SIZE];
    full_path(out, CS_OUT_MANIFEST, path, sizeof path);
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK); /* a FIFO: no wait for a writer */
    if (fd < 0 && errno == ENOENT) return CS_OK;
    struct stat st;
    if (fd >= 0 && (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
        close(fd);
        return cs_error_set(err, CS_ERR_IO, "%s: not a regular file, so not a manifest of cablesim's", path);
    }
    if (fd >= 0 &&
        st.st_size > MANIFEST_MAX_BYTES) { /* not read: a sparse file of terabytes is refused at once */
        close(fd);
        return cs_error_set(err, CS_ERR_IO,
                            "%s: %lld bytes, more than a manifest of cablesim's holds, so not one", path,
                            (long long)st.st_size);
    }
    FILE *f = fd < 0 ? NULL : fdopen(fd, "r");
    if (!f) {
        cs_status st = cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errno));
        if (fd >= 0) close(fd);
        return st;
    }
    char line[512];
    if (!fgets(line, sizeof line, f) || strncmp(line, MANIFEST_HEAD, sizeof MANIFEST_HEAD - 1) != 0) {
        fclose(f);
        return cs_error_set(err, CS_ERR_IO,
                            "%s: not a manifest of cablesim's (a file of yours): it is kept, and the "
                            "folder cannot hold cablesim's beside it%s%s: move it away, or write elsewhere",
                            path, force ? ", even with " : "", force ? force : "");
    }
    if (!strchr(line, '\n')) { /* a first line longer than cablesim's: the rest of it is no name */
        int c;
        while ((c = fgetc(f)) != EOF && c != '\n') {
        }
    }
    int cap = 0, unnamed = 0; /* unnamed: a "written by" line that names no command, or another */
    while (fgets(line, sizeof line, f)) {
        size_t n = strcspn(line, "\n");
        int whole = line[n] == '\n' || feof(f);
        line[n] = '\0';
        if (!whole) { /* longer than any name cablesim writes: skip the rest */
            int c;
            while ((c = fgetc(f)) != EOF && c != '\n') {
            }
            continue;
        }
        if (strncmp(line, "# written by:", 13) == 0) { /* one command, named once or more */
            const char *c = strncmp(line, "# written by: cablesim ", 23) == 0 ? line + 23 : "";
            size_t k = strlen(c);
            if (k == 0 || k >= sizeof out->prev_command || strspn(c, "abcdefghijklmnopqrstuvwxyz") != k ||
                (out->prev_command[0] && strcmp(out->prev_command, c) != 0))
                unnamed = 1;
            else
                memcpy(out->prev_command, c, k + 1);
        }
        char *tab = strchr(line, '\t');
        if (tab) *tab = '\0';
        cs_out_listed e = {.ours = -1};
        size_t len = strlen(line);
        if (line[0] == '#' || len >= sizeof e.name || !inside(line)) continue;
        /* a name listed twice (a commit's file and the earlier run's of that name): either is cablesim's */
        cs_out_listed *seen = find(out, line);
        if (seen && seen->ours == 1) continue;
        memcpy(e.name, line, len + 1);
        if (tab && read_print(tab + 1, &e.print)) e.ours = as_written(out, &e);
        if (seen) {
            if (e.ours == 1) *seen = e;
            continue;
        }
        if (out->prev_count == MANIFEST_MAX_FILES) { /* and each line's look-up bounded */
            fclose(f);
            return cs_error_set(
                err, CS_ERR_IO,
                "%s: lists more than %d files, more than a manifest of cablesim's, so not one", path,
                MANIFEST_MAX_FILES);
        }
        if (out->prev_count == cap) {
            cap = cap ? 2 * cap : 64;
            cs_out_listed *grown = realloc(out->prev, (size_t)cap * sizeof *grown);
            if (!grown) {
                fclose(f);
                return cs_error_set(err, CS_ERR_MEMORY, "out of memory reading %s", path);
            }
            out->prev = grown;
        }
        out->prev[out->prev_count++] = e;
    }
    fclose(f);
    if (unnamed) out->prev_command[0] = '\0';
    for (int i = 0; strcmp(out->prev_command, out->command) != 0 && i < out->prev_count; i++)
        if (out->prev[i].ours == 1) out->prev[i].ours = -2;
    return CS_OK;
}

/* DIR/.cablesim-manifest: the files written and those of the earlier manifest still cablesim's (not removed
 * by this commit), through a temporary and a rename. With both, also the earlier run's size and hash of the
 * names this commit writes: a name listed twice is cablesim's while it holds either run's file, so the
 * manifest is true whichever of the renames are done. */
static cs_status write_manifest(cs_outdir *out, int both, cs_error *err) {
    char tmp[PATH_SIZE], path[PATH_SIZE];
    full_path(out, CS_OUT_MANIFEST, path, sizeof path);
    int fd = begin_aside(out, "manifest", tmp);
    FILE *f = fd < 0 ? NULL : fdopen(fd, "w");
    if (!f) {
        cs_status st = cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errno));
        if (fd >= 0) close(fd), unlink(tmp);
        end_aside(out);
        return st;
    }
    fchmod(fd, (mode_t)out->mode);
    fprintf(f, MANIFEST_HEAD
            ", each with its size in bytes and the 64-bit FNV-1a hash of its bytes; the next "
            "run into it removes or replaces these while they are as written, and no other file\n");
    fprintf(f, "# written by: cablesim %s\n", out->command);
    for (int i = 0; i < out->count; i++)
        fprintf(f, "%s\t%lld\t%016llx\n", out->names[i], out->prints[i].size, out->prints[i].hash);
    for (int i = 0; i < out->prev_count; i++) {
        const cs_out_listed *e = &out->prev[i];
        if (e->ours == 1 && (both || !written(out, e->name)))
            fprintf(f, "%s\t%lld\t%016llx\n", e->name, e->print.size, e->print.hash);
    }
    int bad = fflush(f) != 0 || ferror(f) || fsync(fd) != 0;
    int errnum = errno;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path) != 0) {
        cs_status st = cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(bad ? errnum : errno));
        unlink(tmp);
        end_aside(out);
        return st;
    }
    end_aside(out);
    return CS_OK;
}

/* ---- what the folder holds ---- */

/* Whether name, a file's at depth (0 the folder, 1 a subfolder), is one of cablesim's temporaries: in the
 * folder or a subfolder of it (plots/), where outputs go, and named as begin and begin_aside name them,
 * ".cablesim-tmp.NAME." and mkstemp's six letters or digits. */
static int temporary(const char *name, int depth) {
    size_t n = strlen(name), p = sizeof tmp_prefix - 1;
    if (depth > 1 || n < p + 8 || strncmp(name, tmp_prefix, p) != 0 || name[n - 7] != '.') return 0;
    for (size_t i = n - 6; i < n; i++)
        if (!((name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
              (name[i] >= '0' && name[i] <= '9')))
            return 0;
    return 1;
}

/* The first file under DIR/rel that no manifest lists into found (1), else 0; -1 with err filled if a
 * folder cannot be read. Folders are walked, not followed through links; the lock, the manifest and
 * temporaries are cablesim's, and so is a sweep's journal to a sweep (to another command, the runs of a
 * sweep stopped before its outputs, kept as the user's files are); folders that hold no file are not files.
 * With remove, the temporaries a killed run left are removed instead (the folder is locked: no run is writing
 * them). */
static int scan(const cs_outdir *out, const char *rel, int depth, int remove, char *found, size_t found_size,
                cs_error *err) {
    char path[PATH_SIZE];
    if (rel[0])
        full_path(out, rel, path, sizeof path);
    else
        snprintf(path, sizeof path, "%s", out->dir);
    DIR *d = opendir(path);
    if (!d) {
        cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errno));
        return -1;
    }
    int rc = 0;
    struct dirent *e;
    while (rc == 0 && (e = readdir(d)) != NULL) {
        const char *name = e->d_name;
        if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0) continue;
        char sub[PATH_SIZE], full[PATH_SIZE];
        snprintf(sub, sizeof sub, "%s%s%s", rel, rel[0] ? "/" : "", name);
        full_path(out, sub, full, sizeof full);
        struct stat st;
        if (lstat(full, &st) != 0) continue; /* gone since */
        int ours = S_ISREG(st.st_mode) && temporary(name, depth);
        if (S_ISDIR(st.st_mode) && depth < MAX_DEPTH) {
            rc = scan(out, sub, depth + 1, remove, found, found_size, err);
        } else if (ours && remove) {
            unlink(full);
        } else if (!ours && !remove && !listed(out, sub) &&
                   !(!rel[0] &&
                     (strcmp(name, CS_OUT_MANIFEST) == 0 || strcmp(name, CS_OUT_LOCK) == 0 ||
                      (strcmp(name, CS_OUT_JOURNAL) == 0 && strcmp(out->command, "sweep") == 0)))) {
            snprintf(found, found_size, "%s", sub);
            rc = 1;
        }
    }
    closedir(d);
    return rc;
}

/* Refuse a folder holding a file no manifest lists (unless CS_OUT_FORCE; the refusal names force, the
 * caller's way to it, as cs_out_open says), else remove the temporaries a killed run left. */
static cs_status check_contents(cs_outdir *out, const char *force, cs_error *err) {
    if (out->flags & CS_OUT_FORCE) return CS_OK;
    char found[PATH_SIZE], why[PATH_SIZE], how[160];
    int rc = scan(out, "", 0, 0, found, sizeof found, err);
    if (force)
        snprintf(how, sizeof how, "write beside such files with %s (none of them is removed)", force);
    else
        snprintf(how, sizeof how, "move such files out of it");
    if (rc == 1)
        cs_error_set(err, CS_ERR_IO, "%s holds %s, which %s: choose another folder, or %s", out->dir, found,
                     not_ours(out, found, why, sizeof why), how);
    if (rc == 0) rc = scan(out, "", 0, 1, found, sizeof found, err);
    return rc == 0 ? CS_OK : CS_ERR_IO;
}

/* cs_out_open's folders made and lock taken, with signals held: both are known to the handler at once. */
static cs_status open_held(cs_outdir *out, const char *dir, const char *force, cs_error *err) {
    snprintf(out->dir, sizeof out->dir, "%s", dir);
    enlist(out);
    char part[1024];
    for (size_t i = 1; i <= strlen(dir); i++) {
        if ((dir[i] != '/' && dir[i] != '\0') || dir[i - 1] == '/') continue;
        snprintf(part, sizeof part, "%.*s", (int)i, dir);
        if (mkdir(part, 0777) == 0) {
            if (out->made < (int)(sizeof out->made_at / sizeof out->made_at[0]))
                out->made_at[out->made++] = (unsigned short)i;
        } else if (errno != EEXIST) {
            cs_out_abort(out);
            return cs_error_set(err, CS_ERR_IO, "%s: %s", part, strerror(errno));
        }
    }
    struct stat st;
    int found = stat(dir, &st) == 0;
    if (!found || !S_ISDIR(st.st_mode)) {
        cs_out_abort(out);
        return cs_error_set(err, CS_ERR_IO, "%s: %s", dir, strerror(found ? ENOTDIR : errno));
    }
    cs_status status = take_lock(out, force, err);
    if (status != CS_OK) cs_out_abort(out);
    return status;
}

cs_status cs_out_open(cs_outdir *out, const char *dir, const char *command, int flags, const char *force,
                      cs_error *err) {
    memset(out, 0, sizeof *out);
    out->lock = out->journal = -1;
    out->flags = flags;
    snprintf(out->command, sizeof out->command, "%s", command);
    mode_t mask = umask(0);
    umask(mask);
    out->mode = 0666u & ~(unsigned)mask;
    if (strlen(dir) >= sizeof out->dir - 80) {
        return cs_error_set(err, CS_ERR_INVALID, "%s: output path too long", dir);
    }
    sigset_t old;
    hold_signals(&old);
    cs_status status = open_held(out, dir, force, err);
    let_signals(&old);
    /* the manifest's files read and hashed with signals let through: a Ctrl-C is taken at once, and the
     * handler finds the folders made and the lock, all it removes */
    if (status == CS_OK) status = read_manifest(out, force, err);
    if (status == CS_OK) status = check_contents(out, force, err);
    if (status != CS_OK && out->lock >= 0) cs_out_abort(out);
    return status;
}

cs_status cs_out_subdir(cs_outdir *out, const char *subdir, cs_error *err) {
    char path[PATH_SIZE];
    full_path(out, subdir, path, sizeof path);
    struct stat st;
    sigset_t old;
    hold_signals(&old);
    int made = mkdir(path, 0777) == 0, errnum = errno;
    if (made && out->subdir_count < 8)
        snprintf(out->subdirs[out->subdir_count++], sizeof out->subdirs[0], "%s", subdir);
    let_signals(&old);
    if (!made && errnum != EEXIST) {
        return cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errnum));
    }
    if (lstat(path, &st) != 0 || !S_ISDIR(st.st_mode)) { /* a file, or a link to somewhere else */
        return cs_error_set(err, CS_ERR_IO, "%s: not a folder of this one (%s)", path, strerror(ENOTDIR));
    }
    return CS_OK;
}

/* Whether this run may put its file at DIR/name: nothing there, or the earlier run's file as written (then
 * *taken is 1, else 0). CS_OK, or CS_ERR_IO with err filled (a folder there, or a file of the user's, which
 * is kept). */
static cs_status place_free(const cs_outdir *out, const char *name, int *taken, cs_error *err) {
    char final[PATH_SIZE], why[PATH_SIZE];
    full_path(out, name, final, sizeof final);
    struct stat st;
    *taken = lstat(final, &st) == 0;
    if (!*taken) return CS_OK;
    if (S_ISDIR(st.st_mode)) return cs_error_set(err, CS_ERR_IO, "%s: %s", final, strerror(EISDIR));
    if (listed(out, name)) return CS_OK;
    return cs_error_set(err, CS_ERR_IO,
                        "%s: a file is there which %s: it is kept; remove it or write elsewhere", final,
                        not_ours(out, name, why, sizeof why));
}

/* A temporary beside DIR/name, open for writing (its descriptor), named into out. -1 with err filled. */
static int begin(cs_outdir *out, const char *name, cs_error *err) {
    char final[PATH_SIZE];
    if (out->count == CS_OUT_MAX_FILES) {
        cs_error_set(err, CS_ERR_MEMORY, "too many output files");
        return -1;
    }
    if (strlen(name) >= sizeof out->names[0] || !inside(name)) {
        cs_error_set(err, CS_ERR_INVALID, "%s/%s: not a name for an output file", out->dir, name);
        return -1;
    }
    full_path(out, name, final, sizeof final);
    int taken;
    if (place_free(out, name, &taken, err) != CS_OK) return -1;
    const char *slash = strrchr(name, '/');
    int head = slash ? (int)(slash - name + 1) : 0;
    char *rel = out->tmps[out->count];
    snprintf(rel, sizeof out->tmps[0], "%.*s%s%s.XXXXXX", head, name, tmp_prefix, name + head);
    snprintf(out->names[out->count], sizeof out->names[0], "%s", name);
    sigset_t old;
    hold_signals(&old);
    int fd = make_temp(out, rel);
    if (fd >= 0) out->count++;
    let_signals(&old);
    if (fd < 0) {
        cs_error_set(err, CS_ERR_IO, "%s: %s", final, strerror(errno));
        return -1;
    }
    fchmod(fd, (mode_t)out->mode);
    return fd;
}

/* The stream of an output file: its descriptor's writes, each error's errno kept (the first) so that the
 * file's end says why, whatever a writer did with errno since. On an error it returns what it wrote, 0 if
 * nothing: fopencookie(3) takes no negative count (glibc then counts -1 byte written and reads past the
 * caller's buffer). */
static ssize_t stream_write(void *cookie, const char *buf, size_t size) {
    int *c = cookie; /* {fd, first errno} */
    size_t done = 0;
    while (done < size) {
        ssize_t n = write(c[0], buf + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            if (!c[1]) c[1] = errno;
            return (ssize_t)done;
        }
        done += (size_t)n;
    }
    return (ssize_t)done;
}

static int stream_close(void *cookie) {
    return close(((int *)cookie)[0]);
}

/* CABLESIM_TEST_DEV_FULL=NAME (for tests): the file NAME is written to /dev/full, as a full disk would
 * take it (every write fails with ENOSPC). */
static void test_dev_full(int fd, const char *name) {
    const char *full = getenv("CABLESIM_TEST_DEV_FULL");
    int dev = full && strcmp(full, name) == 0 ? open("/dev/full", O_WRONLY) : -1;
    if (dev >= 0) dup2(dev, fd), close(dev);
}

FILE *cs_out_begin(cs_outdir *out, const char *name, cs_error *err) {
    int fd = begin(out, name, err);
    if (fd < 0) return NULL;
    test_dev_full(fd, name);
    int *c = out->streams[out->count - 1];
    c[0] = fd;
    c[1] = 0;
    FILE *f = fopencookie(c, "w", (cookie_io_functions_t){NULL, stream_write, NULL, stream_close});
    if (!f) {
        cs_error_set(err, CS_ERR_IO, "%s/%s: %s", out->dir, name, strerror(errno));
        close(fd);
    }
    return f;
}

cs_status cs_out_begin_path(cs_outdir *out, const char *name, char *path, size_t path_size, cs_error *err) {
    cs_error own;
    int fd = begin(out, name, err ? err : &own);
    if (fd < 0) return err ? err->status : own.status;
    close(fd);
    full_path(out, out->tmps[out->count - 1], path, path_size);
    return CS_OK;
}

static cs_status end_failed(const cs_outdir *out, int i, int errnum, cs_error *err) {
    return cs_error_set(err, CS_ERR_IO, "%s/%s: %s", out->dir, out->names[i], strerror(errnum));
}

/* Start writing fd's data to the disk, not waiting for it: cs_out_commit's fsync of each file then waits
 * for writes already under way, and the system can put the files' blocks in one journal commit rather than
 * one a file. Its errors are the fsync's to report. */
static void start_writeback(int fd) {
    sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
}

cs_status cs_out_end_at(cs_outdir *out, int i, FILE *f, cs_error *err) {
    int *c = out->streams[i];
    int bad = fflush(f) != 0 || ferror(f);
    int errnum = c[1] ? c[1] : errno; /* the first write's error, else the flush's */
    if (!bad) start_writeback(c[0]);
    bad |= fclose(f) != 0;
    return bad ? end_failed(out, i, errnum ? errnum : errno, err) : CS_OK;
}

cs_status cs_out_finish(cs_outdir *out, FILE *f, cs_status status, cs_error *err) {
    /* a failed end is the cause, in err: which file, and the system's reason */
    cs_status end = cs_out_end(out, f, err);
    return end != CS_OK ? end : status;
}

cs_status cs_out_end(cs_outdir *out, FILE *f, cs_error *err) {
    return cs_out_end_at(out, out->count - 1, f, err);
}

/* The i-th file's temporary opened, then sync (fsync, or start_writeback when wait is 0). CS_OK, or
 * CS_ERR_IO with err filled (the file and the system's reason). */
static cs_status sync_file(const cs_outdir *out, int i, int wait, cs_error *err) {
    char path[PATH_SIZE];
    full_path(out, out->tmps[i], path, sizeof path);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return end_failed(out, i, errno, err);
    int bad = 0, errnum = 0;
    if (wait)
        bad = fsync(fd) != 0, errnum = errno;
    else
        start_writeback(fd);
    close(fd);
    return bad ? end_failed(out, i, errnum, err) : CS_OK;
}

cs_status cs_out_end_path(cs_outdir *out, cs_error *err) {
    return sync_file(out, out->count - 1, 0, err);
}

/* fsync DIR/rel (a folder), so that the renames in it last. */
static void sync_folder(const cs_outdir *out, const char *rel, int len) {
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/%.*s", out->dir, len, rel);
    int fd = open(path, O_RDONLY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

/* How cs_out_commit put a file at its name: where no file was; exchanged with the earlier run's file, which
 * waits under the temporary's name; renamed over it (a file system that cannot exchange). */
enum { PUT_NEW = 1, PUT_SWAPPED, PUT_OVER };

/* Put the temporary tmp at final, a name that held no file at the commit's look: the system refuses to
 * replace one put there since (renameat2's RENAME_NOREPLACE, or where the file system has no such rename,
 * link and unlink, which refuse too), so a file the user saves in that instant is kept. PUT_NEW, or -errno
 * (-EEXIST: something is there now). */
static int put_new(const char *tmp, const char *final) {
    if (renameat2(AT_FDCWD, tmp, AT_FDCWD, final, RENAME_NOREPLACE) == 0) return PUT_NEW;
    if (errno != EINVAL && errno != ENOSYS) return -errno;
    if (link(tmp, final) != 0) return -errno;
    unlink(tmp);
    return PUT_NEW;
}

/* Remove the earlier run's file e, a file (not a folder) in a folder of this one (not through a link):
 * moved aside to a temporary in its folder, then checked against its print, so that a file the user wrote
 * there since the commit's look goes back to its name (e->ours 0: the user's) and no instant is left in
 * which it could be removed. 0: removed, kept as the user's, or not there; else the errno of the failed
 * removal, with err filled only when the user's file could not be put back. */
static int remove_earlier(const cs_outdir *out, cs_out_listed *e, cs_error *err) {
    char path[PATH_SIZE], aside[PATH_SIZE], rel[PATH_SIZE];
    struct stat st;
    const char *slash = strrchr(e->name, '/');
    for (const char *s = strchr(e->name, '/'); s; s = strchr(s + 1, '/')) {
        snprintf(path, sizeof path, "%s/%.*s", out->dir, (int)(s - e->name), e->name);
        if (lstat(path, &st) != 0 || !S_ISDIR(st.st_mode)) return 0;
    }
    full_path(out, e->name, path, sizeof path);
    if (lstat(path, &st) != 0 || S_ISDIR(st.st_mode)) return 0;
    snprintf(rel, sizeof rel, "%.*s%sgone.XXXXXX", slash ? (int)(slash - e->name) + 1 : 0, e->name,
             tmp_prefix);
    int fd = make_temp(out, rel);
    if (fd < 0) return errno;
    close(fd);
    full_path(out, rel, aside, sizeof aside);
    if (rename(path, aside) != 0) {
        int errnum = errno;
        unlink(aside);
        return errnum == ENOENT ? 0 : errnum;
    }
    cs_out_print now;
    if (fingerprint(aside, &now) == 0 && now.size == e->print.size && now.hash == e->print.hash)
        return unlink(aside) == 0 || errno == ENOENT ? 0 : errno;
    e->ours = 0;
    int put = put_new(aside, path);
    if (put == PUT_NEW) return 0;
    cs_error_set(
        err, CS_ERR_IO,
        "%s: written during the commit, and it could not be put back at its name (%s): it is now %s, "
        "which the next run into this folder removes as a temporary: move it back first",
        path, strerror(-put), aside);
    return -put;
}

/* Put tmp at final, the i-th name, over the earlier run's file there (as written at the commit's look):
 * exchanged with it (RENAME_EXCHANGE), the earlier file kept under tmp's name until the commit ends, for
 * take_back; where the file system cannot exchange, checked against its print once more and renamed over
 * it (-EEXIST if the user wrote over it since). How (put_new's way if the earlier file has gone since), or
 * -errno. */
static int put_over(const cs_outdir *out, int i, const char *tmp, const char *final) {
    if (renameat2(AT_FDCWD, tmp, AT_FDCWD, final, RENAME_EXCHANGE) == 0) return PUT_SWAPPED;
    if (errno == ENOENT) return put_new(tmp, final);
    if (errno != EINVAL && errno != ENOSYS) return -errno;
    const cs_out_listed *e = find(out, out->names[i]);
    if (!e || !as_written(out, e)) return -EEXIST;
    return rename(tmp, final) == 0 ? PUT_OVER : -errno;
}

/* Whether the file exchanged out of the i-th name to tmp is the earlier run's as the commit looked at it: a
 * file the user put at that name in the instant between the look and the exchange is not. */
static int swapped_out_earlier(const cs_outdir *out, int i, const char *tmp) {
    const cs_out_listed *e = find(out, out->names[i]);
    cs_out_print now;
    return e && e->ours == 1 && fingerprint(tmp, &now) == 0 && now.size == e->print.size &&
           now.hash == e->print.hash;
}

/* The user's file, exchanged out of the i-th name to tmp, put back at its name, this run's under tmp (which
 * cs_out_abort removes). -EEXIST, for undo; where the system will not exchange them back, CS_ERR_IO with
 * err saying where each is, the temporary kept (its name taken off the list of those to remove). */
static int put_back(cs_outdir *out, int i, const char *tmp, const char *final, cs_error *err) {
    if (renameat2(AT_FDCWD, final, AT_FDCWD, tmp, RENAME_EXCHANGE) == 0) return -EEXIST;
    int errnum = errno;
    out->in_place = -1;
    out->tmps[i][0] = '\0';
    cs_error_set(err, CS_ERR_IO,
                 "%s: something appeared there during the commit, which could not be put back (%s): it is "
                 "now %s, and this run's file is at its name: move it back",
                 final, strerror(errnum), tmp);
    return 0;
}

/* The i-th file, put in place the way how, taken back: its name holds what it held before the commit again,
 * this run's file its temporary's name (cs_out_abort removes it). 0, or -1: the name keeps this run's file
 * (the earlier one was not kept, or the system refused). */
static int take_back(const cs_outdir *out, int i, int how) {
    char tmp[PATH_SIZE], final[PATH_SIZE];
    full_path(out, out->tmps[i], tmp, sizeof tmp);
    full_path(out, out->names[i], final, sizeof final);
    if (how == PUT_SWAPPED) return renameat2(AT_FDCWD, final, AT_FDCWD, tmp, RENAME_EXCHANGE);
    return how == PUT_NEW ? rename(final, tmp) : -1;
}

/* The failed-th file could not be put in place (errnum): the files put before it taken back, so that the
 * folder holds the earlier run's results, whole. CS_ERR_IO with err saying why, and, when some of this run's
 * files could not be taken back (out->in_place -1), which are in place and what to do. The manifest lists
 * both runs' files, true either way; one the commit wrote where there was none goes with the files taken
 * back (fresh: no earlier manifest), so that a folder "nothing written" holds nothing of this run's. */
static cs_status undo(cs_outdir *out, int failed, int errnum, const int *put, int fresh, cs_error *err) {
    char why[CS_MESSAGE_SIZE], more[40] = "";
    full_path(out, out->names[failed], why, sizeof why);
    size_t n = strlen(why);
    if (errnum == EEXIST)
        snprintf(why + n, sizeof why - n,
                 ": something appeared there during the commit, which is kept: move it away and run again");
    else
        snprintf(why + n, sizeof why - n, ": %s", strerror(errnum));
    int left = 0, first = 0;
    for (int i = failed - 1; i >= 0; i--)
        if (take_back(out, i, put[i]) != 0) left++, first = i;
    if (!left) {
        char manifest[PATH_SIZE];
        full_path(out, CS_OUT_MANIFEST, manifest, sizeof manifest);
        if (fresh && unlink(manifest) == 0) sync_folder(out, "", 0);
        return cs_error_set(err, CS_ERR_IO, "%s", why);
    }
    out->in_place = -1;
    if (left > 1) snprintf(more, sizeof more, " (and %d more)", left - 1);
    return cs_error_set(err, CS_ERR_IO,
                        "%s; %s holds this run's %s%s, the rest as before the command: run it again to write "
                        "them all",
                        why, out->dir, out->names[first], more);
}

/* cs_out_commit once every file is on the disk: the manifests and the renames. */
static cs_status put_in_place(cs_outdir *out, cs_error *err) {
    char tmp[PATH_SIZE], final[PATH_SIZE];
    int taken[CS_OUT_MAX_FILES], put[CS_OUT_MAX_FILES];
    cs_status st = CS_OK;
    /* the folder as it is now, not as cs_out_open found it: an earlier file edited during the run, or a
     * file the user put where this run writes, is the user's */
    for (int i = 0; i < out->prev_count; i++)
        if (out->prev[i].ours == 1) out->prev[i].ours = as_written(out, &out->prev[i]);
    for (int i = 0; st == CS_OK && i < out->count; i++)
        st = place_free(out, out->names[i], &taken[i], err);
    /* the manifest first names both runs' files, so that every file cablesim put here stays its own */
    char manifest[PATH_SIZE];
    struct stat was;
    full_path(out, CS_OUT_MANIFEST, manifest, sizeof manifest);
    int fresh = lstat(manifest, &was) != 0;
    if (st == CS_OK) st = write_manifest(out, 1, err);
    if (st != CS_OK) return st;
    for (int i = 0; i < out->count; i++) {
        full_path(out, out->tmps[i], tmp, sizeof tmp);
        full_path(out, out->names[i], final, sizeof final);
        put[i] = taken[i] ? put_over(out, i, tmp, final) : put_new(tmp, final);
        if (put[i] == PUT_SWAPPED && !swapped_out_earlier(out, i, tmp)) {
            put[i] = put_back(out, i, tmp, final, err);
            if (!put[i]) return CS_ERR_IO;
        }
        if (put[i] < 0) return undo(out, i, -put[i], put, fresh, err);
    }
    for (int i = 0; i < out->count; i++) { /* the earlier run's files exchanged out */
        full_path(out, out->tmps[i], tmp, sizeof tmp);
        if (put[i] == PUT_SWAPPED) unlink(tmp);
    }
    out->in_place = 1;
    /* the earlier run's files this run does not write, removed; one that cannot be stays in the manifest,
     * cablesim's for the next run to remove; one the user wrote over since the look is the user's */
    int removed = 0, kept = 0, kept_at = 0, kept_errno = 0, users = 0;
    cs_error lost = {0};
    for (int i = 0; i < out->prev_count; i++) {
        const char *rel = out->prev[i].name, *slash = strrchr(rel, '/');
        if (out->prev[i].ours != 1 || written(out, rel)) continue;
        int errnum = remove_earlier(out, &out->prev[i], &lost);
        if (out->prev[i].ours == 0) {
            users++;
            continue;
        }
        if (errnum) {
            if (!kept++) kept_at = i, kept_errno = errnum;
            continue;
        }
        out->prev[i].ours = 2, removed++;
        if (slash) { /* a subfolder this left empty */
            full_path(out, rel, tmp, sizeof tmp);
            tmp[strlen(out->dir) + 1 + (size_t)(slash - rel)] = '\0';
            rmdir(tmp);
        }
    }
    /* the commit point: the manifest of this run's files and the earlier ones kept (the first already is,
     * when it named no name twice, removed no file and found none the user's since) */
    int twice = 0;
    for (int i = 0; i < out->prev_count; i++)
        twice |= out->prev[i].ours == 1 && written(out, out->prev[i].name);
    cs_error why;
    if ((removed || twice || users) && write_manifest(out, 0, &why) != CS_OK) {
        return cs_error_set(err, CS_ERR_IO, "the new results are in %s, but %s", out->dir, why.message);
    }
    if (out->journal >= 0) { /* this sweep's journal: its runs are in the outputs now */
        full_path(out, CS_OUT_JOURNAL, tmp, sizeof tmp);
        unlink(tmp);
    }
    sync_folder(out, "", 0);
    for (int i = 0; i < out->count; i++) {
        const char *slash = strrchr(out->names[i], '/');
        int len = slash ? (int)(slash - out->names[i]) : 0;
        if (len && (i == 0 || strncmp(out->names[i - 1], out->names[i], (size_t)len + 1) != 0))
            sync_folder(out, out->names[i], len);
    }
    char more[40] = "";
    if (kept > 1) snprintf(more, sizeof more, " (and %d more of its files)", kept - 1);
    if (lost.message[0]) {
        st = cs_error_set(err, CS_ERR_IO, "the new results are in %s, but %s", out->dir, lost.message);
    } else if (kept) {
        st = cs_error_set(err, CS_ERR_IO,
                          "the new results are in %s, but the earlier run's %s could not be removed: %s%s; "
                          "%s still lists it for the next run there to remove",
                          out->dir, out->prev[kept_at].name, strerror(kept_errno), more, CS_OUT_MANIFEST);
    }
    out->count = 0;
    out->made = out->subdir_count = 0; /* the folders hold a result now */
    release(out);
    delist(out);
    return st;
}

cs_status cs_out_commit(cs_outdir *out, cs_error *err) {
    cs_status st = CS_OK;
    char tmp[PATH_SIZE];
    for (int i = 0; st == CS_OK && i < out->count; i++) { /* every file on the disk before any is renamed */
        st = sync_file(out, i, 1, err);
        full_path(out, out->tmps[i], tmp, sizeof tmp);
        if (st == CS_OK && fingerprint(tmp, &out->prints[i]) != 0) st = end_failed(out, i, errno, err);
    }
    if (st != CS_OK) return st;
    /* a signal from here on is taken once the files are in place: it finds the folder as it was before
     * the command, or with the command's files, never with some of each */
    sigset_t old;
    hold_signals(&old);
    st = put_in_place(out, err);
    let_signals(&old);
    return st;
}

cs_status cs_out_fail(cs_outdir *out, cs_status status, cs_error *err) {
    cs_out_abort(out);
    if (err && !out->in_place) {
        char why[CS_MESSAGE_SIZE];
        memcpy(why, err->message, sizeof why);
        cs_error_set(err, status, "nothing written: %s", why);
    }
    return status;
}

void cs_out_abort(cs_outdir *out) {
    sigset_t old;
    hold_signals(&old);
    remove_uncommitted(out);
    if (out->lock >= 0) close(out->lock); /* its file removed above */
    out->lock = -1;
    out->count = out->subdir_count = out->made = 0;
    end_aside(out);
    release(out);
    delist(out);
    let_signals(&old);
}

/* ---- a sweep's journal ---- */

/* Write all of text to fd and fsync it. 0, or -1 with errno set. */
static int write_all_sync(int fd, const char *text, size_t len) {
    while (len > 0) {
        ssize_t n = write(fd, text, len);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return -1;
        text += n, len -= (size_t)n;
    }
    return fsync(fd);
}

/* Whether the file at path, if any, may be replaced by a journal: none there, or one that begins as a
 * journal does. 1, else 0 (a file of the user's, or not a regular file). */
static int journal_replaceable(const char *path) {
    char head[sizeof CS_OUT_JOURNAL_HEAD - 1];
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return errno == ENOENT;
    struct stat st;
    int ok = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
             pread(fd, head, sizeof head, 0) == (ssize_t)sizeof head &&
             memcmp(head, CS_OUT_JOURNAL_HEAD, sizeof head) == 0;
    close(fd);
    return ok;
}

cs_status cs_out_journal_start(cs_outdir *out, const char *text, size_t len, cs_error *err) {
    char tmp[PATH_SIZE], path[PATH_SIZE];
    full_path(out, CS_OUT_JOURNAL, path, sizeof path);
    if (!journal_replaceable(path))
        return cs_error_set(err, CS_ERR_IO,
                            "%s: not a journal of cablesim's (a file of yours): it is kept, with or without "
                            "force, and the sweep cannot keep its journal beside it: move it away, or write "
                            "elsewhere",
                            path);
    int fd = begin_aside(out, "journal", tmp);
    if (fd < 0 || fchmod(fd, (mode_t)out->mode) != 0 || write_all_sync(fd, text, len) != 0 ||
        rename(tmp, path) != 0) {
        cs_status st = cs_error_set(err, CS_ERR_IO, "%s: %s", path, strerror(errno));
        if (fd >= 0) close(fd), unlink(tmp);
        end_aside(out);
        return st;
    }
    end_aside(out);
    sync_folder(out, "", 0);
    if (out->journal >= 0) close(out->journal);
    out->journal = fd; /* the renamed file: appends go on at its end */
    return CS_OK;
}

cs_status cs_out_journal_add(cs_outdir *out, const char *text, size_t len, cs_error *err) {
    if (out->journal < 0 || write_all_sync(out->journal, text, len) != 0) {
        char path[PATH_SIZE];
        full_path(out, CS_OUT_JOURNAL, path, sizeof path);
        return cs_error_set(err, CS_ERR_IO, "%s: %s", path, out->journal < 0 ? "not open" : strerror(errno));
    }
    return CS_OK;
}

char *cs_out_journal_read(const char *dir, size_t *len, cs_error *err) {
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/%s", dir, CS_OUT_JOURNAL);
    char *text = NULL;
    int errnum = 0;
    cs_error reason;
    cs_status_set(err, CS_OK, "");
    if (cs_input_load(path, (size_t)2 << 30, &text, len, &errnum, &reason) != CS_OK) {
        if (errnum != ENOENT) cs_error_set(err, CS_ERR_IO, "%s: %s", path, reason.message);
        return NULL;
    }
    while (*len > 0 && text[*len - 1] != '\n') /* a row cut short by a kill */
        text[--*len] = '\0';
    return text;
}
