/* SPDX-License-Identifier: MIT */
#include "record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static size_t frame_bytes(const cs_record *rec) {
    size_t nc = (size_t)rec->cable_count, np = (size_t)rec->post_count, nn = (size_t)rec->max_nodes;
    return sizeof(cs_vehicle_view) + sizeof(cs_energy) + nc * sizeof(cs_cable_view) +
           np * (rec->lean ? sizeof(cs_post_state) : sizeof(cs_post_view)) + 2 * sizeof(cs_anchor_view) +
           (nn ? nc * (sizeof(int) + nn * 4 * sizeof(double)) : 0);
}

/* The frames a run of the model can record: one at its start, one each output interval (each step if
 * the interval is shorter) to t_end, and the last; 0 if the scenario does not say. */
static double scenario_frames(const cs_model *model) {
    const cs_scenario_def *sc = cs_model_scenario(model);
    if (!sc || !(sc->dt > 0.0) || !(sc->t_end > 0.0)) return 0.0;
    double every = sc->output_interval < sc->dt ? sc->dt : sc->output_interval;
    double frames = sc->t_end / every + 3.0; /* the start, the last and a step's rounding */
    return frames < 1e9 ? frames : 1e9;
}

int cs_record_init_for(cs_record *rec, const cs_model *model, cs_record_kind kind) {
    memset(rec, 0, sizeof *rec);
    rec->cable_count = cs_model_cable_count(model);
    rec->post_count = cs_model_post_count(model);
    rec->lean = kind == CS_RECORD_FILES;
    /* two anchors, every post, the vehicle's corners and wheels */
    rec->max_nodes = rec->lean ? 0 : cs_model_path_capacity(model);
    double frame = (double)frame_bytes(rec), frames = CS_RECORD_BYTES / frame;
    rec->max_frames = frames < 64.0 ? 64 : (frames > 1e8 ? 100000000 : (int)frames);
    double first = scenario_frames(model), most = CS_RECORD_FIRST_BYTES / frame;
    if (first > most) first = most;
    rec->first_frames = first < 256.0 ? 256 : (int)first;
    rec->stride = 1;
    return 0;
}

int cs_record_init(cs_record *rec, const cs_model *model) {
    return cs_record_init_for(rec, model, CS_RECORD_ALL);
}

/* Frame `to` becomes a copy of frame `from`. */
static void move_frame(cs_record *rec, int to, int from) {
    size_t nc = (size_t)rec->cable_count, np = (size_t)rec->post_count, nn = (size_t)rec->max_nodes;
    size_t t = (size_t)to, f = (size_t)from;
    rec->vehicle[t] = rec->vehicle[f];
    rec->energy[t] = rec->energy[f];
    memmove(rec->cables + t * nc, rec->cables + f * nc, nc * sizeof *rec->cables);
    if (rec->lean)
        memmove(rec->post_states + t * np, rec->post_states + f * np, np * sizeof *rec->post_states);
    else
        memmove(rec->posts + t * np, rec->posts + f * np, np * sizeof *rec->posts);
    memmove(rec->anchors + t * 2, rec->anchors + f * 2, 2 * sizeof *rec->anchors);
    if (!nn) return;
    memmove(rec->path_count + t * nc, rec->path_count + f * nc, nc * sizeof *rec->path_count);
    memmove(rec->path_xyz + t * nc * nn * 3, rec->path_xyz + f * nc * nn * 3, nc * nn * 3 * sizeof(double));
    memmove(rec->path_tension + t * nc * nn, rec->path_tension + f * nc * nn, nc * nn * sizeof(double));
}

/* Full: keep frames 0, 2, 4, ... and record every other output from now on. */
static void thin(cs_record *rec) {
    int kept = 0;
    for (int f = 0; f < rec->frame_count; f += 2)
        move_frame(rec, kept++, f);
    rec->frame_count = kept;
    rec->stride *= 2;
}

static int grow(cs_record *rec) {
    int cap = rec->capacity ? 2 * rec->capacity : rec->first_frames;
    if (cap > rec->max_frames) cap = rec->max_frames;
    size_t nc = (size_t)rec->cable_count, np = (size_t)rec->post_count, nn = (size_t)rec->max_nodes;
    void *p;
#define CS_GROW(field, count)                                                                                \
    p = realloc(rec->field, (size_t)cap * (count) * sizeof *rec->field);                                     \
    if (!p) return -1;                                                                                       \
    rec->field = p;
    CS_GROW(vehicle, 1)
    CS_GROW(energy, 1)
    CS_GROW(cables, nc)
    if (rec->lean) {
        CS_GROW(post_states, np)
    } else {
        CS_GROW(posts, np)
    }
    CS_GROW(anchors, 2)
    if (nn) {
        CS_GROW(path_count, nc)
        CS_GROW(path_xyz, nc * nn * 3)
        CS_GROW(path_tension, nc * nn)
    }
#undef CS_GROW
    rec->capacity = cap;
    return 0;
}

