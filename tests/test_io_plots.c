/* SPDX-License-Identifier: MIT */
/* Plots: the plotting layer puts a known value on the expected pixel and keeps a label inside its frame
 * at every corner, and every figure of a synthetic run comes out as a PNG of the stated size that is not
 * blank, and as well-formed SVG and PDF; traced, every text of every figure lies inside its frame (a
 * label inside its plotting area, the rest inside the figure), the time axes end at the run's end (and
 * compare's at the end of the last trace it shows), the top views are at true scale with the whole
 * vehicle in them, and the posts' legend names a post that is the mirror image of another; the set written
 * through an output directory is complete and leaves no temporaries. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "out/compare.h"
#include "out/figures.h"
#include "out/plot.h"

enum { FRAMES = 300, CABLES = 2, POSTS = 6 };
static const double PI = 3.14159265358979323846, G0 = 9.80665;

/* ---- files ---- */

typedef struct tmpdir {
    char path[64];
} tmpdir;

static void tmp_make(tmpdir *d) {
    snprintf(d->path, sizeof d->path, "/tmp/cs_plots_XXXXXX");
    assert_non_null(mkdtemp(d->path));
}

static void tmp_file(const tmpdir *d, const char *name, char *out, size_t size) {
    int n = snprintf(out, size, "%s/%s", d->path, name);
    assert_true(n > 0 && (size_t)n < size);
}

/* Remove DIR/name for every name, then DIR/plots and DIR. */
static void tmp_remove(const tmpdir *d, const char *const *names, int count) {
    char p[256];
    for (int i = 0; i < count; i++) {
        tmp_file(d, names[i], p, sizeof p);
        unlink(p);
    }
    tmp_file(d, "plots", p, sizeof p);
    rmdir(p);
    rmdir(d->path);
}

/* The whole file into a malloc'ed buffer; *size its length. */
static unsigned char *slurp(const char *path, long *size) {
    FILE *f = fopen(path, "rb");
    if (!f) fail_msg("%s: cannot open", path);
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = malloc((size_t)*size + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)*size, f), (size_t)*size);
    buf[*size] = 0;
    fclose(f);
    return buf;
}

/* A PNG of width x height (from its IHDR) whose pixels are not all alike (variance of grey level). */
static void check_png(const char *path, int width, int height) {
    long size;
    unsigned char *b = slurp(path, &size);
    static const unsigned char magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    assert_true(size > 33);
    assert_memory_equal(b, magic, 8);
    assert_memory_equal(b + 12, "IHDR", 4);
    uint32_t w = (uint32_t)b[16] << 24 | (uint32_t)b[17] << 16 | (uint32_t)b[18] << 8 | b[19];
    uint32_t h = (uint32_t)b[20] << 24 | (uint32_t)b[21] << 16 | (uint32_t)b[22] << 8 | b[23];
    free(b);
    if ((int)w != width || (int)h != height)
        fail_msg("%s is %ux%u, expected %dx%d", path, w, h, width, height);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    assert_int_equal(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    const unsigned char *px = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    double sum = 0, sum2 = 0, ink = 0, n = (double)width * height;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const unsigned char *p = px + (size_t)y * (size_t)stride + 4 * (size_t)x;
            double g = (p[0] + p[1] + p[2]) / 3.0;
            sum += g, sum2 += g * g, ink += g < 200;
        }
    cairo_surface_destroy(s);
    double var = sum2 / n - (sum / n) * (sum / n);
    if (!(var > 100)) fail_msg("%s looks blank: grey-level variance %g", path, var);
    if (!(ink / n > 0.01)) fail_msg("%s has almost no ink: %.2f %% dark pixels", path, 100 * ink / n);
}

static void check_svg(const char *path) {
    long size;
    char *b = (char *)slurp(path, &size);
    assert_true(size > 100);
    assert_memory_equal(b, "<?xml", 5);
    assert_non_null(strstr(b, "<svg"));
    long end = size;
    while (end > 0 && (b[end - 1] == '\n' || b[end - 1] == ' '))
        end--;
    if (end < 6 || memcmp(b + end - 6, "</svg>", 6) != 0) fail_msg("%s does not end with </svg>", path);
    /* its texts are text an editor edits, not glyphs' outlines */
    if (!strstr(b, "</text>") || strstr(b, "glyph")) fail_msg("%s: texts drawn as glyphs, not <text>", path);
    free(b);
}

static void check_pdf(const char *path) {
    long size;
    char *b = (char *)slurp(path, &size);
    assert_true(size > 100);
    assert_memory_equal(b, "%PDF-", 5);
    long end = size;
    while (end > 0 && (b[end - 1] == '\n' || b[end - 1] == '\r'))
        end--;
    if (end < 5 || memcmp(b + end - 5, "%%EOF", 5) != 0) fail_msg("%s does not end with %%%%EOF", path);
    free(b);
}

/* ---- the plotting layer ---- */

static void test_nice_step(void **state) {
    (void)state;
    assert_float_equal(cs_plot_nice_step(0, 7.3, 6), 2, 1e-12);
    assert_float_equal(cs_plot_nice_step(0, 0.189, 4), 0.05, 1e-12);
    assert_float_equal(cs_plot_nice_step(-500, 1200, 7), 500, 1e-9);
    assert_float_equal(cs_plot_nice_step(3, 3, 5), 1, 0); /* an empty range still has a step */
}

