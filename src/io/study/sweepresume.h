/* SPDX-License-Identifier: MIT */
/* A sweep's record of its study, for --resume (sweepresume.c): what the study (sweepstudy.c) writes
 * before its runs and reads back from a stopped sweep's folder. */
#ifndef CS_SWEEPRESUME_H
#define CS_SWEEPRESUME_H

#include <limits.h>
#include <stddef.h>

#include "study/sweepstudy.h"

typedef struct cs_sweep_resumed {
    char version[64], model_hash[20], inputs_hash[20];
    char spec_as_given[PATH_MAX], cwd[PATH_MAX]; /* the spec as the stopped sweep's command line gave it */
    int partial;
    char *journal;      /* DIR/.cablesim-journal, when a killed sweep left one (NULL: none) */
    const char *rows;   /* its runs.csv, after its first line */
    size_t rows_length; /* their length */
} cs_sweep_resumed;

/* {"spec": the spec's absolute path, "spec_as_given" and the "cwd" it was given in, "runs", "seed", "set":
 * the command line's fixed values, "netcdf", "allow": the --allow-path folders, absolute}, allocated
 * (NULL if memory is short). */
char *cs_sweep_resume_record(const cs_sweep_options *o, const char *as_given, const char *cwd);
/* The record of the study into o (its strings kept in static storage) and r: the first line of
 * DIR/.cablesim-journal when a sweep killed before it wrote its outputs left one (r->journal), else
 * DIR/summary.json's. CS_OK, or with err filled CS_ERR_IO (no journal or summary to read: the path and
 * the system's reason) or CS_ERR_INVALID (none with a record of the study). */
cs_status cs_sweep_resume_read(const char *dir, cs_sweep_options *o, cs_sweep_resumed *r, cs_error *err);
/* The runs of DIR/runs.csv, or of the journal a killed sweep left, into all (the others left pending),
 * after checking that the study is the one DIR holds. Returns how many were read, or -1 (why said:
 * cs_sweep_say). */
long cs_sweep_resume_runs(const char *dir, const cs_sweep_spec *spec, const cs_sweep_resumed *was,
                          const double *x, cs_sweep_result *all, long n, cs_sweep_options *o);
/* The runs a stopped study in dir saved, which --resume reads back and a new study there would replace:
 * the rows of DIR/.cablesim-journal when there is one (a sweep killed before its outputs; or one running,
 * unless the caller holds the folder's lock), else DIR/summary.json's "runs_done" when it is "partial"; 0
 * when dir holds neither (or they cannot be read). *where: the file of dir that holds those runs. */
long cs_sweep_stopped_runs(const char *dir, const char **where);

#endif