void cs_record_frame(const cs_model *model, const cs_state *state, void *user) {
    cs_record *rec = user;
    if (rec->failed) return;
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(state, &sm, NULL);
    int last = sm.outcome != CS_RUNNING;
    if (rec->calls++ % rec->stride != 0 && !last) return;
    if (rec->frame_count == rec->max_frames) thin(rec);
    if (rec->frame_count == rec->capacity && grow(rec) != 0) {
        rec->failed = 1;
        return;
    }
    int f = rec->frame_count;
    rec->vehicle[f].size = sizeof rec->vehicle[f];
    cs_state_vehicle(model, state, &rec->vehicle[f], NULL);
    rec->energy[f].size = sizeof rec->energy[f];
    cs_state_energy(state, &rec->energy[f], NULL);
    for (int c = 0; c < rec->cable_count; c++) {
        size_t k = (size_t)f * (size_t)rec->cable_count + (size_t)c;
        rec->cables[k].size = sizeof rec->cables[k];
        cs_state_cable(model, state, c, &rec->cables[k], NULL);
        if (rec->max_nodes)
            rec->path_count[k] =
                cs_state_cable_path(model, state, c, rec->path_xyz + k * (size_t)rec->max_nodes * 3,
                                    rec->path_tension + k * (size_t)rec->max_nodes, rec->max_nodes);
    }
    for (int p = 0; p < rec->post_count; p++) {
        size_t k = (size_t)f * (size_t)rec->post_count + (size_t)p;
        if (rec->lean) {
            cs_post_view v = {.size = sizeof v};
            cs_state_post(model, state, p, &v, NULL);
            rec->post_states[k] = (cs_post_state){v.status, v.tilt};
        } else {
            rec->posts[k].size = sizeof rec->posts[k];
            cs_state_post(model, state, p, &rec->posts[k], NULL);
        }
    }
    for (int a = 0; a < 2; a++) {
        cs_anchor_view *v = &rec->anchors[(size_t)f * 2 + (size_t)a];
        v->size = sizeof *v;
        cs_state_anchor(model, state, a, v, NULL);
    }
    rec->frame_count++;
}

void cs_record_release(cs_record *rec) {
    free(rec->vehicle);
    free(rec->energy);
    free(rec->cables);
    free(rec->posts);
    free(rec->post_states);
    free(rec->anchors);
    free(rec->path_count);
    free(rec->path_xyz);
    free(rec->path_tension);
    memset(rec, 0, sizeof *rec);
}

cs_record *cs_record_create(const cs_model *model, cs_error *err) {
    cs_record *rec = malloc(sizeof *rec);
    if (!rec || cs_record_init(rec, model) != 0) {
        free(rec);
        if (err) {
            err->status = CS_ERR_MEMORY;
            snprintf(err->message, sizeof err->message, "out of memory for the record");
        }
        return NULL;
    }
    return rec;
}

void cs_record_free(cs_record *rec) {
    if (!rec) return;
    cs_record_release(rec);
    free(rec);
}

int cs_record_ok(const cs_record *rec) {
    return !rec->failed;
}

int cs_record_frame_count(const cs_record *rec) {
    return rec->frame_count;
}

static int in_frame(const cs_record *rec, int frame) {
    return frame >= 0 && frame < rec->frame_count;
}

const cs_vehicle_view *cs_record_vehicle(const cs_record *rec, int frame) {
    return in_frame(rec, frame) ? &rec->vehicle[frame] : NULL;
}

const cs_energy *cs_record_energy(const cs_record *rec, int frame) {
    return in_frame(rec, frame) ? &rec->energy[frame] : NULL;
}

const cs_cable_view *cs_record_cable(const cs_record *rec, int frame, int cable) {
    if (!in_frame(rec, frame) || cable < 0 || cable >= rec->cable_count) return NULL;
    return &rec->cables[(size_t)frame * (size_t)rec->cable_count + (size_t)cable];
}

const cs_post_view *cs_record_post(const cs_record *rec, int frame, int post) {
    if (!in_frame(rec, frame) || post < 0 || post >= rec->post_count || !rec->posts) return NULL;
    return &rec->posts[(size_t)frame * (size_t)rec->post_count + (size_t)post];
}

const cs_anchor_view *cs_record_anchor(const cs_record *rec, int frame, int anchor) {
    if (!in_frame(rec, frame) || anchor < 0 || anchor > 1) return NULL;
    return &rec->anchors[(size_t)frame * 2 + (size_t)anchor];
}

int cs_record_cable_path(const cs_record *rec, int frame, int cable, const double **xyz,
                         const double **tension) {
    if (!in_frame(rec, frame) || cable < 0 || cable >= rec->cable_count) return -1;
    if (!rec->max_nodes) { /* recorded without paths */
        if (xyz) *xyz = NULL;
        if (tension) *tension = NULL;
        return 0;
    }
    size_t k = (size_t)frame * (size_t)rec->cable_count + (size_t)cable;
    if (xyz) *xyz = rec->path_xyz + k * (size_t)rec->max_nodes * 3;
    if (tension) *tension = rec->path_tension + k * (size_t)rec->max_nodes;
    return rec->path_count[k];
}
