/* SPDX-License-Identifier: MIT */
/** @file
 * Model files: read a model (YAML, units on every value), resolve its named parts and file references,
 * apply `--set` overrides, check it, and fill the engine's definition structs (def.h). Every problem is
 * collected as "file:line:column: what is wrong (what was expected)". A loader holds all its own state:
 * use one per thread. */
#ifndef CABLESIM_LOADER_H
#define CABLESIM_LOADER_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A model file's loader (opaque): its unit database, the files it read, overrides and problems. */
typedef struct cs_loader cs_loader;

/** A loaded model: the engine's definitions of the barrier, the vehicle and the attack, in SI. The names,
 * files and arrays behind barrier.cables, barrier.posts and barrier.rails belong to the loader: they last
 * until its next load, cs_loader_reset, cs_loader_reuse or cs_loader_free. It starts with its size, as the
 * engine's views do (sim.h): the loader fills that much of it; new fields go at its end. */
typedef struct cs_model_input {
    size_t size;              /**< the size of this struct in the program: set it (cs_model_input in =
                                   {.size = sizeof in}); the loader fills only that much, and the functions
                                   that take it back need every field up to scenario */
    const char *name;         /**< the model's name (the default output folder is results/NAME) */
    const char *file;         /**< the model file as given */
    cs_barrier_def barrier;   /**< cables, posts, rails and anchors */
    cs_vehicle_def vehicle;   /**< the vehicle */
    cs_scenario_def scenario; /**< the attack and the integration */
} cs_model_input;

/** Create a loader.
 * @param data_dir the folder of the parts library (the YAML files of data/), or NULL to find it: the
 * environment variable CABLESIM_DATA, else PREFIX/share/cablesim of the installed library or command that
 * runs, else the source tree's data/ for a program of the build tree (docs/parts.md).
 * @param err filled on failure (may be NULL)
 * @return the loader, or NULL with err filled: CS_ERR_MEMORY if memory is short, CS_ERR_IO if the unit
 * database (udunits2) cannot be read. */
CS_API cs_loader *cs_loader_create(const char *data_dir, cs_error *err);
/** Free a loader and everything it returned. NULL is allowed. */
CS_API void cs_loader_free(cs_loader *loader);

/** The folder of the parts library as cs_loader_create resolved it ("" when none was found: loading a
 * model that names a part then reports why). Its validation/ holds the values `cablesim validate` compares
 * with. */
CS_API const char *cs_loader_data_dir(const cs_loader *loader);

/** Allow the files a model names (`file:`) to be read from a folder and its subfolders, beyond the folder
 * of the model file loaded (and its subfolders) and the parts library's, which are always allowed (as
 * `cablesim run --allow-path DIR`). It lasts for the loader's life.
 * @param loader the loader
 * @param dir the folder
 * @param err filled on failure (may be NULL)
 * @return CS_OK, or CS_ERR_INVALID when dir is not a folder. */
CS_API cs_status cs_loader_allow_path(cs_loader *loader, const char *dir, cs_error *err);

/** Queue an override for the next load, as `cablesim run --set` does.
 * @param loader the loader
 * @param assignment "PATH=VALUE", the path of a value in the model file with units on the value:
 *        "scenario.speed=35 mph", "barrier.posts[0].spacing=6 ft", "vehicle=M".
 * @return CS_OK, or CS_ERR_INVALID when it is not PATH=VALUE (the problem is recorded). */
CS_API cs_status cs_loader_set(cs_loader *loader, const char *assignment);
/** Queue an override as cs_loader_set does, for a command-line option that stands for one (`cablesim run
 * --dt T` is scenario.dt=T): its problems name the option as the user gave it, not the --set.
 * @param loader the loader
 * @param assignment "PATH=VALUE" as for cs_loader_set: "scenario.dt=2 ms"
 * @param given the option as given, which the messages name: "--dt 2 ms" (NULL: as cs_loader_set)
 * @return as cs_loader_set (CS_ERR_MEMORY: no room to keep it). */
