/* SPDX-License-Identifier: MIT */
/* cairo and fontconfig, loaded when the first plot is drawn (dynlib.h): the plot layer's files include this
 * in place of <cairo.h>, call cs_cairo_load, then cairo_* as usual. plot.h includes <cairo.h> alone, for
 * its types, so a program that links cairo itself (the plot tests) calls the library directly. */
#ifndef CS_IO_CAIRO_LIB_H
#define CS_IO_CAIRO_LIB_H

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include "dynlib.h"

#define CS_CAIRO_FUNCTIONS(X)                                                                                \
    X(cairo_arc)                                                                                             \
    X(cairo_clip) X(cairo_close_path) X(cairo_create) X(cairo_debug_reset_static_data) X(cairo_destroy)      \
        X(cairo_fill) X(cairo_fill_preserve) X(cairo_image_surface_create) X(cairo_line_to) X(cairo_move_to) \
            X(cairo_new_path) X(cairo_paint) X(cairo_pattern_add_color_stop_rgb)                             \
                X(cairo_pattern_create_linear) X(cairo_pattern_destroy)                                      \
                    X(cairo_pdf_surface_create_for_stream) X(cairo_rectangle) X(cairo_restore)               \
                        X(cairo_rotate) X(cairo_save) X(cairo_select_font_face) X(cairo_set_dash)            \
                            X(cairo_set_font_size) X(cairo_set_line_cap) X(cairo_set_line_join)              \
                                X(cairo_set_line_width) X(cairo_set_source) X(cairo_set_source_rgb)          \
                                    X(cairo_set_source_rgba) X(cairo_show_text) X(cairo_status)              \
                                        X(cairo_status_to_string) X(cairo_stroke) X(cairo_stroke_preserve)   \
                                            X(cairo_surface_destroy) X(cairo_surface_finish)                 \
                                                X(cairo_surface_status) X(cairo_surface_write_to_png_stream) \
                                                    X(cairo_svg_surface_create_for_stream)                   \
                                                        X(cairo_svg_surface_set_document_unit)               \
                                                            X(cairo_text_extents) X(cairo_text_path)         \
                                                                X(cairo_translate)

typedef struct cs_cairo_lib {
    CS_CAIRO_FUNCTIONS(CS_DYNLIB_FIELD)
} cs_cairo_lib;

typedef struct cs_fontconfig_lib {
    CS_DYNLIB_FIELD(FcFini)
} cs_fontconfig_lib;

extern cs_cairo_lib cs_cairo;
extern cs_fontconfig_lib cs_fontconfig;

/* cairo's functions and fontconfig's FcFini, loaded once (thread-safe): CS_OK; CS_ERR_IO with err filled
 * (dynlib.h). */
cs_status cs_cairo_load(cs_error *err);
/* Whether they are loaded: a program that drew no plot has no cairo to release. */
int cs_cairo_loaded(void);

#define cairo_arc (cs_cairo.cairo_arc)
#define cairo_clip (cs_cairo.cairo_clip)
#define cairo_close_path (cs_cairo.cairo_close_path)
#define cairo_create (cs_cairo.cairo_create)
#define cairo_debug_reset_static_data (cs_cairo.cairo_debug_reset_static_data)
#define cairo_destroy (cs_cairo.cairo_destroy)
#define cairo_fill (cs_cairo.cairo_fill)
#define cairo_fill_preserve (cs_cairo.cairo_fill_preserve)
#define cairo_image_surface_create (cs_cairo.cairo_image_surface_create)
#define cairo_line_to (cs_cairo.cairo_line_to)
#define cairo_move_to (cs_cairo.cairo_move_to)
#define cairo_new_path (cs_cairo.cairo_new_path)
#define cairo_paint (cs_cairo.cairo_paint)
#define cairo_pattern_add_color_stop_rgb (cs_cairo.cairo_pattern_add_color_stop_rgb)
#define cairo_pattern_create_linear (cs_cairo.cairo_pattern_create_linear)
#define cairo_pattern_destroy (cs_cairo.cairo_pattern_destroy)
#define cairo_pdf_surface_create_for_stream (cs_cairo.cairo_pdf_surface_create_for_stream)
#define cairo_rectangle (cs_cairo.cairo_rectangle)
#define cairo_restore (cs_cairo.cairo_restore)
#define cairo_rotate (cs_cairo.cairo_rotate)
#define cairo_save (cs_cairo.cairo_save)
#define cairo_select_font_face (cs_cairo.cairo_select_font_face)
#define cairo_set_dash (cs_cairo.cairo_set_dash)
#define cairo_set_font_size (cs_cairo.cairo_set_font_size)
#define cairo_set_line_cap (cs_cairo.cairo_set_line_cap)
#define cairo_set_line_join (cs_cairo.cairo_set_line_join)
#define cairo_set_line_width (cs_cairo.cairo_set_line_width)
#define cairo_set_source (cs_cairo.cairo_set_source)
#define cairo_set_source_rgb (cs_cairo.cairo_set_source_rgb)
#define cairo_set_source_rgba (cs_cairo.cairo_set_source_rgba)
#define cairo_show_text (cs_cairo.cairo_show_text)
#define cairo_status (cs_cairo.cairo_status)
#define cairo_status_to_string (cs_cairo.cairo_status_to_string)
#define cairo_stroke (cs_cairo.cairo_stroke)
#define cairo_stroke_preserve (cs_cairo.cairo_stroke_preserve)
#define cairo_surface_destroy (cs_cairo.cairo_surface_destroy)
#define cairo_surface_finish (cs_cairo.cairo_surface_finish)
#define cairo_surface_status (cs_cairo.cairo_surface_status)
#define cairo_surface_write_to_png_stream (cs_cairo.cairo_surface_write_to_png_stream)
#define cairo_svg_surface_create_for_stream (cs_cairo.cairo_svg_surface_create_for_stream)
#define cairo_svg_surface_set_document_unit (cs_cairo.cairo_svg_surface_set_document_unit)
#define cairo_text_extents (cs_cairo.cairo_text_extents)
#define cairo_text_path (cs_cairo.cairo_text_path)
#define cairo_translate (cs_cairo.cairo_translate)
#define FcFini (cs_fontconfig.FcFini)

#endif
