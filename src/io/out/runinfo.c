/* SPDX-License-Identifier: MIT */
/* What a run's outputs say beside its results (writers.h): its designations as run, the record of a run
 * made through the library, the model hash's text, and the posts nearest the impact (which the plots and
 * the report follow). */
#include <math.h>
#include <stdio.h>

#include "writers.h"

void cs_run_info_rate(cs_run_info *info, const cs_model_input *in, const cs_summary *summary) {
    cs_rating_rules rules = cs_default_rating_rules();
    const cs_standard standards[] = {CS_ASTM_F2656, CS_SD_STD_02_01};
    const char *klass = cs_rating_vehicle_class(in->vehicle.mass);
    info->rating_count = 0;
    for (int i = 0; i < 2 && klass; i++)
        if (cs_standard_tests_class(standards[i], klass))
            info->ratings[info->rating_count++] = cs_rate_as_run(
                standards[i], NULL, &in->vehicle, in->scenario.speed, in->scenario.angle, summary, &rules);
}

void cs_run_info_motion(cs_run_info *info, const cs_model_input *in, const cs_record *rec,
                        const cs_state *state, const cs_summary *summary) {
    info->motion = 1;
    cs_record_roll_pitch_peaks(rec, &info->roll_peak, &info->pitch_peak);
    info->occupant_ok = cs_occupant_risk_for_run(rec, summary->first_contact_time_s,
                                                 info->occupant_at ? info->occupant_point : NULL,
                                                 &info->occupant, &info->occupant_error) == CS_OK;
    info->criteria_count = 0;
    if (!cs_roadside_test_as_run(&in->vehicle, in->scenario.speed, in->scenario.angle, &info->criteria_test))
        return;
    cs_exit_box_of_record(rec, &in->vehicle, in->scenario.impact_x,
                          summary->outcome == CS_REDIRECTED ? summary->exit_time_s : -1.0, &info->exit_box);
    info->exit_box.heading_back &=
        summary->outcome == CS_REDIRECTED; /* only a vehicle that left has an exit */
    /* the standards take the occupant risk at the CG: with --occupant-at, the criteria judge the CG's */
    cs_occupant_risk cg;
    cs_error cg_error = {CS_OK, ""};
    int cg_ok = info->occupant_ok;
    const cs_occupant_risk *judged = &info->occupant;
    const char *why = info->occupant_error.message;
    if (info->occupant_at) {
        cg_ok = cs_occupant_risk_for_run(rec, summary->first_contact_time_s, NULL, &cg, &cg_error) == CS_OK;
        judged = &cg, why = cg_error.message;
    }
    cs_test_result r = {
        summary, cg_ok ? judged : NULL, why, info->roll_peak, info->pitch_peak, &info->exit_box, state,
    };
    info->criteria_count = cs_roadside_criteria(&info->criteria_test, &r, info->criteria);
}

void cs_run_info_of(cs_run_info *info, const cs_model_input *in, const cs_state *state) {
    *info = (cs_run_info){.model_hash = cs_model_input_hash(in)};
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    cs_run_info_rate(info, in, &s);
}

void cs_model_hash_text(unsigned long long hash, char buf[17]) {
    snprintf(buf, 17, "%016llx", hash);
}

int cs_nearest_posts(const cs_model_input *in, int *idx, int max) {
    int count = 0;
    double x0 = in->scenario.impact_x;
    for (int p = 0; p < in->barrier.post_count; p++) {
        double dp = fabs(in->barrier.posts[p].x - x0);
        int j = count < max ? count++ : max;
        while (j > 0 && fabs(in->barrier.posts[idx[j - 1]].x - x0) > dp) {
            if (j < max) idx[j] = idx[j - 1];
            j--;
        }
        if (j < max) idx[j] = p;
    }
    return count;
}
