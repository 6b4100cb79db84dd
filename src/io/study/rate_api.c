/* SPDX-License-Identifier: MIT */
/* The interface's ratings (cablesim/rating.h): a finished run rated as summary.json and `cablesim rate`
 * rate it (rating.c), handed back at the caller's size. */
#include <string.h>

#include "rating.h"
#include "status.h"

cs_status cs_standard_from_name(const char *name, cs_standard *out) {
    return name && cs_standard_parse(name, out) == 0 ? CS_OK : CS_ERR_INVALID;
}

cs_status cs_rate(const cs_model *model, const cs_state *state, cs_standard standard,
                  const char *vehicle_class, cs_rating_result *out, cs_error *err) {
    if (cs_status_sized(out, sizeof *out, "cs_rating_result", err) != CS_OK) return CS_ERR_INVALID;
    if ((unsigned)standard >= CS_STANDARD_COUNT)
        return cs_status_set(err, CS_ERR_INVALID, "no such standard");
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(state, &sm, NULL);
    if (sm.outcome == CS_RUNNING)
        return cs_status_set(err, CS_ERR_INVALID, "the run has not ended: rate it once cs_run returns");
    const cs_scenario_def *sc = cs_model_scenario(model);
    cs_rating_rules rules = cs_default_rating_rules();
    cs_rating r =
        cs_rate_as_run(standard, vehicle_class, cs_model_vehicle(model), sc->speed, sc->angle, &sm, &rules);
    cs_rating_result full = {.size = sizeof full,
                             .standard = r.standard,
                             .speed_mph = r.speed_mph,
                             .penetration_m = r.penetration,
                             .rated = r.rated,
                             .tested = r.tested,
                             .through = r.through};
    snprintf(full.vehicle_class, sizeof full.vehicle_class, "%s", r.vehicle_class);
    snprintf(full.label, sizeof full.label, "%s", r.label);
    snprintf(full.note, sizeof full.note, "%s", r.note);
    cs_rating_text(&r, full.text, sizeof full.text);
    return cs_status_put_sized(out, &full, sizeof full, "cs_rating_result", err);
}
