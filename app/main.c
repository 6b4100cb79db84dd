/* cablesim: run, check and list cable-barrier models. Exit status: 0 done, 1 the run or its outputs
 * failed, 2 a bad model or command line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/cablesim.h"
#include "cablesim/loader.h"
#include "commands.h"
#include "load/schema.h"
#include "out/figures.h"
#include "out/outfile.h"
#include "out/record.h"
#include "out/report_html.h"
#include "out/writers.h"
#include "sweepcmd.h"

enum { EXIT_RUN = 1, EXIT_BAD = 2 };

static const char usage[] =
    "Usage: cablesim run FILE [-o DIR] [--dt T] [--t-end T] [--set PATH=VALUE]... [--plots] [--report]\n"
    "  or:  cablesim check FILE [--set PATH=VALUE]...\n"
    "  or:  cablesim sweep SPEC.yaml [-o DIR] [--threads N]\n"
    "  or:  cablesim rate FILE --standard sd-std-02.01|sd-std-02.01a|astm-f2656 [--class M50|K8]\n"
    "  or:  cablesim rate FILE --standard nchrp-350|mash [--level 3|4 | --test 3-11]\n"
    "  or:  cablesim validate [-o DIR]\n"
    "  or:  cablesim compare RUN... [--measured FILE.csv] [-o DIR]\n"
    "  or:  cablesim list | schema | --help | --version\n"
    "Simulate a vehicle crashing into a cable barrier and its progressive failure.\n"
    "\n"
    "Commands:\n"
    "  run       run a model: DIR/timeseries.csv, DIR/events.csv and DIR/summary.json (default DIR:\n"
    "            results/<model name>) and a summary printed; --plots also draws the run's figures as\n"
    "            DIR/plots/*.png and *.svg; --report writes DIR/report.html, one page that opens from disk:\n"
    "            summary, failure timeline, plots, 3D replay\n"
    "  check     check a model (or a sweep spec) only: every problem as file:line:column\n"
    "  sweep     a study: grids, Monte Carlo, Latin hypercube (cablesim sweep --help)\n"
    "  rate      the highest class of ASTM F2656 or SD-STD-02.01 a design passes, or the NCHRP 350 or\n"
    "            MASH tests of a level\n"
    "  validate  the validation suite: DIR/validation.md and .csv\n"
    "  compare   runs (folders of cablesim run) and a measured history side by side: a table and plots\n"
    "  list      the named parts of the library and the folder they are read from\n"
    "  schema    the model-file reference (docs/file-format.md)\n"
    "\n"
    "Values take units: --dt \"0.2 ms\", --set scenario.speed=\"35 mph\",\n"
    "--set barrier.cables[0].pretension=\"8 kip\".\n"
    "The parts library is the folder named by CABLESIM_DATA, else PREFIX/share/cablesim of an installed\n"
    "cablesim, else the source tree's data/.\n"
    "Exit status: 0 done, 1 the run failed, 2 bad model or usage.\n";

typedef struct options {
    const char *command, *file, *out_dir;
    int plots, report;
} options;

static int bad_usage(const char *what) {
    fprintf(stderr, "cablesim: %s\n%s", what, usage);
    return EXIT_BAD;
}

/* Parse the command line into o, queueing --set, --dt and --t-end on the loader. */
static int parse(int argc, char **argv, options *o, cs_loader *l) {
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i], *v = NULL;
        char set[1024];
        if (strcmp(a, "--plots") == 0) {
            o->plots = 1;
            continue;
        }
        if (strcmp(a, "--report") == 0) {
            o->report = 1;
            continue;
        }
        static const char *const valued[][2] = {
            {"--set", NULL}, {"--dt", "scenario.dt"}, {"--t-end", "scenario.t_end"}, {"-o", NULL}};
        int k = -1;
        for (int j = 0; j < 4; j++) {
            size_t n = strlen(valued[j][0]);
            if (strncmp(a, valued[j][0], n) == 0 && (a[n] == '\0' || a[n] == '=')) {
                k = j;
                v = a[n] == '=' ? a + n + 1 : i + 1 < argc ? argv[++i] : NULL;
            }
        }
        if (k < 0 && a[0] == '-') return bad_usage("unknown option");
        if (k < 0 && o->file) return bad_usage("more than one model file");
        if (k < 0)
            o->file = a;
        else if (!v)
            return bad_usage("an option lacks its value");
        else if (k == 3)
            o->out_dir = v;
        else {
            snprintf(set, sizeof set, "%s%s%s", valued[k][1] ? valued[k][1] : "", valued[k][1] ? "=" : "", v);
            cs_loader_set(l, set);
        }
    }
    return o->file ? 0 : bad_usage("no model file");
}

