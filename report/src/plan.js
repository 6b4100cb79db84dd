// SPDX-License-Identifier: MIT
// Drawings of the run from its recorded frames, as SVG: the vehicle (its schematic box between bumper and
// hood heights, placed by its CG, roll, pitch and yaw), the barrier (posts from base to top, cables along
// their recorded paths) in plan (x-y) and seen along the barrier (y-z), and the vehicle's path in plan
// with MASH's exit box. World axes: x along the barrier, y toward the protected side, z up.
import { POST_COLORS, postState } from './replay.js';

const NS = 'http://www.w3.org/2000/svg';

export function svg(tag, attrs = {}, ...children) {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  for (const c of children) if (c) e.append(c);
  return e;
}

// A body point (x forward, y left, z up, from the CG) in the world, as figures.c places it:
// R = Rz(yaw) Ry(pitch) Rx(roll).
export function toWorld(pose, b) {
  const [px, py, pz, roll, pitch, yaw] = pose;
  const [cr, sr, cp, sp, cy, sy] = [Math.cos(roll), Math.sin(roll), Math.cos(pitch), Math.sin(pitch), Math.cos(yaw), Math.sin(yaw)];
  const [bx, by, bz] = b;
  return [
    px + cy * cp * bx + (cy * sp * sr - sy * cr) * by + (cy * sp * cr + sy * sr) * bz,
    py + sy * cp * bx + (sy * sp * sr + cy * cr) * by + (sy * sp * cr - cy * sr) * bz,
    pz - sp * bx + cp * sr * by + cp * cr * bz,
  ];
}

// The 8 corners of the vehicle's box in the world: front face (less its crush) to rear, its width, from
// the face's bottom to its top.
function corners(vehicle, pose) {
  const xf = vehicle.cg_to_front - pose[6];
  const xr = -vehicle.cg_to_rear;
  const hw = vehicle.front_width / 2;
  const zb = vehicle.face_bottom - vehicle.cg_height;
  const zt = vehicle.face_top - vehicle.cg_height;
  const out = [];
  for (const x of [xf, xr]) for (const y of [hw, -hw]) for (const z of [zb, zt]) out.push(toWorld(pose, [x, y, z]));
  return out;
}

