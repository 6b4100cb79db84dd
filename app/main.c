/* SPDX-License-Identifier: MIT */
/* cablesim: run, check and list cable-barrier models. Exit status: 0 done, 1 the run or its outputs
 * failed, 2 a bad model or command line. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/cablesim.h"
#include "cablesim/loader.h"
#include "cli.h"
#include "commands.h"
#include "load/schema.h"
#include "load/units.h"
#include "out/figures.h"
#include "out/htmltext.h"
#include "out/outfile.h"
#include "out/record.h"
#include "out/report_html.h"
#include "out/writers.h"
#include "status.h"
#include "sweepcmd.h"

enum { EXIT_RUN = CS_EXIT_RUN, EXIT_BAD = CS_EXIT_USAGE };

static const char usage[] =
    "Usage: cablesim run FILE [-o DIR] [--force] [--dt T] [--t-end T] [--set PATH=VALUE]... [--plots] "
    "[--report] [--occupant-at X,Y,Z] [--allow-path DIR]...\n" /* one line: help2man takes the synopsis from
                                                                 lines that begin with the command */
    "  or:  cablesim check FILE [--dt T] [--t-end T] [--set PATH=VALUE]... [--allow-path DIR]...\n"
    "  or:  cablesim sweep SPEC.yaml [-o DIR] [--threads N] [--quiet] ...\n"
    "  or:  cablesim sweep --resume DIR\n"
    "  or:  cablesim rate FILE --standard astm-f2656|sd-std-02.01|sd-std-02.01a [--class M50|PU60|K8]\n"
    "  or:  cablesim rate FILE --standard nchrp-350|mash [--level 3|4 | --test 3-11]\n"
    "  or:  cablesim validate [-o DIR]\n"
    "  or:  cablesim compare RUN... [--measured FILE.csv] [-o DIR]\n"
    "  or:  cablesim designer [FILE] [-o DIR]\n"
    "  or:  cablesim list | schema | --help | --version\n"
    "Simulate a vehicle crashing into a cable barrier and its progressive failure.\n"
    "\n"
    "Commands:\n"
    "  run       run a model: DIR/timeseries.csv, DIR/events.csv and DIR/summary.json (default DIR:\n"
    "            results/<model name>, and one of its own for a run with overrides, cablesim run --help)\n"
    "            and a summary printed; --plots also draws the run's figures as\n"
    "            DIR/plots/*.png and *.svg; --report writes DIR/report.html, one page that opens from disk:\n"
    "            data sheet, summary, failure timeline, plots, 3D replay\n"
    "  check     check a model (or a sweep spec) only: every problem as file:line:column\n"
    "  sweep     a study: grids, Monte Carlo, Latin hypercube (cablesim sweep --help); --resume DIR\n"
    "            completes an interrupted one\n"
    "  rate      the rating: the highest class of ASTM F2656 or SD-STD-02.01 a design passes, or the\n"
    "            NCHRP 350 or MASH tests of a level\n"
    "  validate  the validation suite: DIR/validation.md and .csv\n"
    "  compare   runs (folders of cablesim run) and a measured history side by side: a table and plots\n"
    "  designer  one page that runs the model in the browser as its values are edited: DIR/designer.html\n"
    "  list      the named parts of the library and the folder they are read from\n"
    "  schema    the model-file reference (docs/file-format.md)\n"
    "cablesim COMMAND --help gives the command's options.\n"
    "\n"
    "Values take units: --dt \"0.2 ms\", --set scenario.speed=\"35 mph\",\n"
    "--set barrier.cables[0].pretension=\"8 kip\".\n"
    "The parts library is the folder named by CABLESIM_DATA, else PREFIX/share/cablesim of an installed\n"
    "cablesim, else the source tree's data/.\n"
    "Exit status (every command): 0 done, 1 a run or its outputs failed, 2 a bad model, spec or command\n"
    "line; validate: 3 its targets missed; 128 + the signal (130 Ctrl-C, 143 SIGTERM) when a signal\n"
    "stopped it: a sweep's outputs partial, any other command's output folder left as it was.\n";

