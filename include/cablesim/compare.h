/* SPDX-License-Identifier: MIT */
/** @file
 * Runs side by side, as `cablesim compare` puts them (docs/tutorial.md): folders written by `cablesim run`
 * (their summary.json and timeseries.csv) and at most one measured time history (a CSV file whose header
 * names each column with its unit), read back, their response parameters each with its difference from
 * the reference (the measured history if there is one, else the first run), and the files the command
 * writes: compare.csv, compare.md, compare.html, plots/compare-*.png and .svg, and with a measured history
 * metrics.csv (NCHRP W179's validation metrics). */
#ifndef CABLESIM_COMPARE_H
#define CABLESIM_COMPARE_H

#include <stdio.h>

#include "cablesim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The most runs a comparison takes (beside a measured history). */
enum { CS_COMPARE_MAX_RUNS = 12 };

/** What to compare. Start it from cs_default_compare_def(), which sets its size; new fields go at its end. */
typedef struct cs_compare_def {
    size_t size;             /**< the size of this struct in the program (cs_default_compare_def sets it) */
    const char *const *runs; /**< the run folders, as `cablesim run -o` wrote them */
    int run_count;           /**< how many: 1 to CS_COMPARE_MAX_RUNS */
    const char *measured;    /**< a measured history (CSV), the reference; NULL: none, the first run is */
    const char *force_given; /**< the command-line option that stands for CS_COMPARE_FORCE, as the user
                                  gives it ("--force"), which cs_compare_write's refusal of a folder holding
                                  files no manifest lists names as the way to write beside them; NULL: the
                                  refusal names CS_COMPARE_FORCE */
} cs_compare_def;

/** A comparison: the runs and the measured history read back (opaque). */
typedef struct cs_compare cs_compare;

/** A def with no runs and no measured history, its size set (inline: the program's size, def.h). */
static inline cs_compare_def cs_default_compare_def(void) {
    cs_compare_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    return d;
}

/** Read every run of def and its measured history; nothing is written.
 * @param def what to compare (read to its size)
 * @param out the comparison, to free with cs_compare_free (NULL on failure)
 * @param err filled on failure (may be NULL)
 * @return CS_OK; CS_ERR_INVALID for a def of a size this library does not know, or no run or more than
 *         CS_COMPARE_MAX_RUNS; CS_ERR_IO for a run folder or measured file that cannot be read, the message
 *         naming it and why (the system's reason, or "FILE:LINE:COLUMN: what is wrong" there). */
CS_API cs_status cs_compare_create(const cs_compare_def *def, cs_compare **out, cs_error *err);
/** Free a comparison. NULL is allowed. */
CS_API void cs_compare_free(cs_compare *compare);

/** The number of its histories: the runs, in def's order, then the measured one if any. */
CS_API int cs_compare_count(const cs_compare *compare);
/** The index of the reference: the measured history if there is one, else 0 (the first run). */
CS_API int cs_compare_reference(const cs_compare *compare);
/** History i's label (its folder or file as def gave it), or NULL if there is none i. */
CS_API const char *cs_compare_label(const cs_compare *compare, int i);
/** Run i's outcome as its summary.json names it ("stopped", "breakthrough", ...); "" for the measured
 * history; NULL if there is none i. */
CS_API const char *cs_compare_outcome(const cs_compare *compare, int i);

/** The number of response parameters compared: compare.csv's rows after its outcome, in their order. */
CS_API int cs_compare_parameter_count(void);

/** One response parameter of one history, as a row of compare.csv gives it. */
typedef struct cs_compare_row {
    size_t size;       /**< the size of this struct in the program: set it (cs_compare_row r =
                            {.size = sizeof r}); the library fills only that much */
    const char *name;  /**< the parameter, as compare.csv's first column ("max 50-ms deceleration") */
    const char *unit;  /**< its SI unit, as compare.csv's second column ("g", "m", "m/s", "N", "s") */
    double value;      /**< the history's value in that unit; NAN where it gives none (compare.csv: empty) */
    double difference; /**< its difference from the reference, per cent of the reference's magnitude;
                            NAN for the reference itself, where either gives no value, for a lower bound
                            (the penetration beyond of a vehicle through) or a reference of 0 */
} cs_compare_row;

/** Fill out with parameter `parameter` (0 to cs_compare_parameter_count() - 1) of history i, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such parameter or history, or out's size
 *         0 or larger than this library's. */
CS_API cs_status cs_compare_get(const cs_compare *compare, int parameter, int i, cs_compare_row *out,
                                cs_error *err);

/** How cs_compare_write treats its folder. */
enum {
    CS_COMPARE_FORCE = 1 /**< write into a folder beside files no manifest lists (none of them is removed) */
};

/** Write the comparison into dir as `cablesim compare -o DIR` does: compare.csv, compare.md, compare.html,
 * plots/compare-*.png and .svg, and with a measured history metrics.csv; the files appear together, listed
 * in dir/.cablesim-manifest, and nothing is left if one fails.
 * @param compare the comparison
 * @param dir the folder (made if need be)
 * @param flags 0 or CS_COMPARE_FORCE
 * @param err filled on failure (may be NULL)
 * @return CS_OK, or CS_ERR_IO with err filled: "nothing written: " and why (also when dir is the folder of a
 *         run compared: writing there would remove that run's files), or, when the files are in place but an
 *         earlier comparison's file there could not be removed, "the new results are in DIR, but ..." naming
 *         it and why (it stays in the manifest, for the next comparison there to remove), or, when a rename
 *         failed and the system refused to take back those before it, "DIR/NAME: why; DIR holds this run's
 *         NAME2 (and N more), the rest as before the command: run it again to write them all". */
CS_API cs_status cs_compare_write(const cs_compare *compare, const char *dir, int flags, cs_error *err);

/** With a measured history: print each run's validation metrics against it (Sprague-Geers M, P, C, the
 * ANOVA mean and standard deviation of the residuals, W179's verdict) to f, as `cablesim compare` does;
 * nothing without one. */
CS_API void cs_compare_print_metrics(const cs_compare *compare, FILE *f);

#ifdef __cplusplus
}
#endif
#endif
