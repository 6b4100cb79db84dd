/* SPDX-License-Identifier: MIT */
/* The fallback of the barrier solve: where Newton (system.c) stalls far from equilibrium, Gauss-Seidel
 * over the elements' local problems, each solved with its neighbours held: a post's tilt (its cables
 * sliding through it) and, sliding out of its footing, its pull, a support's material coordinate, a contact's
 * height on the face, and the crush (the paper's crush correction, by regula falsi). It converges where
 * Newton's linearisation misleads it (a massless post on its plastic plateau under the ropes' pull), slowly;
 * Newton goes on from where it leaves off (barrier.c). With may_fall, a post with no equilibrium near falls
 * to the next one. The rows it solves are those of post.c, post_pullout.c, support.c (with termination.c's
 * ends) and contact.c, one element at a time. */
#include "core/vec3.h"
#include "elements/rows.h"
#include "solver/solver.h"
#include "solver/work.h"

#include <math.h>

/* Solve node i's sliding condition exactly (regula falsi, Illinois variant) with its neighbours'
 * material held. Returns the relative violation found before solving (0 if it was sticking). */
double cs_relax_slide_node(const cs_model *model, const cs_cable_model *cm, cs_cable_state *cs, int i,
                           double tol) {
    int id = cs->node[i];
    if (id >= 0 && model->posts[id].clamped) return 0.0;
    const cs_rope *r = &cm->rope;
    double dl[4], dr[4];
    cs_span_chord(cs, i - 1, dl), cs_span_chord(cs, i, dr);
    double ll = dl[3], lr = dr[3], ql = cs_span_sag(r, dl), qr = cs_span_sag(r, dr);
    double m0 = cs->m[i - 1], m2 = cs->m[i + 1], m = cs->m[i];
    double tl = cs_span_tension_at(r, ll, m - m0, cs_span_plastic(cs, i - 1, m0, m), ql);
    double tr = cs_span_tension_at(r, lr, m2 - m, cs_span_plastic(cs, i, m, m2), qr);
    double ratio = exp(cs_node_capstan_exponent(model, cm, cs, i, NULL));
    /* dir = +1: left side too taut, rope slides into the left span (m grows). */
    int dir;
    double viol;
    if (tl > ratio * tr) {
        dir = 1, viol = tl - ratio * tr;
    } else if (tr > ratio * tl) {
        dir = -1, viol = tr - ratio * tl;
    } else {
        return 0.0;
    }
    double rel = viol / r->fu;
    if (rel <= tol * 1e-3) return rel;
    double eps = 1e-12 * (m2 - m0);
    double a = m, b = dir > 0 ? m2 - eps : m0 + eps;
    /* h(x) > 0 at a, < 0 at b */
#define CS_H(x)                                                                                              \
    (dir > 0 ? cs_span_tension_at(r, ll, (x)-m0, cs_span_plastic(cs, i - 1, m0, (x)), ql) -                  \
                   ratio * cs_span_tension_at(r, lr, m2 - (x), cs_span_plastic(cs, i, (x), m2), qr)          \
             : cs_span_tension_at(r, lr, m2 - (x), cs_span_plastic(cs, i, (x), m2), qr) -                    \
                   ratio * cs_span_tension_at(r, ll, (x)-m0, cs_span_plastic(cs, i - 1, m0, (x)), ql))
    double ha = viol, hb = CS_H(b), x = a;
    if (hb >= 0.0) {
        cs->m[i] = b; /* cannot be met inside the bracket: slide to its end */
        return rel;
    }
    int side = 0;
    for (int it = 0; it < 100; it++) {
        x = (a * hb - b * ha) / (hb - ha);
        double hx = CS_H(x);
        /* x == a or b: the bracket is down to adjacent doubles, where a rope span a few mm long (a node
         * next to a face corner) still jumps by more than the tolerance; nothing lies between */
        if (fabs(hx) <= 1e-4 * tol * r->fu || fabs(b - a) <= 1e-15 * (m2 - m0) || x == a || x == b) break;
        if (hx > 0.0) {
            a = x, ha = hx;
            if (side == 1) hb *= 0.5;
            side = 1;
        } else {
            b = x, hb = hx;
            if (side == -1) ha *= 0.5;
            side = -1;
        }
    }
#undef CS_H
    cs->m[i] = x;
    return rel;
}

