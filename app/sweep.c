/* SPDX-License-Identifier: MIT */
/* cablesim sweep: the command line into the study's def, then the study run by the library
 * (cablesim/sweep.h) on this process's OpenMP threads and, in cablesim-mpi, on the ranks of MPI through
 * the def's ranks (app/sweep_mpi.c's hooks send each finished run to rank 0, which journals it).
 * `cablesim check SPEC`: the study checked by the library, nothing run. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef CS_MPI
#include <mpi.h>

#include "sweep_mpi.h"
#endif

#include "cablesim/cablesim.h"
#include "cli.h"
#include "sweepcmd.h"

enum { EXIT_RUN = CS_EXIT_RUN, EXIT_BAD = CS_EXIT_USAGE };

static const char sweep_usage[] =
    "Usage: cablesim sweep SPEC.yaml [-o DIR] [--threads N] [--runs N] [--seed S] [--set PATH=VALUE]...\n"
    "                      [--t-end T] [--dt T] [--netcdf] [--allow-path DIR]... [--quiet] [--force]\n"
    "  or:  cablesim sweep --resume DIR [--threads N] [--quiet] [--force]\n"
    "Runs the study of SPEC (a base model, the values to vary: grids, or Monte Carlo / Latin hypercube\n"
    "samples) and writes DIR/runs.csv, DIR/summary.md and DIR/summary.json (default DIR: results/<spec\n"
    "name>). --threads: OpenMP threads per process (default: OMP_NUM_THREADS or the cores, shared among\n"
    "the ranks of a machine). Under MPI (mpirun -n R cablesim-mpi sweep ...) the runs are shared among\n"
    "the R ranks. --runs and --seed replace the spec's; --set, --t-end and --dt apply to every run.\n"
    "--allow-path DIR: the model (SPEC's `model:`) and the files it names may be in DIR and its subfolders,\n"
    "beyond SPEC's folder (and its subfolders) and the parts library's.\n"
    "--netcdf (or `netcdf: true` in SPEC) also writes DIR/runs.nc: runs.csv's table as netCDF (CF-1.8).\n"
    "SPEC's `plot:` draws a response against a varied value in DIR/plots/<y>-vs-<x>.png (docs/sweep.md).\n"
    "DIR is checked and locked before any run; the files appear together at the end, listed in\n"
    "DIR/.cablesim-manifest, and an earlier study's files (its manifest's) that this one does not write\n"
    "are removed. A DIR holding a file no manifest lists (or one changed since cablesim wrote it), or a\n"
    "stopped study's runs done (below), is refused, unless --force: then the study is written beside such\n"
    "files, and none of them is removed, and it replaces the stopped study. --quiet prints nothing but\n"
    "errors (no progress, no closing lines).\n"
    "SIGINT (Ctrl-C) or SIGTERM: the runs under way finish, no other starts, and DIR gets the runs done,\n"
    "marked partial (summary.md, summary.json \"partial\": true; exit status 130 or 143); before the\n"
    "runs begin, it leaves DIR as it was. --resume DIR\n"
    "reads them back from DIR/runs.csv, runs the others as those were run (the study's own --set, --t-end\n"
    "and --dt: none of the study's options is taken with --resume) and writes the whole study; it refuses\n"
    "a DIR whose study changed (spec, model, values, cablesim). A new study (no --resume) into a DIR\n"
    "holding a stopped one's runs done (its summary.json partial, or DIR/.cablesim-journal, the journal\n"
    "of a sweep killed before its outputs) is refused, exit status 1 and DIR as it was, naming how many:\n"
    "--resume DIR runs the rest of that study, --force starts the new one afresh and replaces it.\n"
    "Exit status: 0 done, 1 DIR refused or the outputs failed, 2 a bad spec or command line, 128 + the\n"
    "signal: partial.\n";

static const cs_cli sweep_cli = {"sweep", sweep_usage};

/* ---- the command line ---- */

static int sweep_bad_usage(int rank, const char *what, const char *arg) {
    if (rank == 0) cs_cli_usage_error(&sweep_cli, "%s%s%s", what, arg ? ": " : "", arg ? arg : "");
    return EXIT_BAD;
}

/* The command line: the study's def (cablesim/sweep.h) and the strings it points to. */
typedef struct sweep_args {
    cs_sweep_def def;
    int quiet;
    const char *sets[256], *given[256], *allow[64];
    char set_text[256][1100];   /* --t-end and --dt as sets */
    char given_text[256][1100]; /* and as the user gave them, which their problems name */
} sweep_args;