CS_API cs_status cs_loader_set_given(cs_loader *loader, const char *assignment, const char *given);
/** Load, resolve, override and check a model file. A `file:` it names is found from the folder of the file
 * naming it, and read only when it is a regular file of at most 64 MB in the folder of path (or a
 * subfolder), the parts library's, or a folder of cs_loader_allow_path; a named file that is not a model
 * is reported at its place, without its text.
 * @param loader the loader
 * @param path the model file
 * @param out filled with the model on success, to its size
 * @return CS_OK, or CS_ERR_INVALID with every problem recorded (cs_loader_error_count, cs_loader_error):
 *         also out's size 0 or larger than this library's. */
CS_API cs_status cs_loader_load(cs_loader *loader, const char *path, cs_model_input *out);
/** The same as cs_loader_load for a model file's contents held in memory.
 * @param loader the loader
 * @param name stands for the file in messages; files the model refers to are found from its folder
 * @param data the contents, needed only during the call
 * @param size their length in bytes
 * @param out filled with the model on success, to its size
 * @return CS_OK, or CS_ERR_INVALID with every problem recorded. */
CS_API cs_status cs_loader_load_buffer(cs_loader *loader, const char *name, const char *data, size_t size,
                                       cs_model_input *out);
/** Forget every loaded file, override and problem, keeping the unit database: ready for a new model.
 * Whatever an earlier load returned becomes invalid. */
CS_API void cs_loader_reset(cs_loader *loader);
/** Forget the last load's overrides, problems and what it returned, keeping the files it read (parsed
 * once) and the parts library: for another load of the same model with other overrides (a sweep's runs).
 * After a load with problems it is cs_loader_reset. */
CS_API void cs_loader_reuse(cs_loader *loader);
/** 64-bit FNV-1a of a loaded model's definitions (barrier, vehicle, scenario: every value as the engine
 * gets it, in SI), not of its name or file: two loads give the same hash exactly when they give the engine
 * the same numbers; 0 for an input whose size does not reach its scenario. */
CS_API unsigned long long cs_model_input_hash(const cs_model_input *in);
/** Build the engine's model from a loaded input (cs_model_create). On failure the engine's message is
 * recorded at the place in the file, or the override, of the element it names (or that the input's size
 * does not reach its scenario).
 * @return the model (free it with cs_model_free), or NULL. */
CS_API cs_model *cs_loader_build(cs_loader *loader, const cs_model_input *in);

/** The number of problems recorded, each once. */
CS_API int cs_loader_error_count(cs_loader *loader);
/** The i-th problem, "file:line:column: what is wrong (what was expected)", sorted by file and place. */
CS_API const char *cs_loader_error(cs_loader *loader, int i);
/** Print every problem, one a line. */
CS_API void cs_loader_print_errors(cs_loader *loader, FILE *out);

/** The kinds of named parts in the parts library (and in a model file's own `parts:`). */
typedef enum cs_part_kind {
    CS_PART_VEHICLE,   /**< a cs_vehicle_def (data/vehicles.yaml) */
    CS_PART_ROPE,      /**< a cs_rope_def (data/ropes.yaml) */
    CS_PART_SECTION,   /**< a post's cs_section_def (data/sections.yaml) */
    CS_PART_RAIL,      /**< a cs_rail_def (data/rails.yaml) */
    CS_PART_KIND_COUNT /**< the number of kinds */
} cs_part_kind;

/** The names of the library's parts of a kind, in file order.
 * @param loader the loader
 * @param kind the kind
 * @param names set to the names (they belong to the loader)
 * @param descriptions set to their descriptions, in the same order
 * @return their number, or -1 when the library cannot be read (problems recorded). */
CS_API int cs_loader_library(cs_loader *loader, cs_part_kind kind, const char ***names,
                             const char ***descriptions);
/** Resolve a named part into its definition.
 * @param loader the loader
 * @param kind the kind
 * @param name the part's name
 * @param def a cs_vehicle_def, cs_rope_def, cs_section_def or cs_rail_def by kind
 * @return CS_OK, or CS_ERR_INVALID with the problem recorded. */
CS_API cs_status cs_loader_part(cs_loader *loader, cs_part_kind kind, const char *name, void *def);

#ifdef __cplusplus
}
#endif
#endif