static const char run_usage[] =
    "Usage: cablesim run FILE [-o DIR] [--force] [--dt T] [--t-end T] [--set PATH=VALUE]... [--plots]\n"
    "                    [--report] [--occupant-at X,Y,Z] [--allow-path DIR]...\n"
    "Runs the model of FILE and prints a summary: the outcome, the model's hash, the response parameters,\n"
    "the designations as run (docs/ratings.md), the failure events. Writes DIR/timeseries.csv,\n"
    "DIR/events.csv and DIR/summary.json; --plots also the run's figures as DIR/plots/*.png and *.svg,\n"
    "--report DIR/report.html (one page that opens from disk: a data sheet that prints on one page,\n"
    "summary, failure timeline, plots, 3D replay). Default DIR: results/<model name>; with overrides,\n"
    "a folder of its own named from them, each as its path (without its first part) and its value:\n"
    "--set scenario.speed=\"35 mph\" writes results/aps3_speed-35mph, --set\n"
    "barrier.cables[0].pretension=\"8 kip\" --t-end \"1 s\" results/aps3_cables0.pretension-8kip_t-end-1s.\n"
    "DIR is checked and locked before the run; the files\n"
    "appear together once all are written, with DIR/.cablesim-manifest listing them, and the files of an\n"
    "earlier run there (its manifest's) that this one does not write are removed: DIR holds one run. A DIR\n"
    "holding a file no manifest lists, or one changed since cablesim wrote it (the manifest holds each\n"
    "file's size and hash), is refused, naming it. A failed run writes nothing; an earlier run's file\n"
    "that cannot be removed once the new files are in place fails the run too (status 1), the message\n"
    "saying the new results are written and naming that file, which the manifest keeps for the next run\n"
    "to remove. Ctrl-C (SIGINT) or SIGTERM leaves DIR as it was, no temporary or lock left and a folder\n"
    "the run made removed, unless the files were being renamed into place: the renames end first. The\n"
    "run then ends by the signal.\n"
    "  -o, --out DIR        the output folder\n"
    "  --force              write into DIR beside files no manifest lists (none of them is removed)\n"
    "  --set PATH=VALUE     replace a value of the model: --set scenario.speed=\"35 mph\"\n"
    "  --dt T, --t-end T    the time step and the time limit: --dt \"0.2 ms\" (scenario.dt, scenario.t_end)\n"
    "  --plots, --report    the figures, the HTML report\n"
    "  --occupant-at X,Y,Z  the occupant risk at this point of the vehicle, not at its CG: lengths from the\n"
    "                       CG, forward, to the left and up: --occupant-at \"0.3 m,0.4 m,0.2 m\"\n"
    "  --allow-path DIR     the files FILE names (file:) may be in DIR and its subfolders, beyond FILE's\n"
    "                       folder (and its subfolders) and the parts library's\n"
    "Exit status: 0 done, 1 the run or its outputs failed, 2 a bad model or command line, 128 + the\n"
    "signal that stopped it (130 Ctrl-C, 143 SIGTERM).\n";

static const char check_usage[] =
    "Usage: cablesim check FILE [--dt T] [--t-end T] [--set PATH=VALUE]... [--allow-path DIR]...\n"
    "Checks a model file (or a sweep spec, see cablesim sweep --help) without running it: every problem as\n"
    "FILE:LINE:COLUMN. --allow-path DIR: the files FILE names may be in DIR, as for cablesim run.\n"
    "Exit status: 0 valid, 2 problems or a bad command line.\n";

static const char list_usage[] = "Usage: cablesim list\n"
                                 "Lists the named parts of the library (data/*.yaml): vehicles, wire ropes, "
                                 "post and rail sections.\n"
                                 "Exit status: 0 done, 1 no parts library, 2 a bad library file or command "
                                 "line.\n";

static const char schema_usage[] = "Usage: cablesim schema\n"
                                   "Prints the model-file reference (docs/file-format.md) from the loader's "
                                   "schema.\n"
                                   "Exit status: 0 done, 1 it could not be written, 2 a bad command line.\n";

typedef struct options {
    const char *file, *out_dir;
    int plots, report, force;
    cs_overrides *overrides;
    int occupant_at;          /* --occupant-at given */
    double occupant_point[3]; /* m from the CG: forward, left, up */
} options;