/* The end node's m at which its span holds F_s: from the span's law without plastic set
 * (cs_span_material_at), then secants on T(m) - F_s, T falling as rope comes out, to 1e-9 Fu (the span
 * keeps its plastic set on the rope it had, and the rope that came out brings none). */
static double m_at_slip_load(const cs_cable_model *cm, cs_cable_state *cs, int end, int i, int span) {
    double fs = cm->slip_load[end], held = cs_span_material_at(cm, cs, span, fs);
    double a = cs->m[i], fa = cs_span_tension(cm, cs, span) - fs; /* at the commit: above F_s */
    double b = end ? cs->m[i - 1] + held : cs->m[i + 1] - held;
    for (int it = 0; it < 30; it++) {
        cs->m[i] = b;
        double fb = cs_span_tension(cm, cs, span) - fs;
        if (fabs(fb) <= 1e-9 * cm->rope.fu || fb == fa) break;
        double next = b - fb * (b - a) / (fb - fa);
        a = b, fa = fb, b = next;
    }
    return cs->m[i];
}

/* The local problem at each end of cable c whose rope can slip through its fitting (termination.c): the end
 * node sticks where it was committed unless its span would then pass the slip load, else it takes the rope
 * that holds the span at it. */
double cs_relax_ends(const cs_model *model, int c, cs_state *s) {
    const cs_cable_model *cm = &model->cables[c];
    cs_cable_state *cs = &s->cables[c];
    double worst = 0.0;
    for (int end = 0; end < 2; end++) {
        if (!cs_termination_slips(cm, cs, end)) continue;
        int i = end ? cs->node_count - 1 : 0, span = end ? i - 1 : 0;
        double before = cs->tension[span];
        cs->m[i] = cs->m_commit[i]; /* it sticks where it was committed unless that passes F_s */
        if (cs_span_tension(cm, cs, span) > cm->slip_load[end])
            cs->m[i] = m_at_slip_load(cm, cs, end, i, span);
        cs_cable_update_span(cm, cs, span, NULL);
        worst = fmax(worst, fabs(cs->tension[span] - before) / cm->rope.fu);
    }
    return worst;
}

/* dir * F_z less the friction band (cs_contact_band) with the contact of corner k at body height z (the
 * rope in the spans held). */
static double height_excess(const cs_model *model, cs_state *s, int c, int i, int k, double z, int dir) {
    cs_cable_state *cs = &s->cables[c];
    const cs_cable_model *cm = &model->cables[c];
    cs_contact_place_one(model, s, c, i, k, z);
    cs_cable_update_span(cm, cs, i - 1, NULL);
    cs_cable_update_span(cm, cs, i, NULL);
    double fz, fn;
    cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
    return dir * fz - cs_contact_band(model, c, fn, NULL);
}

/* Local solve of a contact's height (Coulomb friction on the vertical face, measured from where it was
 * at the end of the last step): it sticks while |F_z| <= mu F_n, else slides with the pull until
 * |F_z| = mu F_n (bisection over up to 2 m). Returns the relative violation found on entry. */
static double solve_height(const cs_model *model, cs_state *s, int c, int i, int k, double tol) {
    cs_cable_state *cs = &s->cables[c];
    double z0 = cs->corner_z_commit[k], fu = model->cables[c].rope.fu;
    double up = height_excess(model, s, c, i, k, z0, 1), down = height_excess(model, s, c, i, k, z0, -1);
    int dir = up > 0.0 ? 1 : (down > 0.0 ? -1 : 0);
    double entry = 0.0;
    {
        double fz, fn;
        height_excess(model, s, c, i, k, cs->corner_z[k], 1);
        cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
        double b = cs_contact_band(model, c, fn, NULL), dz = cs->corner_z[k] - z0;
        entry =
            (fabs(fz) > b || (dz != 0.0 && fabs(fabs(fz) - b) > tol * fu)) ? fabs(fabs(fz) - b) / fu : 0.0;
    }
    if (dir == 0) {
        height_excess(model, s, c, i, k, z0, 1);
        return entry;
    }
    double a = z0, b = z0 + 2.0 * dir;
    if (height_excess(model, s, c, i, k, b, dir) > 0.0) return entry; /* pulled off the face */
    for (int it = 0; it < 60; it++) {
        double m = 0.5 * (a + b);
        if (height_excess(model, s, c, i, k, m, dir) > 0.0)
            a = m;
        else
            b = m;
    }
    height_excess(model, s, c, i, k, b, dir);
    return entry;
}

