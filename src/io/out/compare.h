/* Several runs, and a measured history, side by side (`cablesim compare`): overlays of the deceleration
 * (raw and 50-ms), the speed, the penetration and the largest rope tension against time, and a table of
 * the response parameters with each one's difference from the reference (the measured history if there
 * is one, else the first run). */
#ifndef CS_COMPARE_H
#define CS_COMPARE_H

#include <stddef.h>

#include "load/runread.h"
#include "out/outfile.h"

/* Into out: compare.csv and compare.md (the table), plots/compare-<response>.png and .svg, and
 * compare.html (the table and the plots in one page that opens from disk). traces[reference] is the
 * reference. Returns 0, or -1 with why filled. */
int cs_compare_write(cs_outdir *out, const cs_trace *traces, int count, int reference, char *why,
                     size_t why_size);

#endif
