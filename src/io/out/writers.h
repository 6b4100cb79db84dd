/* Writers of a run's outputs: timeseries.csv, events.csv, summary.json and the readable summary.
 * A writer never prints NaN or infinity: it stops at the first one and says where it was. */
#ifndef CS_WRITERS_H
#define CS_WRITERS_H

#include <stdio.h>

#include "load/loader.h"
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

/* Each returns 0, or -1 with why filled. */
int cs_write_timeseries(FILE *f, const cs_record *rec, char *why, size_t why_size);
int cs_write_events(FILE *f, const cs_state *state, char *why, size_t why_size);
int cs_write_summary_json(FILE *f, const cs_model_input *in, const cs_model *model, const cs_state *state,
                          char *why, size_t why_size);
/* The readable summary (SI and US units side by side). */
void cs_write_report(FILE *f, const cs_model_input *in, const cs_model *model, const cs_state *state);

#endif