static void test_format_of(void **state) {
    (void)state;
    assert_int_equal(cs_plot_format_of("a/b/speed.png"), CS_PLOT_PNG);
    assert_int_equal(cs_plot_format_of("x.svg"), CS_PLOT_SVG);
    assert_int_equal(cs_plot_format_of("x.pdf"), CS_PLOT_PDF);
    assert_int_equal(cs_plot_format_of("x.jpg"), CS_PLOT_UNKNOWN);
    assert_int_equal(cs_plot_format_of(".png"), CS_PLOT_UNKNOWN);
    assert_string_equal(cs_plot_extension(CS_PLOT_SVG), "svg");
}

/* A panel over x in [0, 10], y in [0, 4] with a red horizontal line at y = 2.5 and a blue vertical line
 * at x = 7; the drawing's plotting area comes back through the user pointer. */
typedef struct known_lines {
    cs_box *area;
} known_lines;

static cs_status draw_known(cs_plot *p, const void *user, cs_error *err) {
    (void)err;
    const known_lines *k = user;
    cs_axes a;
    cs_axes_init(&a, "known lines", "x (m)", "y (kN)");
    cs_axes_set_x(&a, 0, 10);
    cs_axes_set_y(&a, 0, 4);
    cs_axes_layout(p, &a, (cs_box){0, 0, p->width, p->height});
    const double x[] = {0, 10}, y[] = {2.5, 2.5}, vx[] = {7, 7}, vy[] = {0, 4};
    cs_style red = {{1, 0, 0}, 2, CS_SOLID, CS_MARK_NONE, 0},
             blue = {{0, 0, 1}, 2, CS_SOLID, CS_MARK_NONE, 0};
    cs_plot_line(p, &a, x, y, 2, &red, "y = 2.5");
    cs_plot_line(p, &a, vx, vy, 2, &blue, NULL);
    *k->area = a.area;
    return CS_OK;
}

/* Mean pixel centre along a scan of the pixels that are mostly of channel ch (cairo RGB24 is B, G, R). */
static double centre_of(cairo_surface_t *s, int fixed, int vertical, int ch) {
    const unsigned char *px = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    int n = vertical ? cairo_image_surface_get_height(s) : cairo_image_surface_get_width(s);
    double sum = 0, count = 0;
    for (int i = 0; i < n; i++) {
        const unsigned char *p = vertical ? px + (size_t)i * (size_t)stride + 4 * (size_t)fixed
                                          : px + (size_t)fixed * (size_t)stride + 4 * (size_t)i;
        int others = ch == 2 ? p[0] + p[1] : p[1] + p[2];
        if (p[ch] > 200 && others < 160) sum += i + 0.5, count++;
    }
    if (count == 0) fail_msg("no pixels of the line along %s %d", vertical ? "column" : "row", fixed);
    return sum / count;
}

static void test_known_value_lands_on_its_pixel(void **state) {
    (void)state;
    tmpdir d;
    tmp_make(&d);
    char path[256];
    tmp_file(&d, "known.png", path, sizeof path);
    cs_box area = {0, 0, 0, 0};
    known_lines k = {&area};
    cs_error err;
    if (cs_plot_save(path, 640, 400, draw_known, &k, &err) != CS_OK) fail_msg("%s", err.message);
    check_png(path, 640, 400);
    /* the area is a real part of the picture */
    assert_true(area.x > 20 && area.y > 10 && area.w > 400 && area.h > 250);
    assert_true(area.x + area.w < 640 && area.y + area.h < 400);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    double row = area.y + (4 - 2.5) / 4 * area.h, col = area.x + 7.0 / 10 * area.w;
    double got_row = centre_of(s, (int)(area.x + 0.3 * area.w), 1, 2);
    double got_col = centre_of(s, (int)(area.y + 0.5 * area.h + 7), 0, 0);
    cairo_surface_destroy(s);
    if (fabs(got_row - row) > 1) fail_msg("y = 2.5 drawn at row %.2f, expected %.2f", got_row, row);
    if (fabs(got_col - col) > 1) fail_msg("x = 7 drawn at column %.2f, expected %.2f", got_col, col);
    const char *names[] = {"known.png", "known.svg", "known.pdf"};
    for (int f = 1; f < 3; f++) {
        tmp_file(&d, names[f], path, sizeof path);
        if (cs_plot_save(path, 640, 400, draw_known, &k, &err) != CS_OK) fail_msg("%s", err.message);
        (f == 1 ? check_svg : check_pdf)(path);
    }
    tmp_file(&d, "known.txt", path, sizeof path);
    assert_int_equal(cs_plot_save(path, 640, 400, draw_known, &k, &err), CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "unknown plot format"));
    tmp_remove(&d, names, 3);
}