/* --occupant-at X,Y,Z: three lengths with their units into o. Returns 0, or EXIT_BAD with the reason. */
static int occupant_at(const cs_cli *cli, const char *arg, options *o) {
    char text[256];
    cs_error err;
    snprintf(text, sizeof text, "%s", arg);
    cs_units *u = cs_units_open(&err);
    if (!u) return cs_cli_usage_error(cli, "--occupant-at: %s", err.message);
    int k = 0, rc = 0;
    for (char *save = NULL, *p = strtok_r(text, ",", &save); p && rc == 0;
         p = strtok_r(NULL, ",", &save), k++)
        if (k >= 3 || cs_units_read(u, p, CS_Q_LENGTH, &o->occupant_point[k], &err) != CS_OK)
            rc = cs_cli_usage_error(cli, "--occupant-at %s: %s", arg,
                                    k >= 3 ? "more than three lengths (X,Y,Z)" : err.message);
    if (rc == 0 && k != 3)
        rc = cs_cli_usage_error(
            cli, "--occupant-at %s: three lengths are needed, X,Y,Z (\"0.3 m,0.4 m,0.2 m\")", arg);
    cs_units_free(u);
    o->occupant_at = rc == 0;
    return rc;
}

/* A command line cablesim cannot take: what was wrong, in one line, and where the help is. */
static int bad_usage(const char *what) {
    fprintf(stderr, "cablesim: %s (cablesim --help: the commands)\n", what);
    return EXIT_BAD;
}

/* Parse the command line of run or check into o, queueing --set, --dt and --t-end on the loader.
 * Returns 0, a help's 0 with o->file NULL, or EXIT_BAD. */
static int parse(int argc, char **argv, const cs_cli *cli, int is_run, options *o, cs_loader *l) {
    enum { SET = 1000, DT, T_END, PLOTS, REPORT, FORCE, OCCUPANT, ALLOW };
    static const struct option run_opts[] = {{"out", required_argument, NULL, 'o'},
                                             {"set", required_argument, NULL, SET},
                                             {"dt", required_argument, NULL, DT},
                                             {"t-end", required_argument, NULL, T_END},
                                             {"plots", no_argument, NULL, PLOTS},
                                             {"report", no_argument, NULL, REPORT},
                                             {"force", no_argument, NULL, FORCE},
                                             {"occupant-at", required_argument, NULL, OCCUPANT},
                                             {"allow-path", required_argument, NULL, ALLOW},
                                             {"help", no_argument, NULL, 'h'},
                                             {NULL, 0, NULL, 0}};
    static const struct option check_opts[] = {
        {"set", required_argument, NULL, SET},     {"dt", required_argument, NULL, DT},
        {"t-end", required_argument, NULL, T_END}, {"allow-path", required_argument, NULL, ALLOW},
        {"help", no_argument, NULL, 'h'},          {NULL, 0, NULL, 0}};
    int v;
    optind = 1;
    while ((v = cs_cli_next(cli, argc, argv, is_run ? "ho:" : "h", is_run ? run_opts : check_opts)) != -1) {
        char set[1200];
        cs_error err;
        switch (v) {
        case 'h':
            o->file = NULL;
            return cs_cli_help(cli);
        case 'o':
            o->out_dir = optarg;
            break;
        case PLOTS:
            o->plots = 1;
            break;
        case REPORT:
            o->report = 1;
            break;
        case FORCE:
            o->force = 1;
            break;
        case OCCUPANT:
            if (occupant_at(cli, optarg, o) != 0) return EXIT_BAD;
            break;
        case ALLOW:
            if (cs_loader_allow_path(l, optarg, &err) != CS_OK)
                return cs_cli_usage_error(cli, "--allow-path %s", err.message);
            break;
        case SET:
        case DT:
        case T_END:
            if (cs_overrides_add(o->overrides,
                                 v == SET  ? "--set"
                                 : v == DT ? "--dt"
                                           : "--t-end",
                                 optarg) != 0)
                return EXIT_BAD;
            snprintf(set, sizeof set, "%s%s",
                     v == DT      ? "scenario.dt="
                     : v == T_END ? "scenario.t_end="
                                  : "",
                     optarg);
            /* a problem with --dt or --t-end names it as given ("--dt 2 ms": the override's text) */
            cs_loader_set_given(l, set, v == SET ? NULL : o->overrides->text[o->overrides->count - 1]);
            break;
        default:
            return EXIT_BAD;
        }
    }
    int operands = argc - 1 - optind;
    if (operands > 1)
        return cs_cli_usage_error(cli, "more than one model file ('%s' and '%s')", argv[1 + optind],
                                  argv[2 + optind]);
    if (operands < 1) return cs_cli_usage_error(cli, "no model file");
    o->file = argv[1 + optind];
    return 0;
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
    const cs_run_info *info;
} report_args;

