/* SPDX-License-Identifier: MIT */
/* Text and figures into an HTML page: the pages cablesim writes (report.html, a comparison, a study)
 * escape every name and label they take from a model, a spec or the command line, and hold their figures
 * inline as SVG. */
#ifndef CS_HTML_H
#define CS_HTML_H

#include <stdio.h>

#include "out/htmltext.h"
#include "out/plot.h"

/* A width x height figure drawn by draw, inline as SVG. Its ids (cairo's glyphs and clip paths) take the
 * prefix `id`, so that several figures in one page do not take each other's. Returns CS_OK, or as
 * cs_plot_write (CS_ERR_MEMORY: no room for the figure). */
cs_status cs_html_figure(FILE *f, const char *id, double width, double height, cs_plot_draw_fn draw,
                         const void *user, cs_error *err);

#endif