/* Every text of a traced drawing inside its frame (half a pixel of slack), none left out of the log. */
static void check_texts_inside(const cs_plot_log *log, const char *what) {
    if (log->text_count > CS_PLOT_LOG_TEXTS)
        fail_msg("%s: %d texts, more than the log keeps", what, log->text_count);
    for (int i = 0; i < log->text_count; i++) {
        const cs_plot_logged_text *t = &log->text[i];
        const cs_box *b = &t->box, *f = &t->frame;
        if (b->x < f->x - 0.5 || b->y < f->y - 0.5 || b->x + b->w > f->x + f->w + 0.5 ||
            b->y + b->h > f->y + f->h + 0.5)
            fail_msg("%s: '%s' at x %.1f-%.1f, y %.1f-%.1f is not inside its frame x %.1f-%.1f, y %.1f-%.1f",
                     what, t->text, b->x, b->x + b->w, b->y, b->y + b->h, f->x, f->x + f->w, f->y,
                     f->y + f->h);
    }
}

/* Every legend inside a plotting area covers no cell of its data, markers or notes. */
static void check_legends_clear(const cs_plot_log *log, const char *what) {
    for (int i = 0; i < log->legend_count && i < CS_PLOT_LOG_LEGENDS; i++)
        if (log->legend[i].inside && log->legend[i].covered != 0)
            fail_msg("%s: its legend at x %.0f, y %.0f covers %d cells of data", what, log->legend[i].box.x,
                     log->legend[i].box.y, log->legend[i].covered);
}

/* Labels at the four corners of a panel and at its middle, each offset outward. */
static cs_status draw_corner_labels(cs_plot *p, const void *user, cs_error *err) {
    (void)user, (void)err;
    cs_axes a;
    cs_axes_init(&a, "labels", "x (m)", "y (kN)");
    cs_axes_set_x(&a, 0, 10);
    cs_axes_set_y(&a, 0, 4);
    cs_axes_layout(p, &a, (cs_box){0, 0, p->width, p->height});
    const double at[][4] = {
        {0, 0, -12, 16}, {10, 0, 12, 16}, {0, 4, -12, -16}, {10, 4, 12, -16}, {5, 2, 12, -16}};
    for (int k = 0; k < 5; k++)
        for (int align = 0; align <= 2; align++)
            cs_plot_label(p, &a, at[k][0], at[k][1], at[k][2], at[k][3], 0.5 * align,
                          "a long note: max 3.55 g at t = 0.418 s");
    return CS_OK;
}