/* DIR/report.html, begun on out (a cs_more_outputs). A build that lacked node and npm has no page: a
 * warning, no file. */
static cs_status write_report_html(cs_outdir *out, void *user, cs_error *err) {
    const report_args *a = user;
#ifdef CS_HAVE_REPORT
    FILE *f = cs_out_begin(out, "report.html", err);
    if (!f) return err->status;
    cs_status st =
        cs_write_report_html(f, cs_report_page, cs_report_page_size, a->in, a->state, a->rec, a->info, err);
    return cs_out_finish(out, f, st, err);
#else
    (void)out, (void)a, (void)err;
    fprintf(stderr, "cablesim: warning: no report.html: this cablesim was built without node and npm "
                    "(install them with scripts/install-deps.sh and build again)\n");
    return CS_OK;
#endif
}

/* Every output of the run into out (opened before the run), committed together; on a failure nothing is
 * left (cs_out_fail), unless the files were in place (an earlier run's file that could not be removed). */
static int write_outputs(cs_outdir *out, const cs_model_input *in, const cs_model *model,
                         const cs_state *state, const cs_record *rec, const cs_run_info *info, int plots,
                         int report) {
    report_args args = {in, state, rec, info};
    cs_error err;
    cs_status st = cs_write_run_files(out, in, model, state, rec, info, plots ? CS_OUTPUT_PLOTS : 0,
                                      report ? write_report_html : NULL, &args, &err);
    if (st == CS_OK) st = cs_out_commit(out, &err);
    if (st != CS_OK) {
        cs_out_fail(out, st, &err);
        fprintf(stderr, "cablesim: %s\n", err.message);
    }
    return st == CS_OK ? 0 : -1;
}

/* The folder of a run given no -o: results/NAME, and for a run with overrides a folder of its own named
 * from them, so that it does not replace the run as the file has it: each override as its path without
 * its first part and brackets, then its value without spaces (--set scenario.speed="35 mph" --set
 * barrier.cables[0].pretension="8 kip": results/aps3_speed-35mph_cables0.pretension-8kip; --dt 0.2 ms:
 * _dt-0.2ms). A character a file name would not keep plainly becomes '-'; a name past 160 characters is
 * cut. */
static void default_dir(const cs_model_input *in, const cs_overrides *ov, char *path, size_t size) {
    size_t n = (size_t)snprintf(path, size, "results/%s", in->name);
    for (int i = 0; i < ov->count && n + 2 < size && n < 168; i++) {
        const char *t = ov->text[i], *value = strchr(t, ' ') + 1; /* "--set PATH=VALUE", "--dt VALUE" */
        const char *eq = strncmp(t, "--set ", 6) == 0 ? strchr(value, '=') : NULL;
        const char *name = eq ? value : t + 2, *name_end = eq ? eq : value - 1;
        const char *dot = memchr(name, '.', (size_t)(name_end - name));
        if (eq && dot) name = dot + 1; /* scenario.speed: speed */
        path[n++] = '_';
        for (const char *s = name; s < name_end && n + 2 < size; s++)
            if (*s != '[' && *s != ']') path[n++] = strchr("-.", *s) || isalnum((unsigned char)*s) ? *s : '-';
        path[n++] = '-';
        for (const char *s = eq ? eq + 1 : value; *s && n + 1 < size; s++)
            if (*s != ' ' && *s != '"' && *s != '\'')
                path[n++] = strchr("-.+", *s) || isalnum((unsigned char)*s) ? *s : '-';
        path[n] = '\0';
    }
    if (n > 168) path[168] = '\0';
}

