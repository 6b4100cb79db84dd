/* SPDX-License-Identifier: MIT */
/** @file
 * cablesim: progressive-failure simulation of cable barriers struck by a vehicle. The umbrella header:
 * the engine's definitions (def.h) and its model, state, step and run (sim.h), model files (loader.h),
 * a run's time histories and output files (output.h), a run's anti-ram rating (rating.h), studies over
 * a model's values (sweep.h), runs side by side (compare.h), and the US customary units in SI (units.h). Link
 * with libcablesim (pkg-config cablesim, or CMake's find_package(cablesim) and the target
 * cablesim::cablesim). */
#ifndef CABLESIM_H
#define CABLESIM_H

/** The version of these headers, MAJOR.MINOR.PATCH (CMakeLists.txt takes the project's version from it). */
#define CS_VERSION_STRING "0.1.0"

#include "cablesim/compare.h"
#include "cablesim/def.h"
#include "cablesim/loader.h"
#include "cablesim/output.h"
#include "cablesim/rating.h"
#include "cablesim/sim.h"
#include "cablesim/sweep.h"
#include "cablesim/units.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The version of the library linked, MAJOR.MINOR.PATCH: CS_VERSION_STRING of the headers it was built
 * with. */
CS_API const char *cs_version(void);

#ifdef __cplusplus
}
#endif
#endif
