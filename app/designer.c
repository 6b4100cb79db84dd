/* SPDX-License-Identifier: MIT */
/* `cablesim designer [FILE] [-o DIR]`: DIR/designer.html, one page that opens from disk and re-runs the
 * model in the browser as its values are edited (docs/designer.md). The page holds the engine and the
 * loader as WebAssembly (web/, built with emscripten: CS_HAVE_DESIGNER) and this model: its files, the
 * parts library's, and a table of the units it and the form may use, converted by udunits2 here (the page
 * has no udunits2: load/units.h, cs_units_from_table). */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/cablesim.h"
#include "cli.h"
#include "commands.h"
#include "load/loader_int.h"
#include "out/htmltext.h"
#include "out/jsondoc.h"
#include "out/outfile.h"
#include "out/report_html.h"
#include "status.h"

static const char usage[] =
    "Usage: cablesim designer [FILE] [-o DIR] [--force] [--allow-path DIR]...\n"
    "Writes DIR/designer.html (default DIR: results/<model name>-designer): one page that opens from disk,\n"
    "without a network, and runs the model of FILE (default: the APS3 example) in the browser. A form\n"
    "holds the design's main values with their units (ropes and pretension, post sections, spacing and\n"
    "footings, anchors, soil, vehicle, speed, angle and impact point); each change runs the crash again and\n"
    "updates the outcome, the response parameters, the designation as run, the plots and the 3D replay. A "
    "value can be\n"
    "swept over a range, and the edited model downloaded as YAML that cablesim run reproduces exactly.\n"
    "  -o, --out DIR   the output folder (outputs as cablesim run --help says)\n"
    "  --force         write into DIR beside files no manifest lists (none of them is removed)\n"
    "  --allow-path D  the files FILE names may be in D, as for cablesim run; the page holds the text of\n"
    "                  each file the model was read from, and of no other\n"
    "Exit status: 0 written, 1 not written, 2 a bad model or command line.\n";

#ifdef CS_HAVE_DESIGNER
extern const unsigned char cs_designer_page[];
extern const size_t cs_designer_page_size;
#endif

typedef struct design {
    cs_loader *l;
    const char *name, *model_dir; /* the model's name, its file's real folder */
    const char *file;             /* the model's file as the command line gives it (report.html's) */
    char model_path[PATH_MAX];    /* the model's path in the page */
    char *units;                  /* the unit table */
} design;

/* real's path from the folder dir ("../x/y.yaml"), both absolute and canonical. */
static void relative(const char *dir, const char *real, char *out, size_t size) {
    size_t common = 0; /* the length of their common leading folders, up to a '/' */
    for (size_t i = 0; dir[i] && dir[i] == real[i]; i++)
        if (dir[i + 1] == '\0' ? real[i + 1] == '/' : dir[i + 1] == '/') common = i + 1;
    size_t k = 0;
    for (const char *p = dir + common; *p; p++) /* a "../" for each folder of dir below the common ones */
        if (*p == '/' && p[1] && k + 4 < size) memcpy(out + k, "../", 3), k += 3;
    snprintf(out + k, size - k, "%s", real + common + (real[common] == '/'));
}

/* A file's path in the page: the parts library's under /data, the model's files under /model, where
 * the page runs (so that messages name them as the command does from the model's folder). */
static void page_path(const design *d, int i, char *out, size_t size) {
    const cs_lfile *f = &d->l->files[i];
    if (i >= d->l->library_first && i < d->l->library_end) {
        const char *base = strrchr(f->real, '/');
        snprintf(out, size, "/data/%s", base ? base + 1 : f->real);
    } else {
        char rel[PATH_MAX];
        relative(d->model_dir, f->real, rel, sizeof rel);
        snprintf(out, size, "/model/%s", rel);
    }
}

/* A file the loader read, again (the same rule, a regular file of at most CS_INPUT_MAX bytes), as a JSON
 * string; NULL if it cannot be read. */
static json_object *text_of(const char *real) {
    char *text = NULL;
    size_t size = 0;
    int errnum;
    if (cs_input_load(real, CS_INPUT_MAX, &text, &size, &errnum, NULL) != CS_OK) return NULL;
    json_object *s = cs_jstr(text);
    free(text);
    return s;
}