/* Place the post's cable nodes for a tilt (and its pull as it stands) and let the rope slide through the
 * post's own holes, from the material it had on entry, so that what the post feels is a function of its
 * tilt and pull alone. Sliding inside this block matters: held rope would make the post look as stiff as
 * the cable. */
static void place_on_post(const cs_model *model, cs_state *s, int p, const double *tilt,
                          const double *m_entry) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i < 0) continue;
        const cs_cable_model *cm = &model->cables[c];
        cs_post_attachment(model, p, tilt, s->posts[p].pull, cs_post_upright(&model->posts[p]),
                           cs_post_cable_z(model, s, p, c), cs->pos + 3 * i);
        cs->m[i] = m_entry[c];
        cs_relax_slide_node(model, cm, cs, i, model->scenario.solver_tolerance);
        cs_cable_update_span(cm, cs, i - 1, NULL);
        cs_cable_update_span(cm, cs, i, NULL);
    }
}

/* The post's residual at a tilt, its nodes placed there (place_on_post). */
static void post_residual(const cs_model *model, cs_state *s, int p, const double *tilt,
                          const double *m_entry, double *r) {
    place_on_post(model, s, p, tilt, m_entry);
    cs_post_residual_at(model, s, p, tilt, NULL, NULL, NULL, r);
}

/* The balance of a sliding post's pull at w (post_pullout.c), in the force unit of the solve's rows, its
 * nodes placed there at its tilt (place_on_post). */
static double pull_residual(const cs_model *model, cs_state *s, int p, double w, const double *m_entry) {
    s->posts[p].pull = w;
    place_on_post(model, s, p, s->posts[p].tilt, m_entry);
    return cs_post_pull_balance(model, s, p) / cs_rows_force_unit(model);
}

/* A post sliding out of its footing: Newton on its pull with a difference quotient and backtracking, its
 * tilt and its neighbours held. The pull's row falls with w (the shaft's stiffness, or the slide's mass
 * over the time since the last commit, m / h^2, outweighs the ropes' slope), so it has one root near.
 * Without it the fallback would leave the pull where Newton left off, out of balance by the slide's
 * inertial force m (w - w_c - h v_c) / h^2, which the commit books as the slide's motion (docs/theory.md,
 * "A post pulled out of its footing"). Returns the relative residual found on entry. */
static double relax_pull(const cs_model *model, cs_state *s, int p, const double *m_entry, double tol) {
    double w = s->posts[p].pull, g = pull_residual(model, s, p, w, m_entry), entry = fabs(g);
    for (int it = 0; it < 30 && fabs(g) > 1e-3 * tol; it++) {
        const double dw = 1e-9; /* m: a millionth of the slip that mobilises the shaft */
        double slope = (pull_residual(model, s, p, w + dw, m_entry) - g) / dw;
        if (!(slope < 0.0)) break;
        double d = -g / slope, step = fabs(d) > 0.05 ? 0.05 / fabs(d) : 1.0, t = w, gt = g;
        for (int ls = 0; ls < 12; ls++, step *= 0.5) {
            t = w + step * d;
            gt = pull_residual(model, s, p, t, m_entry);
            if (fabs(gt) < fabs(g)) break;
        }
        if (!(fabs(gt) < fabs(g))) break;
        w = t, g = gt;
    }
    pull_residual(model, s, p, w, m_entry); /* leave the nodes at the accepted pull */
    return entry;
}

static void entry_material(const cs_model *model, const cs_state *s, int p, double *m_entry) {
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        m_entry[c] = i >= 0 ? cs->m[i] : 0.0;
    }
}

/* A post whose own solve stalls far from balance has no equilibrium near its tilt, the ropes sliding
 * through it: a post on its plateau under the ropes' downward pull (P-delta) past the point where
 * tilting further adds more moment than it takes. A real post swings the way the unbalanced moment
 * turns it until the moment balances again. Follow that: steps of CS_FALL_STEP along the residual
 * (re-aimed at each step) until it turns back, then bisect the last step to where it vanishes; no
 * further than its fold limit (cs_post_fold_limit: the ground, for a post carrying ropes). The energy
 * the ropes give up on the way beyond what the post and friction take is what the step's ledger
 * books as released (step.c). */
