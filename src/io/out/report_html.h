/* SPDX-License-Identifier: MIT */
/* report.html: one self-contained page (no network) with the run's summary, its failure timeline,
 * interactive plots and a 3D replay. The page itself (HTML, CSS and the bundled JavaScript of report/)
 * is built from report/ by esbuild and compiled into the command as cs_report_page (only when the build
 * found node and npm: CS_HAVE_REPORT); this writer fills its markers with the run's data:
 *   @CS_TITLE@  the model's name, HTML-escaped
 *   @CS_DATA@   the run as one JSON object (cs_write_report_json), safe inside <script>. */
#ifndef CS_REPORT_HTML_H
#define CS_REPORT_HTML_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/loader.h"
#include "record.h"
#include "writers.h"

/* Defined by the generated source of a build with the report (CMake: report/). */
extern const unsigned char cs_report_page[];
extern const size_t cs_report_page_size;

/* Limits of the data blob: the plotted series keep at most CS_REPORT_SERIES_MAX frames, the replay
 * as many frames as fit in about CS_REPORT_REPLAY_BYTES (at least CS_REPORT_REPLAY_MIN, at most
 * CS_REPORT_REPLAY_MAX); the first and last frames are always kept. */
enum {
    CS_REPORT_SERIES_MAX = 4000,
    CS_REPORT_REPLAY_BYTES = 3000000,
    CS_REPORT_REPLAY_MIN = 200,
    CS_REPORT_REPLAY_MAX = 1500
};

/* The run as JSON: where it came from (version, command line, overrides, model hash: info, which may be
 * NULL), summary, ratings, scenario, vehicle, barrier, events, series (plots) and frames (replay), all in
 * SI, and last "units": the unit of every number, shaped as the data, so that the data read on its own
 * (saved, or in the page's source) says what its numbers are. Each is written as the CSVs write units
 * (docs/file-format.md: "m/s^2", "N m", "g", "deg", "1" a pure number), "" for a number without one (a
 * count, an index, a state, a flag: the CSVs' columns named alone). An object's units are an object of
 * its keys; a list's are one unit for every number in it, or a list U whose element i % |U| gives the
 * units of the list's element i: a tuple's units (a post [x, height, rotation limit]), a tuple repeated
 * along a flat list (a frame's posts' [x, y, z, status]), or one entry for each element (each event,
 * whose value's unit is its type's). Every '<', '>' and '&' is escaped, so the text can stand inside a
 * <script> element. Returns CS_OK, or
 * CS_ERR_IO with err filled (a non-finite number where one must be finite, a write error), or
 * CS_ERR_MEMORY. */
cs_status cs_write_report_json(FILE *f, const cs_model_input *in, const cs_state *state, const cs_record *rec,
                               const cs_run_info *info, cs_error *err);
/* The same data as a json-c document (jsondoc.h; to put), or NULL with err filled (CS_ERR_IO: a
 * non-finite number; CS_ERR_MEMORY). */
struct json_object *cs_report_json(const cs_model_input *in, const cs_state *state, const cs_record *rec,
                                   const cs_run_info *info, cs_error *err);

/* Writes a page's data at its @CS_DATA@ marker: CS_OK, or a failure's status with err filled. */
typedef cs_status (*cs_page_data_fn)(FILE *f, void *user, cs_error *err);
/* A page built from report/ (size bytes) with its markers filled: @CS_TITLE@ with title HTML-escaped,
 * @CS_DATA@ by data(user). what names the page in messages. Returns CS_OK, or data's failure, or CS_ERR_IO
 * with err filled (no data marker, a write error). */
cs_status cs_write_page(FILE *f, const unsigned char *page, size_t size, const char *title, const char *what,
                        cs_page_data_fn data, void *user, cs_error *err);

/* The page (size bytes, with the markers above) with its markers filled. Returns as cs_write_page. */
cs_status cs_write_report_html(FILE *f, const unsigned char *page, size_t size, const cs_model_input *in,
                               const cs_state *state, const cs_record *rec, const cs_run_info *info,
                               cs_error *err);

#endif