static int run(const cs_model_input *in, cs_model *model, const options *o, const char *command) {
    char path[1024];
    const char *dir = o->out_dir;
    if (!dir) default_dir(in, o->overrides, path, sizeof path), dir = path;
    cs_outdir out;
    cs_error err = {0};
    /* before the run */
    if (cs_out_open(&out, dir, "run", o->force ? CS_OUT_FORCE : 0, "--force", &err) != CS_OK) {
        fprintf(stderr, "cablesim: nothing run: %s\n", err.message);
        return EXIT_RUN;
    }
    cs_record rec;
    cs_state *state = cs_state_create(model, &err);
    int rc = EXIT_RUN;
    /* every view of each frame only for what draws them */
    cs_record_kind kind = o->plots || o->report ? CS_RECORD_ALL : CS_RECORD_FILES;
    if (!state || cs_record_init_for(&rec, model, kind) != 0) {
        fprintf(stderr, "cablesim: %s\n", state ? "out of memory" : err.message);
        cs_state_free(state);
        cs_out_abort(&out);
        return EXIT_RUN;
    }
    cs_run_info info = {
        .command = command, .override_count = o->overrides->count, .model_hash = cs_model_input_hash(in)};
    const char *overrides[64];
    for (int i = 0; i < o->overrides->count; i++)
        overrides[i] = o->overrides->text[i];
    info.overrides = overrides;
    if (cs_run(model, state, cs_record_frame, &rec, &err) != CS_OK) {
        fprintf(stderr, "cablesim: the run failed, nothing written: %s\n", err.message);
        cs_out_abort(&out);
    } else if (rec.failed) {
        fprintf(stderr, "cablesim: out of memory while recording, nothing written\n");
        cs_out_abort(&out);
    } else {
        cs_summary sm = {.size = sizeof sm};
        cs_state_summary(state, &sm, NULL);
        cs_run_info_rate(&info, in, &sm);
        info.occupant_at = o->occupant_at;
        memcpy(info.occupant_point, o->occupant_point, sizeof info.occupant_point);
        cs_run_info_motion(&info, in, &rec, state, &sm);
        if (write_outputs(&out, in, model, state, &rec, &info, o->plots, o->report) == 0) {
            cs_write_summary_text_with(stdout, in, model, state, &info);
            printf("  outputs              %s/{timeseries.csv,events.csv,summary.json%s%s}\n", dir,
                   o->plots ? ",plots/*.png,plots/*.svg" : "",
                   o->report && HAVE_REPORT ? ",report.html" : "");
            rc = 0;
        }
    }
    cs_record_release(&rec);
    cs_state_free(state);
    return rc;
}

/* The section properties' US units for `list`, from units.h's inch, foot and pound. */
#define IN2 (CS_IN * CS_IN)
#define IN3 (CS_IN * CS_IN * CS_IN)
#define IN4 (CS_IN * CS_IN * CS_IN * CS_IN)
#define LB_PER_FT (CS_LB / CS_FT)

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
                       d.vehicle.mass, d.vehicle.mass / CS_LB,
                       d.vehicle.crush_force[d.vehicle.crush_point_count - 1] / 1e3,
                       d.vehicle.crush_deformation[d.vehicle.crush_point_count - 1], docs[i]);
            else if (k == CS_PART_ROPE)
                printf("  %-14s A %7.1f mm2 (%.3f in2), Fu %6.1f kN (%5.1f kip)  %s\n", names[i],
                       d.rope.area * 1e6, d.rope.area / (CS_IN * CS_IN), d.rope.nominal_strength / 1e3,
                       d.rope.nominal_strength / CS_KIP, docs[i]);
            else if (k == CS_PART_RAIL)
                printf("  %-14s A %.3f in2, I %.3f in4, Fy %.0f ksi, %.2f lb/ft  %s\n", names[i],
                       d.rail.area / IN2, d.rail.inertia / IN4, d.rail.yield_stress / CS_KSI,
                       d.rail.mass_per_length / LB_PER_FT, docs[i]);
            else
                printf("  %-14s Zx %.3f in3, Ix %.3f in4, Aw %.3f in2, Fy %.0f ksi, %.2f lb/ft  %s\n",
                       names[i], d.section.plastic_modulus / IN3, d.section.inertia / IN4,
                       d.section.web_area / IN2, d.section.yield_stress / CS_KSI,
                       d.section.mass_per_length / LB_PER_FT, docs[i]);
        }
    }
    if (cs_loader_error_count(l)) {
        cs_loader_print_errors(l, stderr);
        return EXIT_BAD;
    }
    return 0;
}

