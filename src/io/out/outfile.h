/* Output files written atomically: each to DIR/name.tmp, flushed and fsync'ed, then all renamed at
 * once by cs_out_commit; cs_out_abort removes the temporaries (and the folders cs_out_open made) so a
 * failed run leaves nothing. A folder holds one run's outputs: on commit, the files of the command's
 * own names (cs_out_own) that this run did not write are removed, and nothing else. */
#ifndef CS_OUTFILE_H
#define CS_OUTFILE_H

#include <stdio.h>

enum { CS_OUT_MAX_FILES = 64 }; /* the data files, the plots and the pages */

typedef struct cs_outdir {
    char dir[1024];
    int count;
    char names[CS_OUT_MAX_FILES][128];
    const char *const *owned; /* the command's names (cs_out_own) */
    int owned_count;
    int made; /* the folders cs_out_open created: the last `made` prefixes of dir */
} cs_outdir;

/* Create dir (and its parents) and check that a file can be made in it, before anything is computed.
 * Returns 0, or -1 with why filled ("DIR: Not a directory"). */
int cs_out_open(cs_outdir *out, const char *dir, char *why, size_t why_size);
/* The names of every file the command can write in its folder: "summary.json", or a subfolder and an
 * extension, "plots" "/" "*.png", for every file of plots/ ending in .png. The list must outlive out. */
void cs_out_own(cs_outdir *out, const char *const *names, int count);
/* Create DIR/subdir, for files named "subdir/...". Returns 0, or -1 with why filled. */
int cs_out_subdir(cs_outdir *out, const char *subdir, char *why, size_t why_size);
/* Start DIR/name.tmp. NULL with why filled on failure (also a name longer than names hold). */
FILE *cs_out_begin(cs_outdir *out, const char *name, char *why, size_t why_size);
/* Flush, fsync and close a file from cs_out_begin: the last begun, or the i-th (files written side by
 * side). Returns 0, or -1 with why filled. */
int cs_out_end(cs_outdir *out, FILE *f, char *why, size_t why_size);
int cs_out_end_at(cs_outdir *out, int i, FILE *f, char *why, size_t why_size);
/* The same for a writer that opens its file by name (netCDF): DIR/name.tmp into path, and, once the writer
 * has closed it, cs_out_end_path fsyncs it. Each returns 0, or -1 with why filled. */
int cs_out_begin_path(cs_outdir *out, const char *name, char *path, size_t path_size, char *why,
                      size_t why_size);
int cs_out_end_path(cs_outdir *out, char *why, size_t why_size);
/* Rename every temporary to its name, then remove the files of the owned names this run did not write
 * (an earlier run's, and temporaries a killed run left), and a subfolder they leave empty. Returns 0, or
 * -1 with why filled. */
int cs_out_commit(cs_outdir *out, char *why, size_t why_size);
/* Remove the temporaries begun, and the folders cs_out_open made if they are empty. */
void cs_out_abort(cs_outdir *out);

#endif
