/* Inside the writers of a run's outputs (cablesim/output.h): printing numbers that must be finite, JSON
 * strings, and the output folder with files added by the command (report.html). */
#ifndef CS_WRITERS_H
#define CS_WRITERS_H

#include <stdio.h>

#include "cablesim/loader.h"
#include "cablesim/output.h"
#include "outfile.h"
#include "record.h"

typedef struct cs_wout {
    FILE *f;
    int bad;       /* a non-finite number was met */
    char why[256]; /* where */
} cs_wout;

/* Print v with %.10g; a non-finite v is not printed and marks the output bad, naming what. */
void cs_w_num(cs_wout *w, double v, const char *what);
/* Print s as a JSON string literal (quotes, backslashes and control characters escaped). */
void cs_json_string(FILE *f, const char *s);

/* More files for cs_write_outputs_with to write into the folder before it commits (the command's
 * report.html): each begun on out. Returns 0, or -1 with why filled. */
typedef int (*cs_more_outputs)(cs_outdir *out, void *user, char *why, size_t why_size);
/* cs_write_outputs, with more (may be NULL) called after the others, its files committed with them. */
int cs_write_outputs_with(const char *dir, const cs_model_input *in, const cs_model *model,
                          const cs_state *state, const cs_record *rec, int flags, cs_more_outputs more,
                          void *user, char *why, size_t why_size);

#endif