/* The command line into a. Returns 0, -1 after --help (exit 0), or EXIT_BAD. */
static int parse_opts(int argc, char **argv, sweep_args *a, int rank) {
    enum { THREADS = 1000, RUNS, SEED, SET, T_END, DT, NETCDF, QUIET, RESUME, FORCE, ALLOW };
    static const struct option longopts[] = {
        {"out", required_argument, NULL, 'o'},   {"threads", required_argument, NULL, THREADS},
        {"runs", required_argument, NULL, RUNS}, {"seed", required_argument, NULL, SEED},
        {"set", required_argument, NULL, SET},   {"t-end", required_argument, NULL, T_END},
        {"dt", required_argument, NULL, DT},     {"netcdf", no_argument, NULL, NETCDF},
        {"quiet", no_argument, NULL, QUIET},     {"resume", required_argument, NULL, RESUME},
        {"force", no_argument, NULL, FORCE},     {"allow-path", required_argument, NULL, ALLOW},
        {"help", no_argument, NULL, 'h'},        {NULL, 0, NULL, 0}};
    cs_sweep_def *d = &a->def;
    *d = cs_default_sweep_def();
    d->sets = a->sets, d->sets_given = a->given;
    d->allow = a->allow;
    d->force_given = "--force";
    int v, study = 0;            /* options that define the study, which --resume takes from DIR */
    char first_study[1100] = ""; /* the first of them as given, which a refusal with --resume names */
    optind = 1;
    opterr = 0;
    while ((v = rank == 0 ? cs_cli_next(&sweep_cli, argc, argv, "ho:", longopts)
                          : getopt_long(argc - 1, argv + 1, ":ho:", longopts, NULL)) != -1) {
        char *end;
        switch (v) {
        case 'h':
            if (rank == 0) cs_cli_help(&sweep_cli);
            return -1;
        case 'o':
            d->out_dir = optarg;
            study = 1;
            break;
        case THREADS:
            d->threads = (int)strtol(optarg, &end, 10);
            if (*end || end == optarg || d->threads < 1 || d->threads > 1024)
                return sweep_bad_usage(rank, "--threads takes 1 to 1024", optarg);
            break;
        case RUNS:
            d->runs = strtol(optarg, &end, 10);
            if (*end || end == optarg || d->runs < 1 || d->runs > 1000000)
                return sweep_bad_usage(rank, "--runs takes 1 to 1000000", optarg);
            study = 1;
            break;
        case SEED:
            d->seed = optarg;
            study = 1;
            break;
        case SET:
        case T_END:
        case DT:
            if (d->set_count == 256)
                return sweep_bad_usage(rank, "more than 256 --set, --t-end and --dt", optarg);
            if (v == SET) {
                a->sets[d->set_count] = optarg, a->given[d->set_count] = NULL;
            } else {
                snprintf(a->set_text[d->set_count], sizeof a->set_text[0], "scenario.%s=%s",
                         v == T_END ? "t_end" : "dt", optarg);
                snprintf(a->given_text[d->set_count], sizeof a->given_text[0], "--%s %s",
                         v == T_END ? "t-end" : "dt", optarg);
                a->sets[d->set_count] = a->set_text[d->set_count];
                a->given[d->set_count] = a->given_text[d->set_count];
            }
            d->set_count++;
            study = 1;
            break;
        case NETCDF:
            d->netcdf = 1;
            study = 1;
            break;
        case ALLOW:
            if (d->allow_count == 64) return sweep_bad_usage(rank, "more than 64 --allow-path", optarg);
            a->allow[d->allow_count++] = optarg;
            study = 1;
            break;
        case QUIET:
            a->quiet = 1;
            break;
        case FORCE:
            d->force = 1;
            break;
        case RESUME:
            d->resume = optarg;
            break;
        default:
            return EXIT_BAD;
        }
        if (study && !first_study[0]) { /* this option is the first that defines the study */
            const struct option *o = longopts;
            while (o->name && o->val != v)
                o++;
            snprintf(first_study, sizeof first_study, "%s%s%s%s", v == 'o' ? "-o" : "--",
                     v == 'o' ? "" : o->name, optarg ? " " : "", optarg ? optarg : "");
        }
    }
    int operands = argc - 1 - optind;
    if (d->resume && (operands > 0 || study)) {
        if (rank == 0)
            cs_cli_usage_error(
                &sweep_cli,
                "%s with --resume: --resume DIR takes the study as DIR/summary.json records it "
                "and makes the runs left as those done, with one model, values, time step "
                "and end (expected no SPEC, -o, --runs, --seed, --set, --t-end, --dt, --netcdf "
                "or --allow-path with --resume)",
                operands > 0 ? argv[1 + optind] : first_study);
        return EXIT_BAD;
    }
    /* the problems on stderr; the progress and the closing lines unless --quiet, from rank 0 alone */
    d->errors = stderr;
    d->progress = a->quiet || rank > 0 ? NULL : stderr;
    d->closing = a->quiet || rank > 0 ? NULL : stdout;
    if (d->resume) return 0;
    if (operands > 1) return sweep_bad_usage(rank, "more than one spec file", argv[2 + optind]);
    if (operands < 1) return sweep_bad_usage(rank, "no spec file", NULL);
    d->spec = argv[1 + optind];
    return 0;
}

/* The threads of this process: asked for, or the cores shared among the ranks of this machine. */
static int thread_count(int asked, int local_ranks) {
#ifdef _OPENMP
    if (asked > 0) return asked;
    int t = omp_get_max_threads() / (local_ranks > 0 ? local_ranks : 1);
    return t > 0 ? t : 1;
#else
    (void)local_ranks;
    if (asked > 1) fprintf(stderr, "cablesim sweep: built without OpenMP, running on 1 thread\n");
    return 1;
#endif
}