static void test_labels_stay_inside_the_frame(void **state) {
    (void)state;
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    cs_error err;
    if (cs_plot_trace(640, 400, draw_corner_labels, NULL, log, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(log->panel_count, 1);
    assert_int_equal(log->text_count > 15, 1);
    int labels = 0;
    for (int i = 0; i < log->text_count; i++)
        labels += strncmp(log->text[i].text, "a long note", 11) == 0 &&
                  memcmp(&log->text[i].frame, &log->panel[0].area, sizeof(cs_box)) == 0;
    assert_int_equal(labels, 15);
    check_texts_inside(log, "corner labels");
    free(log);
}

/* ---- the figures of a synthetic run ---- */

/* A 2000-kg car at 10 m/s head-on into two cables on six posts, decelerating at a steady 2 g: cable 0
 * breaks at 0.2 s, the two middle posts hinge at 0.1 s and fail at 0.25 s, the car stops at the end. */
typedef struct synthetic {
    cs_cable_def cables[CABLES];
    cs_post_def posts[POSTS];
    cs_model_input in;
    cs_record rec;
    cs_event events[8];
    cs_figure_data d;
    tmpdir dir; /* where its figures go */
} synthetic;

static synthetic *synthetic_new(int frames) {
    synthetic *s = calloc(1, sizeof *s);
    assert_non_null(s);
    for (int c = 0; c < CABLES; c++) {
        s->cables[c] = cs_default_cable_def();
        s->cables[c].height = 0.6 + 0.3 * c;
        s->cables[c].rope = cs_default_rope_def();
        s->cables[c].rope.nominal_strength = 500e3;
    }
    static const double px[POSTS] = {5, 10, 17, 23, 30, 35};
    for (int p = 0; p < POSTS; p++) {
        s->posts[p] = cs_default_post_def();
        s->posts[p].x = px[p];
        s->posts[p].height = 1.2;
        s->posts[p].rotation_limit = PI / 4;
    }
    cs_model_input *in = &s->in;
    in->size = sizeof *in;
    in->name = "synthetic";
    in->file = "synthetic.yaml";
    in->barrier = cs_default_barrier_def();
    in->barrier.cable_count = CABLES;
    in->barrier.cables = s->cables;
    in->barrier.post_count = POSTS;
    in->barrier.posts = s->posts;
    in->barrier.start_anchor.x = 0;
    in->barrier.end_anchor.x = 40;
    in->vehicle = cs_default_vehicle_def();
    cs_vehicle_def *v = &in->vehicle;
    v->mass = 2000, v->cg_height = 0.6, v->cg_to_front = 2.0, v->front_width = 1.8, v->face_bottom = 0.3;
    v->face_top = 0.9, v->wheelbase = 2.8, v->cg_to_front_axle = 1.1, v->track = 1.5;
    v->cg_to_rear = 2.5, v->side_bottom = 0.3, v->side_top = 1.0;
    in->scenario = cs_default_scenario_def();
    in->scenario.speed = 10, in->scenario.angle = PI / 2, in->scenario.impact_x = 20, in->scenario.dt = 5e-4;

    cs_record *r = &s->rec;
    r->cable_count = CABLES, r->post_count = POSTS, r->max_nodes = POSTS + 4;
    r->frame_count = r->capacity = frames;
    size_t n = (size_t)(frames > 0 ? frames : 1), nn = (size_t)r->max_nodes;
    r->vehicle = calloc(n, sizeof *r->vehicle);
    r->energy = calloc(n, sizeof *r->energy);
    r->cables = calloc(n * CABLES, sizeof *r->cables);
    r->posts = calloc(n * POSTS, sizeof *r->posts);
    r->path_count = calloc(n * CABLES, sizeof *r->path_count);
    r->path_xyz = calloc(n * CABLES * nn * 3, sizeof *r->path_xyz);
    r->path_tension = calloc(n * CABLES * nn, sizeof *r->path_tension);
    assert_true(r->vehicle && r->energy && r->cables && r->posts && r->path_count && r->path_xyz &&
                r->path_tension);
    double a = 2 * G0, u0 = 10, ke0 = 0.5 * v->mass * u0 * u0;
    for (int i = 0; i < frames; i++) {
        double t = i * 1e-3, u = u0 - a * t, y = -v->cg_to_front + u0 * t - 0.5 * a * t * t;
        cs_vehicle_view *vv = &r->vehicle[i];
        vv->t = t;
        vv->position[0] = 20, vv->position[1] = y, vv->position[2] = v->cg_height;
        vv->velocity[1] = vv->forward_speed = u;
        vv->acceleration[1] = -a;
        vv->yaw = PI / 2;
        vv->decel_50ms_g = t > 0.05 ? 2 : 0;
        vv->crush = fmin(0.2, t);
        double face = y + v->cg_to_front - vv->crush;
        for (int k = 0; k < 2; k++)
            vv->front_corners[k][0] = 20 + (k ? -0.9 : 0.9), vv->front_corners[k][1] = face,
            vv->front_corners[k][2] = 0.6;
        vv->penetration = fmax(0, face);
        vv->face_force = face > 0 ? 1e5 : 0;
        cs_energy *e = &r->energy[i];
        e->size = sizeof *e;
        e->initial_kinetic = e->initial_total = ke0;
        e->vehicle_kinetic = 0.5 * v->mass * u * u;
        double gone = ke0 - e->vehicle_kinetic;
        e->crush = 0.4 * gone, e->post_plastic = 0.3 * gone, e->cable_elastic = 0.2 * gone,
        e->friction = 0.1 * gone;
        for (int c = 0; c < CABLES; c++) {
            size_t k = (size_t)i * CABLES + (size_t)c;
            int broken = c == 0 && t >= 0.2;
            double tension = broken ? 0 : 20e3 + 1.5e6 * t * (c ? 0.5 : 1);
            r->cables[k].status = broken ? CS_CABLE_BROKEN : CS_CABLE_INTACT;
            r->cables[k].engaged = face > 0;
            r->cables[k].max_tension = tension;
            r->cables[k].node_count = r->path_count[k] = 4;
            const double pts[4][2] = {{0, 0}, {19.1, fmax(0, face)}, {20.9, fmax(0, face)}, {40, 0}};
            for (int j = 0; j < 4; j++) {
                double *q = r->path_xyz + (k * nn + (size_t)j) * 3;
                q[0] = pts[j][0], q[1] = pts[j][1], q[2] = s->cables[c].height;
                if (j < 3) r->path_tension[k * nn + (size_t)j] = tension;
            }
        }
        for (int p = 0; p < POSTS; p++) {
            cs_post_view *pv = &r->posts[(size_t)i * POSTS + (size_t)p];
            int middle = p == 2 || p == 3;
            pv->tilt = middle ? fmin(0.8, 3.2 * t) : 0.02 * t;
            pv->status = !middle || t < 0.1 ? CS_POST_ELASTIC
                         : t < 0.25         ? CS_POST_HINGED
                                            : CS_POST_FAILED_ROTATION;
            pv->moment_capacity = 8e3;
            pv->base_moment = fmin(8e3, 8e4 * pv->tilt);
            pv->top[0] = px[p], pv->top[1] = 1.2 * sin(pv->tilt), pv->top[2] = 1.2 * cos(pv->tilt);
        }
    }
    const cs_event ev[] = {
        {sizeof(cs_event), 0.1, CS_EVENT_POST_HINGE, CS_ELEMENT_POST, 2, 8e3, -1, -1, -1},
        {sizeof(cs_event), 0.1, CS_EVENT_POST_HINGE, CS_ELEMENT_POST, 3, 8e3, -1, -1, -1},
        {sizeof(cs_event), 0.2, CS_EVENT_CABLE_BREAK, CS_ELEMENT_CABLE, 0, 320e3, -1, -1, -1},
        {sizeof(cs_event), 0.25, CS_EVENT_POST_ROTATION_LIMIT, CS_ELEMENT_POST, 2, 0.8, -1, -1, -1},
        {sizeof(cs_event), 0.25, CS_EVENT_POST_ROTATION_LIMIT, CS_ELEMENT_POST, 3, 0.8, -1, -1, -1},
        {sizeof(cs_event), 0.27, CS_EVENT_OVERRIDE, CS_ELEMENT_CABLE, 1, 0.27, -1, -1, -1},
        {sizeof(cs_event), 0.299, CS_EVENT_STOPPED, CS_ELEMENT_VEHICLE, 0, 0.3, -1, -1, -1},
    };
    memcpy(s->events, ev, sizeof ev);
    s->d = (cs_figure_data){&s->in, &s->rec, s->events, (int)(sizeof ev / sizeof ev[0]), NULL, NULL, NULL};
    tmp_make(&s->dir);
    return s;
}

static void synthetic_free(synthetic *s, const char *const *names, int count) {
    tmp_remove(&s->dir, names, count);
    cs_record_release(&s->rec);
    free(s);
}

static void write_every_figure(int frames) {
    synthetic *s = synthetic_new(frames);
    char names[CS_FIG_COUNT * 3][64];
    const char *list[CS_FIG_COUNT * 3];
    for (int k = 0; k < CS_FIG_COUNT; k++)
        for (int f = 0; f < 3; f++) {
            char path[256];
            snprintf(names[3 * k + f], sizeof names[0], "%s.%s", cs_figure_name((cs_figure)k),
                     cs_plot_extension((cs_plot_format)f));
            list[3 * k + f] = names[3 * k + f];
            tmp_file(&s->dir, names[3 * k + f], path, sizeof path);
            FILE *out = fopen(path, "wb");
            assert_non_null(out);
            cs_error err;
            if (cs_figure_write(out, (cs_plot_format)f, (cs_figure)k, &s->d, &err) != CS_OK)
                fail_msg("%s: %s", names[3 * k + f], err.message);
            assert_int_equal(fclose(out), 0);
            double w, h;
            cs_figure_size((cs_figure)k, &s->d, &w, &h);
            if (f == CS_PLOT_PNG)
                check_png(path, (int)ceil(w), (int)ceil(h));
            else
                (f == CS_PLOT_SVG ? check_svg : check_pdf)(path);
        }
    synthetic_free(s, list, CS_FIG_COUNT * 3);
}

static void test_every_figure_of_a_run(void **state) {
    (void)state;
    write_every_figure(FRAMES);
}

static void test_runs_of_one_frame_and_none(void **state) {
    (void)state;
    write_every_figure(1);
    write_every_figure(0);
}

/* Trace figure k of s into log. */
static void trace(synthetic *s, cs_figure k, cs_plot_log *log) {
    cs_error err;
    if (cs_figure_trace(k, &s->d, log, &err) != CS_OK) fail_msg("%s: %s", cs_figure_name(k), err.message);
}

/* Every text inside its frame, every legend clear of the data, markers and notes. */
static void test_every_text_inside_its_frame(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) /* the largest 50-ms average at the very end: its note must not leave the frame */
            for (int i = 0; i < FRAMES; i++)
                s->rec.vehicle[i].decel_50ms_g =
                    s->rec.vehicle[i].t > 0.05 ? 1 + 10 * s->rec.vehicle[i].t : 0;
        for (int k = 0; k < CS_FIG_COUNT; k++) {
            trace(s, (cs_figure)k, log);
            assert_true(log->text_count > 5);
            check_texts_inside(log, cs_figure_name((cs_figure)k));
            check_legends_clear(log, cs_figure_name((cs_figure)k));
        }
    }
    free(log);
    synthetic_free(s, NULL, 0);
}