#define CS_FALL_STEP 0.01  /* rad */
#define CS_FALL_STALL 1e-2 /* residual, of the capacity, that counts as no equilibrium near */
static double fall(const cs_model *model, cs_state *s, int p, const double *m_entry, double *al, double *r) {
    const cs_post_model *pm = &model->posts[p];
    double rn = v2_norm(r[0], r[1]), t[2], rt[2], limit = cs_post_fold_limit(pm, &s->posts[p]);
    for (int k = 0; k * CS_FALL_STEP < limit + CS_FALL_STEP && v2_norm(al[0], al[1]) < limit; k++) {
        double d[2] = {r[0] / rn, r[1] / rn};
        t[0] = al[0] + CS_FALL_STEP * d[0], t[1] = al[1] + CS_FALL_STEP * d[1];
        post_residual(model, s, p, t, m_entry, rt);
        if (rt[0] * d[0] + rt[1] * d[1] > 0.0) { /* still pushed on */
            al[0] = t[0], al[1] = t[1], r[0] = rt[0], r[1] = rt[1], rn = v2_norm(r[0], r[1]);
            continue;
        }
        double lo = 0.0, hi = CS_FALL_STEP, a0[2] = {al[0], al[1]};
        for (int b = 0; b < 40; b++) { /* the moment along d changes sign between lo and hi */
            double f = 0.5 * (lo + hi);
            t[0] = a0[0] + f * d[0], t[1] = a0[1] + f * d[1];
            post_residual(model, s, p, t, m_entry, rt);
            if (rt[0] * d[0] + rt[1] * d[1] > 0.0)
                lo = f;
            else
                hi = f;
        }
        al[0] = a0[0] + hi * d[0], al[1] = a0[1] + hi * d[1];
        break;
    }
    post_residual(model, s, p, al, m_entry, r);
    return v2_norm(r[0], r[1]) / pm->moment_scale;
}

/* Newton on the post's tilt with a finite-difference Jacobian and backtracking; where it stalls far
 * from balance and may_fall, the post falls to the next equilibrium (fall). Returns the relative
 * residual found on entry. */