/* The page's data: {"version","name","model","file","data_dir","units","files":[{"path","text"}]}. */
static cs_status write_design(FILE *f, void *user, cs_error *err) {
    const design *d = user;
    json_object *doc = json_object_new_object(), *files = json_object_new_array();
    if (!doc || !files) {
        json_object_put(doc), json_object_put(files);
        return cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    }
    json_object_object_add(doc, "version", cs_jstr(CS_VERSION_STRING));
    json_object_object_add(doc, "name", cs_jstr(d->name));
    json_object_object_add(doc, "model", cs_jstr(d->model_path));
    json_object_object_add(doc, "file", cs_jstr(d->file));
    json_object_object_add(doc, "data_dir", cs_jstr("/data"));
    json_object_object_add(doc, "units", cs_jstr(d->units));
    json_object_object_add(doc, "files", files);
    cs_status st = CS_OK;
    for (int i = 0; i < d->l->file_count && st == CS_OK; i++) {
        char path[PATH_MAX + 16];
        page_path(d, i, path, sizeof path);
        json_object *file = json_object_new_object(), *text = text_of(d->l->files[i].real);
        if (!file || !text) {
            json_object_put(file), json_object_put(text);
            char message[CS_MESSAGE_SIZE];
            snprintf(message, sizeof message, "%s: cannot read it again", d->l->files[i].name);
            st = cs_status_set(err, CS_ERR_IO, message);
            break;
        }
        json_object_object_add(file, "path", cs_jstr(path));
        json_object_object_add(file, "text", text);
        json_object_array_add(files, file);
    }
    if (st == CS_OK && cs_json_write(f, doc, 1, "") != 0)
        st = cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    json_object_put(doc);
    return st;
}

/* The unit table: the usual units and every unit written in the files read (the text after a number). */
static char *unit_table(cs_loader *l) {
    int cap = cs_units_usual_count + 1, n = 0;
    for (int i = 0; i < l->file_count; i++)
        cap += l->files[i].tree.count;
    const char **texts = calloc((size_t)cap, sizeof *texts);
    char(*found)[64] = calloc((size_t)cap, sizeof *found);
    char *table = NULL;
    size_t size = 0;
    FILE *f = texts && found ? open_memstream(&table, &size) : NULL;
    if (!f) {
        free(texts), free(found);
        return NULL;
    }
    for (int i = 0; i < cs_units_usual_count; i++)
        texts[n++] = cs_units_usual[i];
    for (int i = 0; i < l->file_count; i++)
        for (int k = 0; k < l->files[i].tree.count; k++) {
            const cs_ynode *y = &l->files[i].tree.items[k];
            char *end;
            if (y->kind != CS_Y_SCALAR || (strtod(y->text, &end), end == y->text)) continue;
            while (isspace((unsigned char)*end))
                end++;
            size_t len = strlen(end);
            while (len > 0 && isspace((unsigned char)end[len - 1]))
                len--;
            if (len == 0 || len >= sizeof found[0]) continue;
            snprintf(found[n], sizeof found[0], "%.*s", (int)len, end);
            texts[n] = found[n];
            n++;
        }
    int written = cs_units_write_table(l->units, texts, n, 1, f);
    fclose(f);
    free(texts), free(found);
    if (written < 0) {
        free(table);
        return NULL;
    }
    return table;
}

/* The APS3 example: the installed examples/ beside the parts library, or the source tree's. */
static const char *default_model(cs_loader *l, char *buf, size_t size) {
    const char *data = cs_loader_data_dir(l);
    const char *const tries[] = {"%s/examples/aps3.yaml", "%s/../examples/aps3.yaml"};
    for (int i = 0; i < 2; i++) {
        snprintf(buf, size, tries[i], data);
        FILE *f = fopen(buf, "r");
        if (f) {
            fclose(f);
            return buf;
        }
    }
    return NULL;
}