/* Every time axis runs from 0 to the last frame's time, not to the next round tick. */
static void test_time_axes_end_at_the_run_end(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    s->rec.frame_count = 287; /* the run ends at 0.286 s, between ticks */
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    static const cs_figure timed[] = {CS_FIG_DECELERATION, CS_FIG_SPEED,  CS_FIG_PENETRATION, CS_FIG_CABLES,
                                      CS_FIG_POSTS,        CS_FIG_ENERGY, CS_FIG_ANGLES};
    for (size_t k = 0; k < sizeof timed / sizeof timed[0]; k++) {
        trace(s, timed[k], log);
        assert_true(log->panel_count >= 1);
        for (int i = 0; i < log->panel_count; i++)
            if (fabs(log->panel[i].x0) > 1e-12 || fabs(log->panel[i].x1 - 0.286) > 1e-9)
                fail_msg("%s: its time axis runs from %g to %g s, the run from 0 to 0.286 s",
                         cs_figure_name(timed[k]), log->panel[i].x0, log->panel[i].x1);
    }
    free(log);
    s->rec.frame_count = FRAMES;
    synthetic_free(s, NULL, 0);
}

/* A trace of t_end s at 1-ms frames from t0, a truck slowing from 17.9 m/s; with only its speed
 * (measured) or every response (a run). */