double cs_relax_post(const cs_model *model, cs_state *s, int p, double tol, int may_fall) {
    if (!cs_post_solved(model, s, p)) return 0.0;
    cs_post_state *ps = &s->posts[p];
    const cs_post_model *pm = &model->posts[p];
    double scale = pm->moment_scale, r[2], m_entry[CS_MAX_CABLES_PER_POST];
    double *al = ps->tilt;
    entry_material(model, s, p, m_entry);
    post_residual(model, s, p, al, m_entry, r);
    double entry = v2_norm(r[0], r[1]) / scale;
    double rn = entry;
    for (int it = 0; it < 30 && rn > 1e-3 * tol; it++) {
        /* On the plastic plateau the radial slope of a massless post's resistance is zero, so Newton
         * cannot see that a post the cables pull less than its capacity must come back. Along the
         * radial line from the elastic boundary to here the residual changes sign once: if it is still
         * positive at the boundary the root lies between (bisect); if not, the post unloads into the
         * elastic range (restart there). A swinging post's residual has the inertial slope J / (beta h^2 (1 +
         * alpha)) there, which Newton sees. */
        double tr[2] = {al[0] - ps->plastic[0], al[1] - ps->plastic[1]}, tn = v2_norm(tr[0], tr[1]);
        double cap = cs_post_moment_cap(pm, ps);
        if (!cs_post_swings(pm, s->h) && pm->k_rot * tn > cap && (r[0] * tr[0] + r[1] * tr[1]) < 0.0) {
            double lo = 0.999 * cap / (pm->k_rot * tn), hi = 1.0, rb[2];
            double b[2] = {ps->plastic[0] + lo * tr[0], ps->plastic[1] + lo * tr[1]};
            post_residual(model, s, p, b, m_entry, rb);
            double f = lo;
            if (rb[0] * tr[0] + rb[1] * tr[1] > 0.0) {
                for (int k = 0; k < 40; k++) {
                    f = 0.5 * (lo + hi);
                    b[0] = ps->plastic[0] + f * tr[0], b[1] = ps->plastic[1] + f * tr[1];
                    post_residual(model, s, p, b, m_entry, rb);
                    if (rb[0] * tr[0] + rb[1] * tr[1] > 0.0)
                        lo = f;
                    else
                        hi = f;
                }
            }
            al[0] = ps->plastic[0] + f * tr[0], al[1] = ps->plastic[1] + f * tr[1];
            post_residual(model, s, p, al, m_entry, r);
            rn = v2_norm(r[0], r[1]) / scale;
            continue;
        }
        double h = 1e-7, jac[4], rp[2];
        for (int k = 0; k < 2; k++) {
            double a2[2] = {al[0], al[1]};
            a2[k] += h;
            post_residual(model, s, p, a2, m_entry, rp);
            jac[k] = (rp[0] - r[0]) / h; /* column k: d r / d alpha_k */
            jac[2 + k] = (rp[1] - r[1]) / h;
        }
        double det = jac[0] * jac[3] - jac[1] * jac[2];
        double d[2];
        if (fabs(det) > 1e-300) {
            d[0] = -(jac[3] * r[0] - jac[1] * r[1]) / det;
            d[1] = -(-jac[2] * r[0] + jac[0] * r[1]) / det;
        } else {
            d[0] = r[0] / pm->k_rot, d[1] = r[1] / pm->k_rot; /* J ~ -k in the elastic range */
        }
        double dn = v2_norm(d[0], d[1]);
        if (dn > 0.05) d[0] *= 0.05 / dn, d[1] *= 0.05 / dn;
        double step = 1.0, trial[2], rt[2], rtn = rn;
        for (int ls = 0; ls < 12; ls++, step *= 0.5) {
            trial[0] = al[0] + step * d[0], trial[1] = al[1] + step * d[1];
            post_residual(model, s, p, trial, m_entry, rt);
            rtn = v2_norm(rt[0], rt[1]) / scale;
            if (rtn < rn) break;
        }
        if (!(rtn < rn)) break;
        al[0] = trial[0], al[1] = trial[1], r[0] = rt[0], r[1] = rt[1], rn = rtn;
    }
    if (may_fall && rn > CS_FALL_STALL)
        fall(model, s, p, m_entry, al, r);
    else
        post_residual(model, s, p, al, m_entry, r); /* leave the nodes at the accepted tilt */
    if (ps->withdrawing) entry = fmax(entry, relax_pull(model, s, p, m_entry, tol));
    return entry;
}

/* ---- an anchor's displacement, its ropes' end spans following ---- */
static void anchor_residual(const cs_model *model, cs_state *s, int a, const double *u, double *r) {
    s->anchors[a].u[0] = u[0], s->anchors[a].u[1] = u[1];
    cs_anchor_place_nodes(model, s, a);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status == CS_CABLE_INTACT)
            cs_cable_update_span(&model->cables[c], cs, a == 0 ? 0 : cs->node_count - 2, NULL);
    }
    cs_anchor_residual(model, s, a, NULL, r);
}

/* The balance of an anchor's rise at w, its ropes' ends placed there, in the rows' force unit. */
static double lift_residual(const cs_model *model, cs_state *s, int a, double w) {
    s->anchors[a].lift = w;
    cs_anchor_place_nodes(model, s, a);
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT)
            cs_cable_update_tensions(&model->cables[c], &s->cables[c], NULL);
    return cs_anchor_lift_balance(model, s, a, NULL) / cs_rows_force_unit(model);
}

/* An anchor rising out of the soil: Newton on its rise with a difference quotient and backtracking, as a
 * post's pull (relax_pull): the row falls with w (the skin's stiffness, or m / h^2). Returns the relative
 * residual found on entry. */
static double relax_lift(const cs_model *model, cs_state *s, int a, double tol) {
    if (!cs_anchor_active(model, s, a) || !s->anchors[a].lifting) return 0.0;
    double w = s->anchors[a].lift, g = lift_residual(model, s, a, w), entry = fabs(g);
    for (int it = 0; it < 30 && fabs(g) > 1e-3 * tol; it++) {
        const double dw = 1e-9;
        double slope = (lift_residual(model, s, a, w + dw) - g) / dw;
        if (!(slope < 0.0)) break;
        double d = -g / slope, step = fabs(d) > 0.05 ? 0.05 / fabs(d) : 1.0, t = w, gt = g;
        for (int ls = 0; ls < 12; ls++, step *= 0.5) {
            t = w + step * d;
            gt = lift_residual(model, s, a, t);
            if (fabs(gt) < fabs(g)) break;
        }
        if (!(fabs(gt) < fabs(g))) break;
        w = t, g = gt;
    }
    lift_residual(model, s, a, w);
    return entry;
}