#ifdef CS_HAVE_REPORT
enum { HAVE_REPORT = 1 };
#else
enum { HAVE_REPORT = 0 };
#endif

/* What report.html is written from. */
typedef struct report_args {
    const cs_model_input *in;
    const cs_state *state;
    const cs_record *rec;
} report_args;

/* DIR/report.html, begun on out (a cs_more_outputs). A build that lacked node and npm has no page: a
 * warning, no file. */
static int write_report_html(cs_outdir *out, void *user, char *why, size_t why_size) {
    const report_args *a = user;
#ifdef CS_HAVE_REPORT
    FILE *f = cs_out_begin(out, "report.html", why, why_size);
    if (!f) return -1;
    int rc =
        cs_write_report_html(f, cs_report_page, cs_report_page_size, a->in, a->state, a->rec, why, why_size);
    char end_why[512];
    if (cs_out_end(out, f, end_why, sizeof end_why) != 0 && rc == 0) {
        snprintf(why, why_size, "%s", end_why);
        rc = -1;
    }
    return rc;
#else
    (void)out, (void)a, (void)why, (void)why_size;
    fprintf(stderr, "cablesim: warning: no report.html: this cablesim was built without node and npm "
                    "(install them with scripts/install-deps.sh and build again)\n");
    return 0;
#endif
}

static int write_outputs(const char *dir, const cs_model_input *in, const cs_model *model,
                         const cs_state *state, const cs_record *rec, int plots, int report) {
    char why[512] = "";
    report_args args = {in, state, rec};
    int rc = cs_write_outputs_with(dir, in, model, state, rec, plots ? CS_OUTPUT_PLOTS : 0,
                                   report ? write_report_html : NULL, &args, why, sizeof why);
    if (rc != 0) fprintf(stderr, "cablesim: nothing written: %s\n", why);
    return rc;
}

static int run(const cs_model_input *in, cs_model *model, const char *dir, int plots, int report) {
    cs_error err = {0};
    cs_record rec;
    cs_state *state = cs_state_create(model, &err);
    int rc = EXIT_RUN;
    if (!state || cs_record_init(&rec, model) != 0) {
        fprintf(stderr, "cablesim: %s\n", state ? "out of memory" : err.message);
        cs_state_free(state);
        return EXIT_RUN;
    }
    char path[1024];
    if (!dir) snprintf(path, sizeof path, "results/%s", in->name);
    if (cs_run(model, state, cs_record_frame, &rec, &err) != CS_OK)
        fprintf(stderr, "cablesim: the run failed, nothing written: %s\n", err.message);
    else if (rec.failed)
        fprintf(stderr, "cablesim: out of memory while recording, nothing written\n");
    else if (write_outputs(dir ? dir : path, in, model, state, &rec, plots, report) == 0) {
        cs_write_summary_text(stdout, in, model, state);
        cs_summary sm;
        cs_state_summary(state, &sm);
        cs_print_run_rating(stdout, &in->vehicle, in->scenario.speed, &sm);
        printf("  outputs              %s/{timeseries.csv,events.csv,summary.json%s%s}\n", dir ? dir : path,
               plots ? ",plots/*.png,plots/*.svg" : "", report && HAVE_REPORT ? ",report.html" : "");
        rc = 0;
    }
    cs_record_release(&rec);
    cs_state_free(state);
    return rc;
}

