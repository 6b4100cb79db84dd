/* SPDX-License-Identifier: MIT */
/* A CSV reader, a row at a time, over a file or a NUL-terminated text: cells cut at commas, quoted cells
 * (RFC 4180: a quote as a cell's first character opens it, a quote not doubled closes it, and commas,
 * doubled quotes and line breaks inside quotes are the cell's; a quote further into a cell is a character
 * like any other, and anything but a comma or the line's end after a closing quote is a problem) where
 * the caller asks, the ' a writer puts before a text that looks like a formula undone where it asks, '#'
 * comment lines and blank lines skipped where it asks. Each cell keeps the line and column it starts at,
 * so that a caller's message can be "file:line:column: what and why"; a row that cannot be read gives its
 * own, the same way. */
#ifndef CS_CSVREAD_H
#define CS_CSVREAD_H

#include <stddef.h>
#include <stdio.h>

enum {
    CS_CSV_QUOTED = 1 << 0,   /* '"' quotes a cell (else it is a character like any other) */
    CS_CSV_UNTEXT = 1 << 1,   /* undo the ' before a text that looks like a formula (cs_csv_untext) */
    CS_CSV_COMMENTS = 1 << 2, /* skip a line that begins with '#' */
    CS_CSV_BLANKS = 1 << 3,   /* skip an empty line */
    CS_CSV_REST = 1 << 4,     /* past max_cells, the last cell holds the rest of the row, commas and all */
    CS_CSV_CR_ENDS = 1 << 5   /* a CR ends a line's text, what follows it on the line not read (unquoted) */
};

typedef struct cs_csv {
    /* set by cs_csv_open_file / _text; flags, max_cells and max_line may be changed between rows */
    int flags;
    int max_cells;   /* the most cells of a row: more is a problem, or the rest (CS_CSV_REST) */
    size_t max_line; /* the most characters of a line, its '\n' aside (0: any) */
    /* the row last read */
    int count;       /* its cells */
    char **cell;     /* each NUL-terminated */
    long *cell_line; /* the line each begins on, 1-based */
    int *cell_col;   /* and its column, 1-based */
    long line;       /* the line the row begins on */
    /* the problem of a row that could not be read: where, and what and why (no file name) */
    long why_line;
    int why_col; /* 0: of the file, not of a place in it */
    char why[160];
    /* the source and the reader's own */
    FILE *f;
    const char *s;
    long lines; /* read so far */
    char *text, *phys;
    size_t text_cap, phys_cap;
    size_t *off;
    int cap;
} cs_csv;

/* A reader of f (left open by cs_csv_close) or of text (kept by the caller while read). */
void cs_csv_open_file(cs_csv *r, FILE *f, int flags, int max_cells);
void cs_csv_open_text(cs_csv *r, const char *text, int flags, int max_cells);
/* The next row into r->count, r->cell...: 1, 0 at the end, or -1 with r->why, r->why_line and
 * r->why_col (a line too long, too many cells, a quote not closed, out of memory, a read error). */
int cs_csv_next(cs_csv *r);
void cs_csv_close(cs_csv *r);

#endif