// Convex hull of 2-D points (monotone chain), counter-clockwise.
function hull(pts) {
  const p = [...pts].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  const upper = [];
  for (const q of p.reverse()) {
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
    upper.push(q);
  }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

// The vehicle's outline seen from above ('top': x-y) or along the barrier ('side': y-z).
export function outline(vehicle, pose, view) {
  const c = corners(vehicle, pose);
  return hull(c.map((p) => (view === 'top' ? [p[0], p[1]] : [p[1], p[2]])));
}

// The front face (front left to front right at mid-height) in the view.
function frontFace(vehicle, pose, view) {
  const xf = vehicle.cg_to_front - pose[6];
  const zm = (vehicle.face_bottom + vehicle.face_top) / 2 - vehicle.cg_height;
  return [1, -1].map((s) => {
    const p = toWorld(pose, [xf, (s * vehicle.front_width) / 2, zm]);
    return view === 'top' ? [p[0], p[1]] : [p[1], p[2]];
  });
}

const RANK = { elastic: 0, yielding: 1, failed: 2 };

// A drawing's frame: world box [u0, u1] x [v0, v1] mapped to an SVG of width w (px, v up), aspect 1:1.
export function frame(u0, u1, v0, v1, w) {
  const s = w / (u1 - u0);
  const h = (v1 - v0) * s;
  return { u0, u1, v0, v1, w, h, s, X: (u) => (u - u0) * s, Y: (v) => (v1 - v) * s };
}

const pts = (f, list) => list.map(([u, v]) => `${f.X(u).toFixed(2)},${f.Y(v).toFixed(2)}`).join(' ');

// One picture of frame fr of the run: 'top' (x-y) or 'side' (y-z), in the world box of f.
export function picture(data, fr, view, f) {
  const top = view === 'top';
  const g = svg('svg', { viewBox: `0 0 ${f.w.toFixed(2)} ${f.h.toFixed(2)}`, class: `pic ${view}`, role: 'img' });
  g.append(svg('rect', { x: 0, y: 0, width: f.w.toFixed(2), height: f.h.toFixed(2), fill: '#fff', stroke: '#999', 'stroke-width': 0.5 }));
  if (top) g.append(svg('line', { x1: 0, x2: f.w, y1: f.Y(0), y2: f.Y(0), stroke: '#888', 'stroke-width': 0.6, 'stroke-dasharray': '3 2' }));
  else g.append(svg('line', { x1: 0, x2: f.w, y1: f.Y(0), y2: f.Y(0), stroke: '#9a7350', 'stroke-width': 1 }));
  // posts: base to top, the worst state drawn last
  const posts = data.barrier.posts;
  const order = posts.map((_, p) => p).sort((a, b) => RANK[postState(fr[2][4 * a + 3])] - RANK[postState(fr[2][4 * b + 3])]);
  for (const p of order) {
    const [tx, ty, tz, st] = fr[2].slice(4 * p, 4 * p + 4);
    const base = top ? [posts[p][0], 0] : [0, 0];
    const tip = top ? [tx, ty] : [ty, tz];
    g.append(svg('polyline', { points: pts(f, [base, tip]), stroke: POST_COLORS[postState(st)], 'stroke-width': 1.6, fill: 'none' }));
  }
  // cables: holding (intact, or passed over or under by the vehicle) dark, let go dashed grey
  for (const c of fr[3]) {
    const xyz = c[2];
    const line = [];
    for (let i = 0; i + 2 < xyz.length; i += 3) line.push(top ? [xyz[i], xyz[i + 1]] : [xyz[i + 1], xyz[i + 2]]);
    const intact = c[0] === 0 || c[0] === 3;
    g.append(svg('polyline', { points: pts(f, line), fill: 'none', stroke: intact ? '#0d3f99' : '#999', 'stroke-width': intact ? 1.1 : 0.8, 'stroke-dasharray': intact ? '' : '3 2' }));
  }
  const pose = fr[1];
  g.append(svg('polygon', { points: pts(f, outline(data.vehicle, pose, view)), fill: '#cfd4da', 'fill-opacity': 0.85, stroke: '#555', 'stroke-width': 0.8 }));
  g.append(svg('polyline', { points: pts(f, frontFace(data.vehicle, pose, view)), stroke: '#1d3f8f', 'stroke-width': 2.2, fill: 'none' }));
  return g;
}

// The world boxes of the top (x-y) and side (y-z) pictures that hold the vehicle in every frame of
// frames and the barrier's deflected cables near it.
export function pictureBoxes(data, frames) {
  let x0 = Infinity;
  let x1 = -Infinity;
  let y0 = 0;
  let y1 = 0;
  let z1 = 0;
  for (const fr of frames) {
    for (const [u, v] of outline(data.vehicle, fr[1], 'top')) (x0 = Math.min(x0, u)), (x1 = Math.max(x1, u)), (y0 = Math.min(y0, v)), (y1 = Math.max(y1, v));
    for (const [, w] of outline(data.vehicle, fr[1], 'side')) z1 = Math.max(z1, w);
  }
  for (const fr of frames)
    for (const c of fr[3])
      for (let i = 0; i + 2 < c[2].length; i += 3) if (c[2][i] >= x0 - 2 && c[2][i] <= x1 + 2) (y1 = Math.max(y1, c[2][i + 1])), (z1 = Math.max(z1, c[2][i + 2]));
  for (const p of data.barrier.posts) z1 = Math.max(z1, p[1]);
  // the top view at least 2.5 times as long as it is deep, about its middle (a head-on run's is deep)
  const grow = Math.max(0, 2.5 * (y1 - y0 + 1) - (x1 - x0 + 2)) / 2;
  return { top: [x0 - 1 - grow, x1 + 1 + grow, y0 - 0.5, y1 + 0.5], side: [y0 - 0.5, y1 + 0.5, -0.2, z1 + 0.3] };
}

// The wheels' plan positions of a frame (criteria.c's cs_vehicle_wheels): front left, front right, rear
// left, rear right.
export function wheels(vehicle, pose) {
  const [x, y, , , , yaw] = pose;
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  const rear = vehicle.wheelbase - vehicle.cg_to_front_axle;
  return [
    [vehicle.cg_to_front_axle, vehicle.track / 2],
    [vehicle.cg_to_front_axle, -vehicle.track / 2],
    [-rear, vehicle.track / 2],
    [-rear, -vehicle.track / 2],
  ].map(([bx, by]) => [x + c * bx - s * by, y + s * bx + c * by]);
}

// The vehicle's path in plan (the CG's from the series, the wheels' from the replay frames) with the
// barrier's line, its posts and MASH's exit box (box: summary.json's exit_box, or null), width w px.
// Returns {svg, legend: [[colour, dash, text]]}.
export function pathPlan(data, box, w) {
  const S = data.series;
  const frames = data.frames;
  const tracks = [[], [], [], []];
  for (const fr of frames) wheels(data.vehicle, fr[1]).forEach((p, k) => tracks[k].push(p));
  const cg = S.cg_x.map((x, i) => [x, S.cg_y[i]]);
  const all = [...cg, ...tracks.flat()];
  let boxPts = null;
  if (box) {
    const xEnd = box.start_x_m + box.direction * box.b_m;
    boxPts = [[box.start_x_m, 0], [xEnd, 0], [xEnd, -box.a_m], [box.start_x_m, -box.a_m]];
    all.push(...boxPts);
  }
  const u0 = Math.min(...all.map((p) => p[0])) - 1;
  const u1 = Math.max(...all.map((p) => p[0])) + 1;
  const v0 = Math.min(0, ...all.map((p) => p[1])) - 1;
  const v1 = Math.max(0, ...all.map((p) => p[1])) + 1;
  const f = frame(u0, u1, v0, v1, w);
  const g = svg('svg', { viewBox: `0 0 ${f.w.toFixed(2)} ${f.h.toFixed(2)}`, class: 'pic path', role: 'img' });
  g.append(svg('rect', { x: 0, y: 0, width: f.w.toFixed(2), height: f.h.toFixed(2), fill: '#fff', stroke: '#999', 'stroke-width': 0.5 }));
  const legend = [];
  if (boxPts) {
    g.append(svg('polygon', { points: pts(f, boxPts), fill: '#e0f2e0', stroke: '#1a801f', 'stroke-width': 1.2, 'stroke-dasharray': '5 3' }));
    g.append(svg('line', { x1: 0, x2: f.w, y1: f.Y(-box.a_m), y2: f.Y(-box.a_m), stroke: '#d91a1a', 'stroke-width': 1, 'stroke-dasharray': '1 3' }));
    legend.push(['#1a801f', '5 3', `MASH's exit box: A = ${box.a_m.toFixed(2)} m across, B = ${box.b_m.toFixed(1)} m along`]);
  }
  const [a0, a1] = [data.barrier.anchors[0][0], data.barrier.anchors[1][0]];
  g.append(svg('line', { x1: f.X(Math.max(u0, a0)), x2: f.X(Math.min(u1, a1)), y1: f.Y(0), y2: f.Y(0), stroke: '#1a1a1a', 'stroke-width': 2 }));
  for (const p of data.barrier.posts) if (p[0] >= u0 && p[0] <= u1) g.append(svg('rect', { x: f.X(p[0]) - 2, y: f.Y(0) - 2, width: 4, height: 4, fill: '#888' }));
  legend.push(['#1a1a1a', '', "the barrier's line before impact, its posts"]);
  for (const fr of [frames[0], frames[frames.length - 1]]) if (fr) g.append(svg('polygon', { points: pts(f, outline(data.vehicle, fr[1], 'top')), fill: '#d9d9d9', stroke: '#777', 'stroke-width': 0.8 }));
  for (const tr of tracks) g.append(svg('polyline', { points: pts(f, tr), fill: 'none', stroke: '#737373', 'stroke-width': 0.8 }));
  g.append(svg('polyline', { points: pts(f, cg), fill: 'none', stroke: '#1f78b5', 'stroke-width': 2.2 }));
  legend.push(['#737373', '', 'wheel tracks'], ['#1f78b5', '', 'path of the CG (the vehicle drawn at the start and the end)']);
  if (box && Number.isFinite(box.cross_along_m)) {
    const x = f.X(box.start_x_m + box.direction * box.cross_along_m);
    const y = f.Y(-box.a_m);
    g.append(svg('path', { d: `M${x - 4},${y - 4}L${x + 4},${y + 4}M${x - 4},${y + 4}L${x + 4},${y - 4}`, stroke: '#d91a1a', 'stroke-width': 2 }));
    legend.push(['#d91a1a', '', `a wheel crosses the box's far side ${box.cross_along_m.toFixed(1)} m along${box.crossed_in_run ? '' : ' (on the path straight on from the run’s end)'}`]);
  }
  return { svg: g, legend, frame: f };
}