/* Newton on the anchor's two components with a difference-quotient Jacobian and backtracking. Returns
 * the relative residual found on entry (of the strongest rope's Fu). */
static double solve_anchor(const cs_model *model, cs_state *s, int a, double tol) {
    if (!cs_anchor_active(model, s, a)) return 0.0;
    double unit = 0.0, u[2] = {s->anchors[a].u[0], s->anchors[a].u[1]}, r[2];
    for (int c = 0; c < model->cable_count; c++)
        unit = fmax(unit, model->cables[c].rope.fu);
    anchor_residual(model, s, a, u, r);
    double entry = v2_norm(r[0], r[1]) / unit, rn = entry;
    for (int it = 0; it < 30 && rn > 1e-3 * tol; it++) {
        double h = 1e-7, jac[4], rp[2];
        for (int k = 0; k < 2; k++) {
            double up[2] = {u[0], u[1]};
            up[k] += h;
            anchor_residual(model, s, a, up, rp);
            jac[k] = (rp[0] - r[0]) / h, jac[2 + k] = (rp[1] - r[1]) / h;
        }
        double det = jac[0] * jac[3] - jac[1] * jac[2];
        if (!(fabs(det) > 0.0)) break;
        double d[2] = {-(jac[3] * r[0] - jac[1] * r[1]) / det, -(-jac[2] * r[0] + jac[0] * r[1]) / det};
        double dn = v2_norm(d[0], d[1]), step = dn > 0.05 ? 0.05 / dn : 1.0, t[2], rt[2], rtn = rn;
        for (int ls = 0; ls < 12; ls++, step *= 0.5) {
            t[0] = u[0] + step * d[0], t[1] = u[1] + step * d[1];
            anchor_residual(model, s, a, t, rt);
            rtn = v2_norm(rt[0], rt[1]) / unit;
            if (rtn < rn) break;
        }
        if (!(rtn < rn)) break;
        u[0] = t[0], u[1] = t[1], r[0] = rt[0], r[1] = rt[1], rn = rtn;
    }
    anchor_residual(model, s, a, u, r); /* leave the ends at the accepted displacement */
    return entry;
}

/* Normal force for a trial crush, with the corner nodes moved there. */
static double face_normal_force(const cs_model *model, cs_state *s, double crush) {
    cs_contact_place_corners(model, s, crush);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        const cs_cable_model *cm = &model->cables[c];
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i]) || !cs_corner_front(cs_node_corner(cs->node[i]))) continue;
            cs_cable_update_span(cm, cs, i - 1, NULL);
            cs_cable_update_span(cm, cs, i, NULL);
        }
    }
    double saved = s->crush;
    s->crush = crush;
    cs_post_place_captured(model, s, crush);
    double n = cs_face_normal_force(model, s, NULL);
    s->crush = saved;
    return n;
}

/* Crush correction: solve N(crush) = C(crush), N falling and C rising with crush (regula falsi),
 * stopping when the force changes by less than the crush tolerance; the sweep loop repeats it until
 * the barrier as a whole converges. Returns the relative residual found on entry. */