static cs_trace compared(const char *label, double t0, double t_end, int measured) {
    cs_trace tr = {.measured = measured, .n = (size_t)lround((t_end - t0) / 1e-3) + 1};
    snprintf(tr.label, sizeof tr.label, "%s", label);
    assert_non_null(tr.t = malloc(tr.n * sizeof *tr.t));
    for (int k = 0; k < CS_TRACE_COUNT; k++) {
        tr.have[k] = !measured || k == CS_TRACE_SPEED;
        if (!tr.have[k]) continue;
        assert_non_null(tr.y[k] = malloc(tr.n * sizeof *tr.y[k]));
    }
    for (size_t i = 0; i < tr.n; i++) {
        double t = t0 + 1e-3 * (double)i;
        tr.t[i] = t;
        for (int k = 0; k < CS_TRACE_COUNT; k++)
            if (tr.have[k])
                tr.y[k][i] = k == CS_TRACE_SPEED         ? 17.9 - 30 * fmax(t, 0)
                             : k == CS_TRACE_PENETRATION ? 4 * fmax(t, 0)
                             : k == CS_TRACE_TENSION     ? 4e5 * fmax(t, 0)
                                                         : 30 * (t > 0);
    }
    return tr;
}

/* compare's plots: every time axis runs from 0, or the earliest start of the traces a plot shows, to the
 * latest end among them, not to the next round tick; every text inside its frame, the legend clear of the
 * data. */
static void test_compare_time_axes_end_at_the_last_end(void **state) {
    (void)state;
    cs_trace tr[3] = {compared("a", 0, 0.286, 0), compared("b", 0, 0.412, 0),
                      compared("test.csv", -0.005, 0.3, 1)};
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    cs_error err;
    /* {traces shown, start, end}: run a alone; both runs and the measured speed (the reference) */
    static const struct {
        int count;
        double t0, t1;
    } cases[] = {{1, 0, 0.286}, {3, 0, 0.412}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int k = 0; k < CS_COMPARE_PLOTS; k++) {
            if (cs_compare_trace(k, tr, cases[c].count, cases[c].count - 1, log, &err) != CS_OK)
                fail_msg("%s", err.message);
            assert_int_equal(log->panel_count, 1);
            const cs_plot_logged_panel *q = &log->panel[0];
            double t0 = cases[c].count == 3 && strstr(q->title, "speed") ? -0.005 : cases[c].t0;
            if (fabs(q->x0 - t0) > 1e-12 || fabs(q->x1 - cases[c].t1) > 1e-12)
                fail_msg("%s, %d traces: its time axis runs from %g to %g s, the traces from %g to %g s",
                         q->title, cases[c].count, q->x0, q->x1, t0, cases[c].t1);
            check_texts_inside(log, q->title);
            assert_int_equal(log->legend_count, 1);
            check_legends_clear(log, q->title);
        }
    free(log);
    for (int i = 0; i < 3; i++)
        cs_trace_free(&tr[i]);
}

/* The snapshots' views are at true scale (as many metres a pixel across as up, within 1%), and each top
 * view holds the whole vehicle at its time: the synthetic car, yawed to +y, spans x 19.1-20.9 m and
 * from 2.5 m behind its centre of gravity to its crushed face. */
static void test_top_views_true_scale_whole_vehicle(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    trace(s, CS_FIG_SNAPSHOTS, log);
    int views = 0, tops = 0;
    for (int i = 0; i < log->panel_count; i++) {
        const cs_plot_logged_panel *q = &log->panel[i];
        if (!q->equal) continue;
        views++;
        double sx = q->area.w / (q->x1 - q->x0), sy = q->area.h / (q->y1 - q->y0);
        if (fabs(sx / sy - 1) > 0.01) fail_msg("%s: %.3f px/m across, %.3f px/m up", q->title, sx, sy);
        double t;
        if (!strstr(q->title, "top view")) continue;
        assert_int_equal(sscanf(q->title, "t = %lf s", &t), 1);
        const cs_vehicle_view *v = &s->rec.vehicle[(int)lround(t * 1e3)];
        double rear = v->position[1] - s->in.vehicle.cg_to_rear, face = v->front_corners[0][1];
        if (q->x0 > 19.1 || q->x1 < 20.9 || q->y0 > rear || q->y1 < face)
            fail_msg("%s shows x %.2f-%.2f m, y %.2f-%.2f m: the vehicle spans x 19.1-20.9 m, y %.2f-%.2f m",
                     q->title, q->x0, q->x1, q->y0, q->y1, rear, face);
        tops++;
    }
    assert_int_equal(views, 12);
    assert_int_equal(tops, 6);
    free(log);
    synthetic_free(s, NULL, 0);
}

/* The posts nearest x = 20 are 17 and 23 m (posts 2 and 3, loaded alike), then 10 and 30 m (posts 1 and
 * 4, alike): each second one is said to be the mirror image of the first, in both panels' legends; a post
 * moved off its mirror place is not. */
static void test_mirror_posts_named_in_the_legend(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) s->posts[4].x = 31;
        trace(s, CS_FIG_POSTS, log);
        int said[5] = {0}, mirrors = 0;
        for (int i = 0; i < log->text_count; i++) {
            int post, of;
            if (strstr(log->text[i].text, "mirror")) mirrors++;
            if (sscanf(log->text[i].text, "post %d at x = %*f m (%*f ft): mirror image of post %d", &post,
                       &of) == 2)
                said[post] += post == 3 ? of == 2 : post == 4 ? of == 1 : -100;
        }
        assert_int_equal(said[3], 2);
        assert_int_equal(said[4], pass == 0 ? 2 : 0);
        assert_int_equal(mirrors, pass == 0 ? 4 : 2);
        check_texts_inside(log, "posts");
    }
    free(log);
    synthetic_free(s, NULL, 0);
}