static int list(cs_loader *l) {
    static const char *const titles[] = {"Vehicles", "Wire ropes", "Post sections", "Rail sections"};
    if (cs_loader_data_dir(l)[0]) printf("Parts library: %s\n\n", cs_loader_data_dir(l));
    for (int k = 0; k < CS_PART_KIND_COUNT; k++) {
        const char **names, **docs;
        int n = cs_loader_library(l, (cs_part_kind)k, &names, &docs);
        if (n < 0) break;
        printf("%s%s:\n", k ? "\n" : "", titles[k]);
        for (int i = 0; i < n; i++) {
            cs_any_def d;
            if (cs_loader_part(l, (cs_part_kind)k, names[i], &d) != 0) continue;
            if (k == CS_PART_VEHICLE)
                printf("  %-14s %7.0f kg (%6.0f lb), crush force %.0f kN at %.2f m  %s\n", names[i],
                       d.vehicle.mass, d.vehicle.mass / 0.45359237,
                       d.vehicle.crush_force[d.vehicle.crush_point_count - 1] / 1e3,
                       d.vehicle.crush_deformation[d.vehicle.crush_point_count - 1], docs[i]);
            else if (k == CS_PART_ROPE)
                printf("  %-14s A %7.1f mm2 (%.3f in2), Fu %6.1f kN (%5.1f kip)  %s\n", names[i],
                       d.rope.area * 1e6, d.rope.area / 0.00064516, d.rope.nominal_strength / 1e3,
                       d.rope.nominal_strength / 4448.2216152605, docs[i]);
            else if (k == CS_PART_RAIL)
                printf("  %-14s A %.3f in2, I %.3f in4, Fy %.0f ksi, %.2f lb/ft  %s\n", names[i],
                       d.rail.area / 0.00064516, d.rail.inertia / 4.162314256e-07,
                       d.rail.yield_stress / 6894757.29316836, d.rail.mass_per_length / 1.4881639435695537,
                       docs[i]);
            else
                printf("  %-14s Zx %.3f in3, Ix %.3f in4, Aw %.3f in2, Fy %.0f ksi, %.2f lb/ft  %s\n",
                       names[i], d.section.plastic_modulus / 1.6387064e-05,
                       d.section.inertia / 4.162314256e-07, d.section.web_area / 0.00064516,
                       d.section.yield_stress / 6894757.29316836,
                       d.section.mass_per_length / 1.4881639435695537, docs[i]);
        }
    }
    if (cs_loader_error_count(l)) {
        cs_loader_print_errors(l, stderr);
        return EXIT_BAD;
    }
    return 0;
}

int main(int argc, char **argv) {
    if (argc < 2) return bad_usage("no command");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        fputs(usage, stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("cablesim %s\n", CS_VERSION_STRING);
        return 0;
    }
    if (strcmp(cmd, "schema") == 0) return cs_schema_markdown(stdout) == 0 ? 0 : EXIT_RUN;
    if (strcmp(cmd, "sweep") == 0) return cs_sweep_command(argc, argv);
    if (strcmp(cmd, "check") == 0 && cs_sweep_check_wanted(argc, argv))
        return cs_sweep_check_command(argc, argv);
    if (strcmp(cmd, "rate") == 0) return cs_command_rate(argc, argv);
    if (strcmp(cmd, "validate") == 0) return cs_command_validate(argc, argv);
    if (strcmp(cmd, "compare") == 0) return cs_command_compare(argc, argv);
    int is_run = strcmp(cmd, "run") == 0, is_check = strcmp(cmd, "check") == 0;
    if (!is_run && !is_check && strcmp(cmd, "list") != 0) return bad_usage("unknown command");
    char why[256];
    cs_loader *l = cs_loader_create(NULL, why, sizeof why);
    if (!l) {
        fprintf(stderr, "cablesim: %s\n", why);
        return EXIT_RUN;
    }
    int rc;
    options o = {cmd, NULL, NULL, 0, 0};
    cs_model_input in;
    cs_model *model = NULL;
    if (!is_run && !is_check)
        rc = list(l);
    else if ((rc = parse(argc, argv, &o, l)) != 0) {
    } else if (cs_loader_load(l, o.file, &in) != 0 || !(model = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fprintf(stderr, "cablesim: %s: %d problem%s, nothing run\n", o.file, cs_loader_error_count(l),
                cs_loader_error_count(l) == 1 ? "" : "s");
        rc = EXIT_BAD;
    } else if (is_check) {
        printf("%s: %s is a valid model (%d cables, %d posts)\n", o.file, in.name, in.barrier.cable_count,
               in.barrier.post_count);
    } else {
        rc = run(&in, model, o.out_dir, o.plots, o.report);
    }
    cs_model_free(model);
    cs_loader_free(l);
    return rc;
}
