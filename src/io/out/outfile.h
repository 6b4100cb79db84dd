/* Output files written atomically: each to DIR/name.tmp, flushed and fsync'ed, then all renamed at
 * once by cs_out_commit; cs_out_abort removes the temporaries so a failed run leaves nothing. */
#ifndef CS_OUTFILE_H
#define CS_OUTFILE_H

#include <stdio.h>

enum { CS_OUT_MAX_FILES = 64 }; /* the data files, the plots and the pages */

typedef struct cs_outdir {
    char dir[1024];
    int count;
    char names[CS_OUT_MAX_FILES][128];
    int created_count; /* the subdirectories cs_out_subdir made, which an abort removes again */
    char created[4][64];
} cs_outdir;

/* Create dir (and its parents). Returns 0, or -1 with why filled. */
int cs_out_open(cs_outdir *out, const char *dir, char *why, size_t why_size);
/* Create DIR/subdir, for files named "subdir/...": removed by cs_out_abort if it made it. Returns 0, or -1
 * with why filled. */
int cs_out_subdir(cs_outdir *out, const char *subdir, char *why, size_t why_size);
/* Start DIR/name.tmp. NULL with why filled on failure (also a name longer than names hold). */
FILE *cs_out_begin(cs_outdir *out, const char *name, char *why, size_t why_size);
/* Flush, fsync and close a file from cs_out_begin. Returns 0, or -1 with why filled. */
int cs_out_end(cs_outdir *out, FILE *f, char *why, size_t why_size);
/* The same for a writer that opens its file by name (netCDF): DIR/name.tmp into path, and, once the writer
 * has closed it, cs_out_end_path fsyncs it. Each returns 0, or -1 with why filled. */
int cs_out_begin_path(cs_outdir *out, const char *name, char *path, size_t path_size, char *why,
                      size_t why_size);
int cs_out_end_path(cs_outdir *out, char *why, size_t why_size);
/* Rename every temporary to its name. Returns 0, or -1 with why filled. */
int cs_out_commit(cs_outdir *out, char *why, size_t why_size);
void cs_out_abort(cs_outdir *out);

#endif