/* The legend of a traced figure: the texts whose frame is the whole figure and that start right of every
 * panel (an outside legend); each must be clear of every panel's plotting area, where the data are. */
static int legend_clear_of_data(const cs_plot_log *log, const char *what) {
    int entries = 0;
    double right = 0;
    for (int i = 0; i < log->panel_count; i++)
        right = fmax(right, log->panel[i].area.x + log->panel[i].area.w);
    for (int i = 0; i < log->text_count; i++) {
        const cs_box *b = &log->text[i].box;
        if (b->x < right - 1) continue; /* a tick label, a title: not the legend */
        entries++;
        for (int k = 0; k < log->panel_count; k++) {
            const cs_box *a = &log->panel[k].area;
            if (b->x < a->x + a->w && b->x + b->w > a->x && b->y < a->y + a->h && b->y + b->h > a->y)
                fail_msg("%s: legend entry '%s' overlaps the plotting area", what, log->text[i].text);
        }
    }
    return entries;
}

/* A text of the log that starts with prefix, or NULL. */
static const cs_plot_logged_text *text_starting(const cs_plot_log *log, const char *prefix) {
    for (int i = 0; i < log->text_count; i++)
        if (strncmp(log->text[i].text, prefix, strlen(prefix)) == 0) return &log->text[i];
    return NULL;
}

/* Roll, pitch and yaw: the synthetic car rolls to 0.2 t rad, pitches to -0.05 t and yaws 0.3 t rad from its
 * heading; the plot's y axis holds every value in degrees and is no more than twice their span (axes from
 * the data), each legend entry names the peak (roll 3.4 deg at 0.299 s) and the legend is clear of the
 * data, every text inside the figure. */
static void test_angles_from_the_data(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    for (int i = 0; i < FRAMES; i++) {
        cs_vehicle_view *v = &s->rec.vehicle[i];
        v->roll = 0.2 * v->t, v->pitch = -0.05 * v->t, v->yaw = PI / 2 + 0.3 * v->t;
    }
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    trace(s, CS_FIG_ANGLES, log);
    assert_int_equal(log->panel_count, 1);
    const cs_plot_logged_panel *q = &log->panel[0];
    double t_end = 0.299, lo = -0.05 * t_end / (PI / 180), hi = 0.3 * t_end / (PI / 180); /* deg */
    if (q->y0 > lo || q->y1 < hi || q->y1 - q->y0 > 2 * (hi - lo))
        fail_msg("angles: y axis %g to %g deg, the data %g to %g deg", q->y0, q->y1, lo, hi);
    assert_true(legend_clear_of_data(log, "angles") >= 3);
    const cs_plot_logged_text *roll = text_starting(log, "roll (");
    assert_non_null(roll);
    double peak, at;
    assert_int_equal(sscanf(strstr(roll->text, "peak"), "peak %lf deg at %lf s", &peak, &at), 2);
    assert_float_equal(peak, 0.2 * t_end / (PI / 180), 0.05);
    assert_float_equal(at, t_end, 1e-9);
    check_texts_inside(log, "angles");
    free(log);
    synthetic_free(s, NULL, 0);
}

/* The times and the peak the figures print are the run's, as the terminal prints them: the largest 50-ms
 * deceleration and its time from the run's summary (a step between two frames), not the frames' largest,
 * and an event's time with the digits that show it exactly (0.2985 s, not 0.299). */
static void test_peak_and_times_are_the_runs(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_summary sm = {.size = sizeof sm};
    sm.max_50ms_decel_g = 2.0049, sm.t_max_50ms_decel_s = 0.1675; /* the frames' largest: 2 g */
    s->d.summary = &sm;
    s->events[6].t = 0.2985; /* stopped */
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    trace(s, CS_FIG_DECELERATION, log);
    const cs_plot_logged_text *peak = text_starting(log, "max ");
    assert_non_null(peak);
    assert_string_equal(peak->text, "max 2.00 g at t = 0.1675 s");
    trace(s, CS_FIG_SPEED, log);
    assert_non_null(text_starting(log, "stopped at t = 0.2985 s"));
    s->d.summary = NULL; /* without a summary: the frames' largest, at its frame */
    trace(s, CS_FIG_DECELERATION, log);
    peak = text_starting(log, "max ");
    assert_non_null(peak);
    assert_string_equal(peak->text, "max 2.00 g at t = 0.051 s");
    free(log);
    synthetic_free(s, NULL, 0);
}

/* The path in plan: at true scale, its ranges hold the car at the start and the end and the exit box (A
 * 4.9 m across, B 10 m along from x = 20 m) and are tight about them in one direction (axes from the data, a
 * metre of margin and a tick), the box is named in the legend with its A and B, the legend is clear of the
 * data, every text inside the figure (the box of NCHRP 350's run named as not its criterion); without a
 * box, none is named. */
