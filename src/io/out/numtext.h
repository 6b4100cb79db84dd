/* SPDX-License-Identifier: MIT */
/* A number as the CSV and JSON files give it: the text printf's "%.10g" gives, byte for byte, made
 * without printf's general formatting. A run's timeseries.csv holds some 10^5 numbers and printf spends
 * most of the writer's time parsing its format and converting through its multi-precision path. */
#ifndef CS_NUMTEXT_H
#define CS_NUMTEXT_H

enum { CS_G10_SIZE = 32 }; /* room for any "%.10g" text and its terminating NUL */

/* Write v as "%.10g" would into buf (NUL-terminated); the text's length. Exact for every double: the
 * 10 digits are the correctly rounded (ties to even, as glibc's printf in the default rounding mode)
 * decimal of v's exact binary value, computed with 128-bit integers; the few values whose scaling does not
 * fit them (below 1e-17 or above 1e36 in magnitude, subnormals, infinities, NaN) go through snprintf. */
int cs_g10(double v, char buf[CS_G10_SIZE]);

/* A time of a run (in s, no unit written) as the text outputs give it: at least 3 decimals and as many more,
 * up to 6, as it takes to show the time exactly (a run's times are whole numbers of steps, 0.5 ms by
 * default, summed with round-off below 1e-9 s): 0.437, 0.5345, 0.050. Returns buf. */
enum { CS_TIME_TEXT_SIZE = 32 };
const char *cs_time_text(double t, char buf[CS_TIME_TEXT_SIZE]);

#endif
