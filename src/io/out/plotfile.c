/* SPDX-License-Identifier: MIT */
/* A plot (plot.h) drawn on cairo's image, SVG or PDF surface and written to a file: PNG through cairo,
 * an SVG with its texts as <text> elements over the drawing, a PDF as cairo writes it. */
#define _POSIX_C_SOURCE 200809L
#include "plot.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cairo_lib.h"
#include "status.h"

static cairo_status_t to_file(void *closure, const unsigned char *data, unsigned int length) {
    return fwrite(data, 1, length, closure) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* An SVG: cairo's drawing with the texts (svg_text) before its closing tag, to f. */
static int write_svg(FILE *f, const char *svg, size_t svg_size, const char *texts, size_t texts_size) {
    const char *end = NULL;
    for (const char *q = svg; (q = strstr(q, "</svg>")) != NULL; q++)
        end = q;
    if (!end) return -1;
    size_t head = (size_t)(end - svg);
    return fwrite(svg, 1, head, f) == head && fwrite(texts, 1, texts_size, f) == texts_size &&
                   fwrite(end, 1, svg_size - head, f) == svg_size - head
               ? 0
               : -1;
}

/* Draw on a surface of format and write it to f; f NULL: an image, written nowhere, traced into log. */
static cs_status plot_write(FILE *f, cs_plot_format format, double width, double height, cs_plot_draw_fn draw,
                            const void *user, cs_plot_log *log, cs_error *err) {
    cs_status rc = cs_cairo_load(err);
    if (rc != CS_OK) return rc;
    cairo_surface_t *s;
    char *svg = NULL, *texts = NULL;
    size_t svg_size = 0, texts_size = 0;
    FILE *svg_mem = NULL, *text_mem = NULL;
    if (format == CS_PLOT_PNG)
        s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)ceil(width), (int)ceil(height));
    else if (format == CS_PLOT_SVG) {
        svg_mem = open_memstream(&svg, &svg_size);
        text_mem = open_memstream(&texts, &texts_size);
        if (!svg_mem || !text_mem) {
            if (svg_mem) fclose(svg_mem), free(svg);
            if (text_mem) fclose(text_mem), free(texts);
            return cs_status_set(err, CS_ERR_MEMORY, "out of memory for an svg");
        }
        s = cairo_svg_surface_create_for_stream(to_file, svg_mem, width, height);
        cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_PX);
    } else if (format == CS_PLOT_PDF)
        s = cairo_pdf_surface_create_for_stream(to_file, f, width, height);
    else {
        return cs_status_set(err, CS_ERR_INVALID, "unknown plot format (use .png, .svg or .pdf)");
    }
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    if (log) memset(log, 0, sizeof *log), log->width = width, log->height = height;
    cs_plot p = {cr, width, height, log, text_mem};
    rc = draw(&p, user, err);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (rc == 0 && st == CAIRO_STATUS_SUCCESS && format == CS_PLOT_PNG && f)
        st = cairo_surface_write_to_png_stream(s, to_file, f);
    cairo_surface_finish(s);
    if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(s);
    cairo_surface_destroy(s);
    if (format == CS_PLOT_SVG) {
        int closed = fclose(svg_mem) == 0 && fclose(text_mem) == 0;
        if (rc == 0 && st == CAIRO_STATUS_SUCCESS &&
            (!closed || write_svg(f, svg, svg_size, texts, texts_size) != 0))
            st = CAIRO_STATUS_WRITE_ERROR;
        free(svg), free(texts);
    }
    if (rc == CS_OK && st != CAIRO_STATUS_SUCCESS) {
        char message[CS_MESSAGE_SIZE];
        snprintf(message, sizeof message, "drawing a %s: %s", cs_plot_extension(format),
                 cairo_status_to_string(st));
        rc = cs_status_set(err, CS_ERR_IO, message);
    }
    return rc;
}

cs_status cs_plot_write(FILE *f, cs_plot_format format, double width, double height, cs_plot_draw_fn draw,
                        const void *user, cs_error *err) {
    return plot_write(f, format, width, height, draw, user, NULL, err);
}

cs_status cs_plot_trace(double width, double height, cs_plot_draw_fn draw, const void *user, cs_plot_log *log,
                        cs_error *err) {
    return plot_write(NULL, CS_PLOT_PNG, width, height, draw, user, log, err);
}

cs_status cs_plot_save(const char *path, double width, double height, cs_plot_draw_fn draw, const void *user,
                       cs_error *err) {
    char message[CS_MESSAGE_SIZE];
    cs_plot_format format = cs_plot_format_of(path);
    if (format == CS_PLOT_UNKNOWN) {
        snprintf(message, sizeof message, "%s: unknown plot format (use .png, .svg or .pdf)", path);
        return cs_status_set(err, CS_ERR_INVALID, message);
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        snprintf(message, sizeof message, "%s: %s", path, strerror(errno));
        return cs_status_set(err, CS_ERR_IO, message);
    }
    cs_status rc = cs_plot_write(f, format, width, height, draw, user, err);
    if (fclose(f) != 0 && rc == CS_OK) {
        snprintf(message, sizeof message, "%s: write error", path);
        rc = cs_status_set(err, CS_ERR_IO, message);
    }
    return rc;
}

void cs_plot_release(void) {
    if (!cs_cairo_loaded()) return;
    cairo_debug_reset_static_data();
    FcFini();
}