static void test_path_from_the_data(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_exit_box box = {4.9, 10, 20, HUGE_VAL, 0, 1, 0};
    cs_plot_log *log = calloc(1, sizeof *log);
    assert_non_null(log);
    static const char *const standard[3] = {"mash", "nchrp-350", NULL};
    for (int k = 0; k < 3; k++) {
        int pass = k == 2; /* 0: with the box (MASH's or, for reference, NCHRP 350's), 1: none */
        s->d.exit_box = pass ? NULL : &box;
        s->d.standard = standard[k];
        trace(s, CS_FIG_PATH, log);
        assert_int_equal(log->panel_count, 1);
        const cs_plot_logged_panel *q = &log->panel[0];
        assert_true(q->equal);
        double sx = q->area.w / (q->x1 - q->x0), sy = q->area.h / (q->y1 - q->y0);
        if (fabs(sx / sy - 1) > 0.01) fail_msg("path: %.3f px/m across, %.3f px/m up", sx, sy);
        /* the data: the car's outline (x 19.1-20.9 m) from the start (its rear 2.5 m behind the CG at
         * -2 m) to the end (its crushed face); the box x 20-30 m, y -4.9-0 m */
        const cs_vehicle_view *e = &s->rec.vehicle[FRAMES - 1];
        double x0 = 19.1, x1 = pass ? 20.9 : 30, y0 = pass ? -2 - 2.5 : -4.9, y1 = e->front_corners[0][1];
        if (q->x0 > x0 || q->x1 < x1 || q->y0 > y0 || q->y1 < y1)
            fail_msg("path (pass %d) shows x %.2f-%.2f m, y %.2f-%.2f m: the data x %.2f-%.2f, y %.2f-%.2f",
                     pass, q->x0, q->x1, q->y0, q->y1, x0, x1, y0, y1);
        if (q->x1 - q->x0 > x1 - x0 + 4 && q->y1 - q->y0 > y1 - y0 + 4)
            fail_msg(
                "path (pass %d): x %.2f-%.2f m, y %.2f-%.2f m is loose about the data in both directions",
                pass, q->x0, q->x1, q->y0, q->y1);
        assert_true(legend_clear_of_data(log, "path") >= 4);
        const cs_plot_logged_text *named =
            text_starting(log, k == 1 ? "MASH's exit box, A = 4.90 m, B = 10.0 m (not in NCHRP 350)"
                                      : "MASH's exit box: A = 4.90 m across, B = 10.0 m along");
        if (pass ? text_starting(log, "MASH's exit box") != NULL : named == NULL)
            fail_msg("path (%s): the exit box %s named", standard[k] ? standard[k] : "no box",
                     pass ? "is" : "is not");
        check_texts_inside(log, "path");
    }
    free(log);
    synthetic_free(s, NULL, 0);
}

/* The set through an output directory: every figure as PNG and SVG under plots/, none left as .tmp. */
static void test_figures_through_outdir(void **state) {
    (void)state;
    synthetic *s = synthetic_new(FRAMES);
    cs_outdir out;
    cs_error err;
    assert_int_equal(cs_out_open(&out, s->dir.path, "run", 0, NULL, &err), CS_OK);
    static const cs_plot_format formats[] = {CS_PLOT_PNG, CS_PLOT_SVG};
    if (cs_figures_write(&out, "plots", formats, 2, &s->d, &err) != CS_OK) fail_msg("%s", err.message);
    char names[2 * CS_FIG_COUNT][64], path[256];
    const char *list[2 * CS_FIG_COUNT];
    for (int k = 0; k < CS_FIG_COUNT; k++)
        for (int f = 0; f < 2; f++) {
            int i = 2 * k + f;
            snprintf(names[i], sizeof names[i], "plots/%s.%s", cs_figure_name((cs_figure)k),
                     cs_plot_extension(formats[f]));
            list[i] = names[i];
            tmp_file(&s->dir, names[i], path, sizeof path);
            assert_int_equal(access(path, F_OK), -1); /* not before the commit */
        }
    assert_int_equal(cs_out_commit(&out, &err), CS_OK);
    for (int i = 0; i < 2 * CS_FIG_COUNT; i++) {
        tmp_file(&s->dir, names[i], path, sizeof path);
        if (access(path, F_OK) != 0) fail_msg("%s missing", names[i]);
        strcat(path, ".tmp");
        assert_int_equal(access(path, F_OK), -1);
    }
    tmp_file(&s->dir, "plots/speed.png", path, sizeof path);
    check_png(path, 1200, 700);
    synthetic_free(s, list, 2 * CS_FIG_COUNT);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nice_step),
        cmocka_unit_test(test_format_of),
        cmocka_unit_test(test_known_value_lands_on_its_pixel),
        cmocka_unit_test(test_every_figure_of_a_run),
        cmocka_unit_test(test_runs_of_one_frame_and_none),
        cmocka_unit_test(test_figures_through_outdir),
        cmocka_unit_test(test_labels_stay_inside_the_frame),
        cmocka_unit_test(test_every_text_inside_its_frame),
        cmocka_unit_test(test_time_axes_end_at_the_run_end),
        cmocka_unit_test(test_compare_time_axes_end_at_the_last_end),
        cmocka_unit_test(test_top_views_true_scale_whole_vehicle),
        cmocka_unit_test(test_mirror_posts_named_in_the_legend),
        cmocka_unit_test(test_angles_from_the_data),
        cmocka_unit_test(test_peak_and_times_are_the_runs),
        cmocka_unit_test(test_path_from_the_data),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    cs_plot_release();
    return rc;
}
