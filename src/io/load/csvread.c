/* SPDX-License-Identifier: MIT */
/* A CSV reader, a row at a time (csvread.h): a line at a time read whole, then cut into cells. */
#include "load/csvread.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "out/htmltext.h"

static void open_reader(cs_csv *r, FILE *f, const char *text, int flags, int max_cells) {
    memset(r, 0, sizeof *r);
    r->f = f, r->s = text, r->flags = flags, r->max_cells = max_cells;
}

void cs_csv_open_file(cs_csv *r, FILE *f, int flags, int max_cells) {
    open_reader(r, f, NULL, flags, max_cells);
}

void cs_csv_open_text(cs_csv *r, const char *text, int flags, int max_cells) {
    open_reader(r, NULL, text, flags, max_cells);
}

void cs_csv_close(cs_csv *r) {
    free(r->text), free(r->phys), free(r->off), free(r->cell), free(r->cell_line), free(r->cell_col);
    r->text = r->phys = NULL, r->off = NULL, r->cell = NULL, r->cell_line = NULL, r->cell_col = NULL;
}

static int problem(cs_csv *r, long line, int col, const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* Record why the row cannot be read, at line and col (col 0: of the file). Returns -1. */
static int problem(cs_csv *r, long line, int col, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->why, sizeof r->why, fmt, ap);
    va_end(ap);
    r->why_line = line, r->why_col = col;
    return -1;
}

/* Room for need bytes at *buf of *cap. 0, or -1 out of memory. */
static int room(char **buf, size_t *cap, size_t need) {
    if (need <= *cap) return 0;
    size_t n = *cap ? *cap : 256;
    while (n < need)
        n *= 2;
    char *more = realloc(*buf, n);
    if (!more) return -1;
    *buf = more, *cap = n;
    return 0;
}

/* The next line into r->phys without its '\n' (past max_line characters, only counted) and its length
 * into *len: 1, 0 at the end, or -1. */
static int read_line(cs_csv *r, size_t *len) {
    size_t n = 0, keep = r->max_line ? r->max_line + 1 : (size_t)-1;
    int c, any = 0;
    while ((c = r->f ? getc(r->f) : *r->s ? (unsigned char)*r->s++ : EOF) != EOF && c != '\n') {
        any = 1;
        if (n < keep && room(&r->phys, &r->phys_cap, n + 2) != 0)
            return problem(r, r->lines + 1, 0, "out of memory");
        if (n < keep) r->phys[n] = (char)c;
        n++;
    }
    if (r->f && ferror(r->f)) return problem(r, r->lines + 1, 0, "cannot read the file: %s", strerror(errno));
    if (c == EOF && !any) return 0;
    if (room(&r->phys, &r->phys_cap, 1) != 0) return problem(r, r->lines + 1, 0, "out of memory");
    r->phys[n < keep ? n : keep] = '\0';
    *len = n;
    r->lines++;
    if (r->max_line && n > r->max_line)
        return problem(r, r->lines, 1, "a line of more than %zu characters (expected shorter lines)",
                       r->max_line);
    return 1;
}

/* A cell beginning at text offset at, line and column col. 0, or -1 out of memory. */
static int begin_cell(cs_csv *r, size_t at, int col) {
    if (r->count == r->cap) {
        int cap = r->cap ? 2 * r->cap : 16;
        size_t *off = realloc(r->off, (size_t)cap * sizeof *off);
        if (off) r->off = off;
        long *line = off ? realloc(r->cell_line, (size_t)cap * sizeof *line) : NULL;
        if (line) r->cell_line = line;
        int *cols = line ? realloc(r->cell_col, (size_t)cap * sizeof *cols) : NULL;
        if (cols) r->cell_col = cols;
        char **cell = cols ? realloc(r->cell, (size_t)cap * sizeof *cell) : NULL;
        if (!cell) return problem(r, r->lines, 0, "out of memory");
        r->cell = cell, r->cap = cap;
    }
    r->off[r->count] = at, r->cell_line[r->count] = r->lines, r->cell_col[r->count] = col;
    r->count++;
    return 0;
}

static int put(cs_csv *r, size_t *n, char c) {
    if (room(&r->text, &r->text_cap, *n + 1) != 0) return problem(r, r->lines, 0, "out of memory");
    r->text[(*n)++] = c;
    return 0;
}

int cs_csv_next(cs_csv *r) {
    size_t len, n = 0;
    int rc;
    r->count = 0;
    do {
        if ((rc = read_line(r, &len)) <= 0) return rc;
        if (r->flags & CS_CSV_CR_ENDS) r->phys[len = strcspn(r->phys, "\r")] = '\0';
    } while (((r->flags & CS_CSV_COMMENTS) && r->phys[0] == '#') ||
             ((r->flags & CS_CSV_BLANKS) && (len == 0 || (len == 1 && r->phys[0] == '\r'))));
    r->line = r->lines;
    if (begin_cell(r, 0, 1) != 0) return -1;
    long open_line = 0;
    int open_col = 0, quoted = 0, closed = 0; /* closed: just past a quoted cell's closing quote */
    for (;;) {
        const char *p = r->phys;
        for (size_t i = 0; i < len; i++) {
            int line_end = p[i] == '\r' && i + 1 == len; /* a line's last \r is its CR LF's */
            if (closed && p[i] != ',' && !line_end)
                return problem(r, r->lines, (int)i + 1,
                               "'%c' after a quoted cell's closing quote (expected a comma or the end of "
                               "the line; a quote inside a quoted cell is doubled: \"\")",
                               p[i]);
            closed = 0;
            if (quoted && p[i] == '"') {
                if (i + 1 < len && p[i + 1] == '"') {
                    if (put(r, &n, p[i++]) != 0) return -1; /* a doubled quote: one quote */
                } else
                    quoted = 0, closed = 1;
            } else if (!quoted && p[i] == '"' && (r->flags & CS_CSV_QUOTED) && n == r->off[r->count - 1]) {
                quoted = 1, open_line = r->lines, open_col = (int)i + 1; /* only a cell's first character */
            } else if (!quoted && p[i] == ',' && !(r->count == r->max_cells && (r->flags & CS_CSV_REST))) {
                if (r->count == r->max_cells)
                    return problem(r, r->lines, (int)i + 2, "more than %d values", r->max_cells);
                if (put(r, &n, '\0') != 0 || begin_cell(r, n, (int)i + 2) != 0) return -1;
            } else if (quoted || !line_end) {
                if (put(r, &n, p[i]) != 0) return -1;
            }
        }
        if (!quoted) break;
        if (put(r, &n, '\n') != 0) return -1; /* a line break inside quotes */
        if ((rc = read_line(r, &len)) < 0) return -1;
        if (rc == 0)
            return problem(r, open_line, open_col,
                           "a quoted cell not closed (expected a closing \" before the end of the file)");
    }
    if (put(r, &n, '\0') != 0) return -1;
    for (int k = 0; k < r->count; k++) {
        r->cell[k] = r->text + r->off[k];
        if (r->flags & CS_CSV_UNTEXT) cs_csv_untext(r->cell[k]);
    }
    return 1;
}
