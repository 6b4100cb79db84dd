/* SPDX-License-Identifier: MIT */
/** @file
 * Anti-ram ratings of a run (docs/ratings.md): how its result reads against SD-STD-02.01 (1985), its
 * revision A (2003) or ASTM F2656, as `cablesim rate` and summary.json give it. A rating is read from a
 * finished run: its vehicle, its impact speed and angle, its outcome and its penetration. */
#ifndef CABLESIM_RATING_H
#define CABLESIM_RATING_H

#include "cablesim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An anti-ram standard. */
typedef enum cs_standard {
    CS_SD_STD_02_01 = 0, /**< SD-STD-02.01 (1985): K4, K8, K12 and L1 to L3 */
    CS_SD_STD_02_01A,    /**< its revision A (2003): penetration measured to the cargo bed's front */
    CS_ASTM_F2656,       /**< ASTM F2656: M30, M40, M50 ... and P1 to P4 */
    CS_STANDARD_COUNT    /**< the number of standards */
} cs_standard;

/** A run's rating against a standard. */
typedef struct cs_rating_result {
    size_t size;           /**< the size of this struct in the program: set it (cs_rating_result r =
                                {.size = sizeof r}); the library fills only that much */
    cs_standard standard;  /**< the standard */
    char vehicle_class[8]; /**< the test vehicle: "C", "PU", "M", "H" (SD-STD: "M"); "" if none */
    int speed_mph;         /**< the speed designation, mph: 30, 40, 50, 60; 0 if none */
    double penetration_m;  /**< m, as the standard measures it; HUGE_VAL through the barrier, NAN unrated */
    char label[24];        /**< "M40/P1", "K8/L2"; "none" (a test, no rating earned); "not rated" */
    int rated;             /**< 1 if label is a rating */
    int tested;            /**< 0 if the run is not the standard's test ("not rated": note says why) */
    int through;           /**< 1 if the vehicle got through the barrier */
    char note[160];        /**< why not rated or none, or "the vehicle got through"; "" if nothing */
    char text[256];        /**< the one wording of `cablesim rate` and summary.json: the standard's title,
                                the label, and in brackets the note and a rating's penetration as the
                                standard measures it ("ASTM F2656 M40/P2 (penetration 1.50 m (4.9 ft),
                                front of the cargo bed, from the barrier's protected-side face)") */
} cs_rating_result;

/** A standard's name as `cablesim rate --standard` takes it: "sd-std-02.01", "sd-std-02.01a", "astm-f2656".
 */
CS_API const char *cs_standard_name(cs_standard standard);
/** The standard of a name (as cs_standard_name gives it).
 * @return CS_OK, or CS_ERR_INVALID with *out unchanged if no standard has that name. */
CS_API cs_status cs_standard_from_name(const char *name, cs_standard *out);

/** Rate a finished run.
 * @param model the model that ran (its vehicle, and its scenario's speed and angle)
 * @param state the state at the run's end
 * @param standard the standard
 * @param vehicle_class the test vehicle the run stands for ("C", "PU", "M", "H"), or NULL: the one of the
 *        vehicle's mass (within 5%)
 * @param out filled with the rating, to its size ("not rated" with a note if the vehicle is none of the
 *        standard's, or the impact is not head-on)
 * @param err filled on failure (may be NULL)
 * @return CS_OK, or CS_ERR_INVALID (out's size 0, or larger than this library's; a run not ended). */
CS_API cs_status cs_rate(const cs_model *model, const cs_state *state, cs_standard standard,
                         const char *vehicle_class, cs_rating_result *out, cs_error *err);

#ifdef __cplusplus
}
#endif
#endif