/* list and schema take no arguments but --help. Returns -1 to go on, else the exit status. */
static int no_arguments(int argc, char **argv, const cs_cli *cli) {
    static const struct option opts[] = {{"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
    int v;
    optind = 1;
    while ((v = cs_cli_next(cli, argc, argv, "h", opts)) != -1)
        return v == 'h' ? cs_cli_help(cli) : EXIT_BAD;
    if (argc - 1 > optind) return cs_cli_usage_error(cli, "takes no argument ('%s')", argv[1 + optind]);
    return -1;
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
    static const cs_cli schema_cli = {"schema", schema_usage}, list_cli = {"list", list_usage},
                        run_cli = {"run", run_usage}, check_cli = {"check", check_usage};
    int rc;
    if (strcmp(cmd, "schema") == 0) {
        if ((rc = no_arguments(argc, argv, &schema_cli)) >= 0) return rc;
        return cs_schema_markdown(stdout) == 0 ? 0 : EXIT_RUN;
    }
    if (strcmp(cmd, "sweep") == 0) return cs_sweep_command(argc, argv);
    cs_cli_catch_signals();
    if (strcmp(cmd, "check") == 0 && cs_sweep_check_wanted(argc, argv))
        return cs_sweep_check_command(argc, argv);
    if (strcmp(cmd, "rate") == 0) return cs_command_rate(argc, argv);
    if (strcmp(cmd, "validate") == 0) return cs_command_validate(argc, argv);
    if (strcmp(cmd, "compare") == 0) return cs_command_compare(argc, argv);
    if (strcmp(cmd, "designer") == 0) return cs_command_designer(argc, argv);
    int is_run = strcmp(cmd, "run") == 0, is_check = strcmp(cmd, "check") == 0;
    if (!is_run && !is_check && strcmp(cmd, "list") != 0) {
        char what[300];
        snprintf(what, sizeof what, "unknown command '%.200s'", cmd);
        return bad_usage(what);
    }
    if (!is_run && !is_check && (rc = no_arguments(argc, argv, &list_cli)) >= 0) return rc;
    cs_error err;
    cs_loader *l = cs_loader_create(NULL, &err);
    if (!l) {
        fprintf(stderr, "cablesim: %s\n", err.message);
        return EXIT_RUN;
    }
    static cs_overrides overrides;
    static char command[8192];
    cs_cli_command_line(argc, argv, command, sizeof command); /* as typed: getopt_long reorders argv */
    options o = {.overrides = &overrides};
    cs_model_input in = {.size = sizeof in};
    cs_model *model = NULL;
    if (!is_run && !is_check)
        rc = list(l);
    else if ((rc = parse(argc, argv, is_run ? &run_cli : &check_cli, is_run, &o, l)) != 0 || !o.file) {
    } else if (cs_loader_load(l, o.file, &in) != 0 || !(model = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fprintf(stderr, "cablesim: %s: %d problem%s, nothing run\n", o.file, cs_loader_error_count(l),
                cs_loader_error_count(l) == 1 ? "" : "s");
        rc = EXIT_BAD;
    } else if (is_check) {
        printf("%s: ", o.file), cs_term_text(stdout, in.name);
        printf(" is a valid model (%d cables, %d posts)\n", in.barrier.cable_count, in.barrier.post_count);
    } else {
        rc = run(&in, model, &o, command);
    }
    cs_model_free(model);
    cs_loader_free(l);
    return rc;
}