/* The file argument of `cablesim check FILE [--set PATH=VALUE]...`: the first word that is not an option or
 * an option's value. */
static const char *check_file(int argc, char **argv) {
    static const char *const valued[] = {"-o",    "--out",   "--threads", "--runs",   "--seed",
                                         "--set", "--t-end", "--dt",      "--resume", "--allow-path"};
    for (int i = 2; i < argc; i++) {
        if (argv[i][0] != '-') return argv[i];
        for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++)
            if (strcmp(argv[i], valued[k]) == 0) {
                i++; /* its value */
                break;
            }
    }
    return NULL;
}

int cs_sweep_check_wanted(int argc, char **argv) {
    const char *f = check_file(argc, argv);
    return f && cs_sweep_is_spec(f);
}

/* The exit status of a study's outcome: 0 done, 128 + the signal that stopped it, 2 a bad spec, 1 else. */
static int exit_status(cs_status st, const cs_sweep *study) {
    return st == CS_OK            ? (cs_sweep_stopped_by(study) ? 128 + cs_sweep_stopped_by(study) : 0)
           : st == CS_ERR_INVALID ? EXIT_BAD
                                  : EXIT_RUN;
}

int cs_sweep_check_command(int argc, char **argv) {
    static sweep_args a;
    memset(&a, 0, sizeof a);
    int rc = parse_opts(argc, argv, &a, 0);
    if (rc != 0) return rc < 0 ? 0 : rc;
    cs_sweep *study = NULL;
    cs_error err;
    cs_status st = cs_sweep_check_study(&a.def, &study, &err); /* its problems said on stderr */
    rc = exit_status(st, study);
    if (st == CS_OK) {
        static const char *const methods[] = {"grid", "Monte Carlo", "Latin hypercube"};
        int vars = cs_sweep_var_count(study);
        printf("%s: a valid sweep spec: %s of %ld runs over %d value%s of %s\n", cs_sweep_spec_file(study),
               methods[cs_sweep_method_of(study)], cs_sweep_run_count(study), vars, vars == 1 ? "" : "s",
               cs_sweep_model(study));
    }
    cs_sweep_free(study);
    return rc;
}

/* OpenMP's parallel region for the library's runs: worker on each of the threads. */
static void omp_parallel(int threads, void (*worker)(void *arg), void *arg) {
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#else
    (void)threads;
#endif
    worker(arg);
}

int cs_sweep_command(int argc, char **argv) {
    cs_sweep_ranks_def ranks = cs_default_sweep_ranks();
    int local = 1; /* the ranks on this machine, which share its cores */
    char command[8192];
    cs_cli_command_line(argc, argv, command, sizeof command); /* as typed: getopt_long reorders argv */
#ifdef CS_MPI
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided); /* sweep_mpi.h */
    MPI_Comm_rank(MPI_COMM_WORLD, &ranks.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks.ranks);
    if (provided < MPI_THREAD_SERIALIZED) {
        if (ranks.rank == 0)
            fprintf(stderr, "cablesim sweep: this MPI gives no MPI_THREAD_SERIALIZED, which the sweep's "
                            "journal of every rank's runs needs\n");
        MPI_Finalize();
        return EXIT_RUN;
    }
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, ranks.rank, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &local);
    MPI_Comm_free(&node);
    cs_sweep_mpi_hooks(&ranks);
#else
    const char *world = getenv("OMPI_COMM_WORLD_SIZE");
    if (!world) world = getenv("PMI_SIZE");
    if (world && atoi(world) > 1) {
        const char *r = getenv("OMPI_COMM_WORLD_RANK");
        if (!r || atoi(r) == 0)
            fprintf(stderr,
                    "cablesim sweep: this cablesim is built without MPI, and %s copies of it would each "
                    "run the whole sweep: run cablesim-mpi under mpirun\n",
                    world);
        return EXIT_BAD;
    }
#endif
    static sweep_args a; /* its strings outlive the study */
    memset(&a, 0, sizeof a);
    int rc = parse_opts(argc, argv, &a, ranks.rank);
    if (rc < 0) {
        rc = 0; /* --help */
    } else if (rc == 0) {
        a.def.threads = thread_count(a.def.threads, local);
        a.def.parallel = omp_parallel;
        a.def.command = command;
        a.def.ranks = &ranks;
        cs_sweep *study = NULL;
        cs_error err;
        /* the program's handlers, the study's own while it runs: a signal before the runs (its folder made
         * and locked, its journal begun) leaves the folder as it was */
        cs_cli_catch_signals();
        cs_status st = cs_sweep_study(&a.def, &study, &err); /* its problems said on stderr */
        rc = exit_status(st, study);
        cs_sweep_free(study);
    }
#ifdef CS_MPI
    MPI_Finalize();
#endif
    return rc;
}
