/* Model files: read (YAML through yamltree.h, units via udunits2), resolve parts and file references,
 * apply --set overrides, check, and fill the engine's definition structs. Every problem is collected as
 * "file:line:column: what is wrong (what was expected)". A loader holds all its own state. */
#ifndef CS_LOADER_H
#define CS_LOADER_H

#include <stdio.h>

#include "cablesim/cablesim.h"

typedef struct cs_loader cs_loader;

/* A loaded model. The arrays behind barrier.cables and barrier.posts belong to the loader. */
typedef struct cs_model_input {
    const char *name; /* model name (results/<name>) */
    const char *file; /* the model file */
    cs_barrier_def barrier;
    cs_vehicle_def vehicle;
    cs_scenario_def scenario;
} cs_model_input;

/* data_dir: the parts library (NULL: $CABLESIM_DATA_DIR, else the source tree's data/). NULL if the
 * unit database cannot be loaded (why filled). */
cs_loader *cs_loader_create(const char *data_dir, char *why, size_t why_size);
void cs_loader_free(cs_loader *loader);

/* The folder of the parts library (data_dir as resolved by cs_loader_create); data/validation/ is in it. */
const char *cs_loader_data_dir(const cs_loader *loader);

/* Queue an override "PATH=VALUE" for the next load. Returns 0, or -1 (error recorded). */
int cs_loader_set(cs_loader *loader, const char *assignment);
/* Load, resolve, override and check a model. Returns 0, or -1 with the errors recorded. */
int cs_loader_load(cs_loader *loader, const char *path, cs_model_input *out);
/* The same for a model file's contents held in memory (size bytes, needed only during the call). name
 * stands for the file in messages; files the model refers to are found from name's folder. */
int cs_loader_load_buffer(cs_loader *loader, const char *name, const char *data, size_t size,
                          cs_model_input *out);
/* Forget every loaded file, override and error, keeping the unit database: ready for a new model.
 * Whatever an earlier load returned becomes invalid. */
void cs_loader_reset(cs_loader *loader);
/* Forget the last load's overrides, errors and what it resolved and returned, keeping the files it
 * read (parsed once) and the parts library, for another load of the same model with other overrides
 * (a sweep's runs). After a load with errors it is cs_loader_reset. */
void cs_loader_reuse(cs_loader *loader);
/* 64-bit FNV-1a of a loaded model's definitions (barrier, vehicle, scenario: every value as the engine
 * gets it, in SI), not of its name or file: two loads give the same hash exactly when they give the engine
 * the same numbers. */
unsigned long long cs_model_input_hash(const cs_model_input *in);

/* Build the engine model from a loaded input; on failure the engine's message is recorded at the
 * location of the element it names. */
cs_model *cs_loader_build(cs_loader *loader, const cs_model_input *in);

int cs_loader_error_count(cs_loader *loader); /* each problem once */
/* The i-th problem, sorted by file and line. */
const char *cs_loader_error(cs_loader *loader, int i);
void cs_loader_print_errors(cs_loader *loader, FILE *out);

/* ---- the parts library (and a model file's own parts) ---- */
typedef enum cs_part_kind {
    CS_PART_VEHICLE,
    CS_PART_ROPE,
    CS_PART_SECTION,
    CS_PART_RAIL,
    CS_PART_KIND_COUNT
} cs_part_kind;

/* Names of the library's parts of a kind, in file order. Returns the count (-1: library errors). */
int cs_loader_library(cs_loader *loader, cs_part_kind kind, const char ***names, const char ***descriptions);
/* Resolve a named library part into its definition (cs_vehicle_def, cs_rope_def or cs_section_def).
 * Returns 0, or -1 with errors recorded. */
int cs_loader_part(cs_loader *loader, cs_part_kind kind, const char *name, void *def);

#endif