double cs_relax_crush(const cs_model *model, cs_state *s) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double lo = cs_crush_permanent(v, s->crush_max);
    double scale = v->crush_force[v->crush_point_count - 1];
    if (!cs_face_loaded(model, s)) {
        s->crush = lo;
        s->face_force = 0.0;
        return 0.0;
    }
    double x = s->crush < lo ? lo : s->crush;
    double n = face_normal_force(model, s, x), g = n - cs_crush_force(v, x, s->crush_max);
    double entry = fabs(g) / scale;
    double glo = face_normal_force(model, s, lo) - cs_crush_force(v, lo, s->crush_max);
    if (glo <= 0.0) { /* the cables do not even reach the permanent set */
        s->crush = lo;
        s->face_force = face_normal_force(model, s, lo);
        return glo < 0.0 ? 0.0 : entry;
    }
    double a = lo, ga = glo, b = x > lo ? x : lo + 1e-3,
           gb = face_normal_force(model, s, b) - cs_crush_force(v, b, s->crush_max);
    for (int k = 0; gb > 0.0 && k < 60; k++) {
        a = b, ga = gb;
        b = lo + 2.0 * (b - lo);
        gb = face_normal_force(model, s, b) - cs_crush_force(v, b, s->crush_max);
    }
    double tol = model->scenario.crush_tolerance, xr = a, last = n;
    int side = 0;
    for (int it = 0; it < 60; it++) {
        xr = (a * gb - b * ga) / (gb - ga);
        double nr = face_normal_force(model, s, xr), gr = nr - cs_crush_force(v, xr, s->crush_max);
        int done =
            fabs(nr - last) <= tol * fmax(fabs(nr), 1e-9 * scale) && fabs(gr) <= tol * fmax(nr, 1e-9 * scale);
        last = nr;
        if (done || fabs(gr) <= 1e-12 * scale || b - a < 1e-13) break;
        if (gr > 0.0) {
            a = xr, ga = gr;
            if (side == 1) gb *= 0.5;
            side = 1;
        } else {
            b = xr, gb = gr;
            if (side == -1) ga *= 0.5;
            side = -1;
        }
    }
    s->crush = xr;
    s->face_force = face_normal_force(model, s, xr);
    return entry;
}

/* Gauss-Seidel over the local problems, up to `sweeps` sweeps, or until CS_GS_STALL sweeps in a row
 * have not brought the residual below 0.9 of the best yet (a stalled sweep is pure cost), or the run's
 * work budget is spent (work.h). Each sweep adds CS_SWEEP_ROW_COST a local problem to the run's work: a
 * local problem is an iterative solve of its own (a post's Newton with its ropes sliding through it, a
 * support's regula falsi, a contact's bisection), which costs several of Newton's rows (measured on the
 * slowest input found: docs/robustness.md). Returns the largest relative residual found in the last sweep;
 * CS_RELAX_NOTHING if it made none (the budget spent on entry). */
#define CS_GS_STALL 50
#define CS_SWEEP_ROW_COST 20.0

double cs_relax(const cs_model *model, cs_state *s, int sweeps, int may_fall) {
    const cs_scenario_def *sc = &model->scenario;
    double worst = CS_RELAX_NOTHING, best = HUGE_VAL;
    for (int sweep = 0, last_gain = 0; sweep < sweeps && sweep - last_gain <= CS_GS_STALL; sweep++) {
        if (cs_work_spent(model, s->work)) break;
        long problems = 0;
        worst = 0.0;
        for (int k = 0; k < model->post_count; k++) {
            int p = (sweep % 2 == 0) ? k : model->post_count - 1 - k; /* alternate direction */
            worst = fmax(worst, cs_relax_post(model, s, p, sc->solver_tolerance, may_fall));
            problems += 1 + s->posts[p].withdrawing; /* its tilt, and its pull while it slides out */
        }
        for (int c = 0; c < model->cable_count; c++) {
            cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT) continue;
            const cs_cable_model *cm = &model->cables[c];
            int n = cs->node_count;
            for (int k = 1; k + 1 < n; k++) {
                int i = (sweep % 2 == 0) ? k : n - 1 - k;
                worst = fmax(worst, cs_relax_slide_node(model, cm, cs, i, sc->solver_tolerance));
            }
            worst = fmax(worst, cs_relax_ends(model, c, s)); /* ends slipping through fittings */
            problems += n;
        }
        for (int a = 0; a < 2; a++) {
            worst = fmax(worst, solve_anchor(model, s, a, sc->solver_tolerance));
            worst = fmax(worst, relax_lift(model, s, a, sc->solver_tolerance));
        }
        for (int c = 0; c < model->cable_count; c++) { /* contact heights on the face */
            cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
            for (int i = 1; i + 1 < cs->node_count; i++) {
                if (!cs_node_is_corner(cs->node[i])) continue;
                worst = fmax(worst,
                             solve_height(model, s, c, i, cs_node_corner(cs->node[i]), sc->solver_tolerance));
                problems++;
            }
        }
        worst = fmax(worst, cs_relax_crush(model, s));
        problems += 3; /* the anchors and the crush */
        s->work->count.sweeps++;
        s->work->count.work += CS_SWEEP_ROW_COST * (double)problems;
        if (worst <= sc->solver_tolerance) break;
        if (worst < 0.9 * best) best = worst, last_gain = sweep;
    }
    return worst;
}
