/* End anchors: every cable is tied to the start anchor at one end and the end anchor at the other.
 * An anchor pulls out when the sum of the tensions of the spans tied to it reaches its capacity;
 * the cables it held are then released (they carry nothing more). */
#include "internal.h"

int cs_anchor_check(const cs_model *model, cs_state *s) {
    int failed = 0;
    for (int k = 0; k < 2; k++) {
        if (s->anchor_failed[k]) continue;
        double pull = 0.0;
        for (int c = 0; c < model->cable_count; c++) {
            const cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT) continue;
            pull += cs->tension[k == 0 ? 0 : cs->node_count - 2];
        }
        if (pull >= model->anchors[k].pullout_capacity) {
            s->anchor_failed[k] = 1;
            cs_event_add(model, s, CS_EVENT_ANCHOR_PULLOUT, CS_ELEMENT_ANCHOR, k, pull);
            failed = 1;
        }
    }
    return failed;
}