static int write_page(design *d, const char *dir, int force) {
#ifdef CS_HAVE_DESIGNER
    cs_outdir out;
    cs_error err = {CS_OK, ""};
    if (cs_out_open(&out, dir, "designer", force ? CS_OUT_FORCE : 0, "--force", &err) != CS_OK) {
        fprintf(stderr, "cablesim designer: nothing written: %s\n", err.message);
        return CS_EXIT_RUN;
    }
    FILE *f = cs_out_begin(&out, "designer.html", &err);
    cs_status st = f ? cs_write_page(f, cs_designer_page, cs_designer_page_size, d->name, "designer.html",
                                     write_design, d, &err)
                     : err.status;
    if (f) st = cs_out_finish(&out, f, st, &err);
    if (st == CS_OK) st = cs_out_commit(&out, &err);
    if (st != CS_OK) {
        cs_out_fail(&out, st, &err);
        fprintf(stderr, "cablesim designer: %s\n", err.message);
        return CS_EXIT_RUN;
    }
    printf("designer page for "), cs_term_text(stdout, d->name), printf(": %s/designer.html\n", dir);
    return 0;
#else
    (void)d, (void)dir, (void)force, (void)write_design;
    fprintf(stderr,
            "cablesim designer: nothing written: this cablesim was built without emscripten (install it "
            "with scripts/install-deps.sh and build again)\n");
    return CS_EXIT_RUN;
#endif
}

int cs_command_designer(int argc, char **argv) {
    static const cs_cli cli = {"designer", usage};
    static const struct option opts[] = {{"out", required_argument, NULL, 'o'},
                                         {"force", no_argument, NULL, 'f'},
                                         {"allow-path", required_argument, NULL, 'A'},
                                         {"help", no_argument, NULL, 'h'},
                                         {NULL, 0, NULL, 0}};
    const char *dir = NULL, *file = NULL, *allow[64];
    int v, force = 0, allow_count = 0;
    optind = 1;
    while ((v = cs_cli_next(&cli, argc, argv, "ho:", opts)) != -1) {
        if (v == 'h') return cs_cli_help(&cli);
        if (v == 'f')
            force = 1;
        else if (v == 'A' && allow_count == 64)
            return cs_cli_usage_error(&cli, "more than 64 --allow-path");
        else if (v == 'A')
            allow[allow_count++] = optarg;
        else if (v == 'o')
            dir = optarg;
        else
            return CS_EXIT_USAGE;
    }
    if (argc - 1 - optind > 1)
        return cs_cli_usage_error(&cli, "more than one model file ('%s' and '%s')", argv[1 + optind],
                                  argv[2 + optind]);
    char buf[PATH_MAX], out_dir[1024], real[PATH_MAX];
    cs_error err;
    cs_loader *l = cs_loader_create(NULL, &err);
    if (!l) {
        fprintf(stderr, "cablesim designer: %s\n", err.message);
        return CS_EXIT_RUN;
    }
    for (int i = 0; i < allow_count; i++)
        if (cs_loader_allow_path(l, allow[i], &err) != CS_OK) {
            cs_loader_free(l);
            return cs_cli_usage_error(&cli, "--allow-path %s", err.message);
        }
    file = argc - 1 > optind ? argv[1 + optind] : default_model(l, buf, sizeof buf);
    int rc = CS_EXIT_USAGE;
    cs_model_input in = {.size = sizeof in};
    cs_model *model = NULL;
    design d = {l, NULL, NULL, file, "", NULL};
    if (!file) {
        fprintf(
            stderr,
            "cablesim designer: no model file given and no examples/aps3.yaml beside the parts library\n");
    } else if (cs_loader_load(l, file, &in) != 0 || !(model = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fprintf(stderr, "cablesim designer: %s: %d problem%s, nothing written\n", file,
                cs_loader_error_count(l), cs_loader_error_count(l) == 1 ? "" : "s");
    } else {
        for (int k = 0; k < CS_PART_KIND_COUNT; k++) { /* the whole library, for the form's choices */
            const char **names, **docs;
            cs_loader_library(l, (cs_part_kind)k, &names, &docs);
        }
        int model = -1; /* the model's file, as the loader found it */
        for (int i = 0; i < l->file_count && model < 0; i++)
            if (strcmp(l->files[i].name, file) == 0) model = i;
        snprintf(real, sizeof real, "%s", model >= 0 ? l->files[model].real : file);
        char *slash = strrchr(real, '/');
        if (slash) *slash = '\0';
        d.name = in.name;
        d.model_dir = real;
        d.units = unit_table(l);
        if (model >= 0) page_path(&d, model, d.model_path, sizeof d.model_path);
        if (!dir) snprintf(out_dir, sizeof out_dir, "results/%s-designer", in.name), dir = out_dir;
        rc = d.units && d.model_path[0] ? write_page(&d, dir, force) : CS_EXIT_RUN;
        if (!d.units || !d.model_path[0]) fprintf(stderr, "cablesim designer: out of memory\n");
    }
    free(d.units);
    cs_model_free(model);
    cs_loader_free(l);
    return rc;
}
