// SPDX-License-Identifier: MIT
// Interactive time-series plots (uPlot): hover for values, drag to zoom into a time range, double-click
// to zoom out, click to show that moment in the 3D replay. A vertical line marks the replay's time.
import uPlot from 'uplot';
import { el, decelPeak } from './summary.js';
import { G0, MPH, FT, KIP, KIP_FT, fmt, seconds } from './units.js';
import { pathPlan } from './plan.js';

// The palette of the PNG figures (src/io/out/plot.c), so that cable k has the same colour everywhere.
export const PALETTE = ['#1f78b5', '#e6730d', '#2b992b', '#cc2629', '#8c5cbd', '#8c5749', '#d966b8', '#737373', '#b3b31a', '#17b3c7'];

function niceStep(span, count) {
  const raw = span / Math.max(1, count);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const norm = raw / mag;
  return (norm < 1.5 ? 1 : norm < 3 ? 2 : norm < 7 ? 5 : 10) * mag;
}

// A right-hand axis in other units on the same scale: ticks at round values of the other unit.
function otherAxis(label, factor, decimals) {
  return {
    scale: 'y',
    side: 1,
    label,
    grid: { show: false },
    splits: (u, _i, min, max) => {
      const lo = min * factor;
      const hi = max * factor;
      const step = niceStep(hi - lo, Math.max(2, Math.round(u.bbox.height / devicePixelRatio / 60)));
      const out = [];
      for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push(v / factor);
      return out;
    },
    values: (_u, splits) => splits.map((v) => (v * factor).toFixed(decimals)),
  };
}

// A plot's width in print, px: a plot card's inside on A4 at the page's 10-mm margins (190 mm, 718 px, less
// the card's padding and border), so that its text prints at about its size on the screen on A4 or Letter.
const PRINT_WIDTH = 690;
const timeAxis = { label: 'time (s)', values: (_u, splits) => splits.map((v) => v.toFixed(3).replace(/0+$/, '').replace(/\.$/, '')) };

// Markers drawn over a plot: {t, v, color, shape: 'circle'|'cross'|'diamond'|'triangle', label}. Returns
// where each label went across the plot, with the plotting area's edges (canvas pixels).
function drawMarkers(u, markers) {
  const ctx = u.ctx;
  const r = 6 * devicePixelRatio;
  ctx.save();
  ctx.beginPath();
  ctx.rect(u.bbox.left, u.bbox.top, u.bbox.width, u.bbox.height);
  ctx.clip();
  const placed = []; // label boxes drawn so far: a new one moves down until it overlaps none
  for (const m of markers) {
    if (!Number.isFinite(m.t) || !Number.isFinite(m.v)) continue;
    const x = u.valToPos(m.t, 'x', true);
    const y = u.valToPos(m.v, 'y', true);
    if (m.vline) {
      ctx.strokeStyle = m.color;
      ctx.lineWidth = 1.2 * devicePixelRatio;
      ctx.setLineDash([4 * devicePixelRatio, 4 * devicePixelRatio]);
      ctx.beginPath();
      ctx.moveTo(x, u.bbox.top);
      ctx.lineTo(x, u.bbox.top + u.bbox.height);
      ctx.stroke();
      ctx.setLineDash([]);
    }
    ctx.strokeStyle = m.color;
    ctx.fillStyle = m.color;
    ctx.lineWidth = 2.5 * devicePixelRatio;
    ctx.beginPath();
    if (m.shape === 'cross') {
      ctx.moveTo(x - r, y - r);
      ctx.lineTo(x + r, y + r);
      ctx.moveTo(x + r, y - r);
      ctx.lineTo(x - r, y + r);
      ctx.stroke();
    } else if (m.shape === 'diamond') {
      ctx.moveTo(x, y - r);
      ctx.lineTo(x + r, y);
      ctx.lineTo(x, y + r);
      ctx.lineTo(x - r, y);
      ctx.closePath();
      ctx.fill();
    } else if (m.shape === 'triangle') {
      ctx.moveTo(x, y - r);
      ctx.lineTo(x + r, y + r * 0.8);
      ctx.lineTo(x - r, y + r * 0.8);
      ctx.closePath();
      ctx.fill();
    } else {
      ctx.arc(x, y, r * 0.8, 0, 2 * Math.PI);
      ctx.fill();
    }
    if (m.label) {
      ctx.font = `${12 * devicePixelRatio}px system-ui, sans-serif`;
      ctx.fillStyle = '#222';
      const pad = 4 * devicePixelRatio;
      // a note wider than the plotting area is broken into lines at its spaces
      const lines = wrapText(ctx, m.label, u.bbox.width - 2 * pad);
      const w = Math.max(...lines.map((l) => ctx.measureText(l).width));
      const h = 15 * devicePixelRatio;
      const tall = h * lines.length;
      const right = x + 10 * devicePixelRatio + w < u.bbox.left + u.bbox.width;
      const below = y - 8 * devicePixelRatio - tall < u.bbox.top;
      // beside the marker, on the side with room, then moved in where it would still cross the frame
      const side = right ? x + 10 * devicePixelRatio : x - 10 * devicePixelRatio - w;
      const x0 = Math.max(u.bbox.left + pad, Math.min(side, u.bbox.left + u.bbox.width - pad - w));
      // ly: the last line's baseline; a box spans (ly - tall, ly]
      let ly = below ? y + 20 * devicePixelRatio + tall - h : y - 8 * devicePixelRatio;
      const overlaps = () => placed.some((b) => x0 < b[0] + b[2] && b[0] < x0 + w && ly - tall < b[1] && b[1] - b[3] < ly);
      for (let k = 0; k < 6 && overlaps(); k++) ly += h;
      placed.push([x0, ly, w, tall]);
      ctx.textAlign = 'left';
      lines.forEach((l, i) => ctx.fillText(l, x0, ly - (lines.length - 1 - i) * h));
    }
  }
  ctx.restore();
  return placed.map(([x0, , w]) => ({ x0, x1: x0 + w, left: u.bbox.left, right: u.bbox.left + u.bbox.width }));
}

// Words of text in lines no wider than width (a word wider than that stands on its own line).
function wrapText(ctx, text, width) {
  const lines = [];
  let line = '';
  for (const word of text.split(' ')) {
    const next = line ? `${line} ${word}` : word;
    if (line && ctx.measureText(next).width > width) {
      lines.push(line);
      line = word;
    } else {
      line = next;
    }
  }
  if (line) lines.push(line);
  return lines;
}

// Value at time t on a series (linear between points).
function valueAt(t, xs, ys) {
  if (!xs.length) return NaN;
  let i = 0;
  while (i + 1 < xs.length && xs[i + 1] < t) i++;
  if (i + 1 >= xs.length) return ys[xs.length - 1];
  const a = ys[i];
  const b = ys[i + 1];
  if (a === null || b === null) return a ?? b ?? NaN;
  const u = xs[i + 1] > xs[i] ? (t - xs[i]) / (xs[i + 1] - xs[i]) : 0;
  return a + Math.max(0, Math.min(1, u)) * (b - a);
}

// The speed plot's words at a run's end event (its time, type and exit speed), as the PNG figure's
// (src/io/out/figures.c): a redirected run ends a vehicle's length after it left the ropes.
function speedLabel(e) {
  const speed = `${fmt(e[4], 1)} m/s (${fmt(e[4] / MPH, 1)} mph)`;
  if (e[1] === 'stopped') return `stopped at t = ${seconds(e[0])}`;
  if (e[1] === 'redirected') return `redirected: the run ends at t = ${seconds(e[0])}, a vehicle's length after it left the ropes at ${speed}`;
  return `broke through at t = ${seconds(e[0])}, leaving at ${speed}, its whole speed`;
}

const line = (label, stroke, width = 2, extra = {}) => ({ label, stroke, width, points: { show: false }, ...extra });

// Every plot: {key, title, caption, data: [t, ...series], series, axes, markers, bands, yRange}.
function specs(data) {
  const S = data.series;
  const t = S.t;
  const ev = data.events;
  const out = [];
  const tension = (c) => S.tension[c].map((v) => v / 1e3);

  // 1. deceleration
  {
    const peak = decelPeak(data.summary);
    out.push({
      key: 'deceleration',
      title: 'Deceleration of the vehicle',
      caption:
        'Deceleration of the centre of gravity along the initial travel direction, in g (9.81 m/s²). The raw value jumps as cables and posts take and lose load; crash-test standards rate the 50-ms moving average (dark), defined once 50 ms have passed. The red dot marks its largest value.' +
        (S.stride > 1 ? ` Every ${S.stride}th recorded frame is shown.` : ''),
      data: [t, S.decel, S.decel50],
      series: [line('raw', '#8cb3e6', 1.2), line('50-ms average', '#0d3f99', 3)],
      axes: [timeAxis, { label: 'deceleration (g)' }, otherAxis('deceleration (m/s²)', G0, 0)],
      markers: peak.g > 0 ? [{ t: peak.t, v: peak.g, color: '#d91a1a', shape: 'circle', label: peak.label }] : [],
    });
  }
  // 2. speed
  out.push({
    key: 'speed',
    title: 'Speed of the vehicle',
    caption: 'Speed of the centre of gravity along the initial travel direction. The slope is the deceleration; a marker shows where the vehicle stopped, broke through or was redirected, with the whole of its speed as it left.',
    data: [t, S.speed],
    series: [line('forward speed (m/s)', PALETTE[0], 3)],
    axes: [timeAxis, { label: 'speed (m/s)' }, otherAxis('speed (mph)', 1 / MPH, 0)],
    yFromZero: true,
    markers: ev
      .filter((e) => e[1] === 'stopped' || e[1] === 'breakthrough' || e[1] === 'redirected')
      .map((e) => ({ t: e[0], v: valueAt(e[0], t, S.speed), color: '#d91a1a', shape: 'diamond', label: speedLabel(e) })),
  });
  // 3. penetration
  out.push({
    key: 'penetration',
    title: 'Penetration past the cable line',
    caption:
      'How far the vehicle got past the attack face of the barrier (y = 0, the cable line before impact). Light blue: the front face now; red: the dynamic penetration (the largest so far, the rated value); green dashed: the furthest point of a cable that holds, intact or passed over or under by the vehicle (the barrier’s deflection), which ends when none holds.',
    data: [t, S.face, S.penetration, S.deflection],
    series: [line('front face now (m)', '#99c7f2', 7), line('dynamic penetration (m)', '#d91a1a', 2.5), line('cable deflection (m)', '#0d800d', 3, { dash: [8, 5] })],
    axes: [timeAxis, { label: 'past the attack face (m)' }, otherAxis('past the attack face (ft)', 1 / FT, 0)],
    markers: [],
  });
  // roll, pitch and yaw (yaw from the initial heading)
  {
    const d = (v) => (v * 180) / Math.PI;
    const yaw0 = S.yaw.length ? S.yaw[0] : 0;
    const cols = [S.roll.map(d), S.pitch.map(d), S.yaw.map((v) => d(v - yaw0))];
    const markers = cols.map((c, k) => {
      let at = 0;
      c.forEach((v, i) => {
        if (Math.abs(v) > Math.abs(c[at])) at = i;
      });
      return { t: t[at], v: c[at], color: PALETTE[k], shape: 'circle', label: `${['roll', 'pitch', 'yaw'][k]} ${fmt(c[at], 1)}°` };
    });
    out.push({
      key: 'angles',
      title: 'Roll, pitch and yaw of the vehicle',
      caption:
        'The vehicle’s attitude: roll about its own x (right side down positive), pitch about its y (nose down positive), and yaw from its heading at the start. MASH asks roll and pitch to stay under 75°; the dots mark each one’s largest value.',
      data: [t, ...cols],
      series: [line('roll (deg)', PALETTE[0], 2.5), line('pitch (deg)', PALETTE[1], 2.5), line('yaw from the initial heading (deg)', PALETTE[2], 2.5)],
      axes: [timeAxis, { label: 'angle (deg)' }],
      markers,
    });
  }
  // 4. cable tensions
  {
    const series = [];
    const cols = [];
    data.barrier.cables.forEach((c, k) => {
      series.push(line(`cable ${k}, ${fmt(c[0], 2)} m high (kN)`, PALETTE[k % PALETTE.length], 2.5));
      cols.push(tension(k));
    });
    const fus = [...new Set(data.barrier.cables.map((c) => c[1]))];
    fus.forEach((fu, k) => {
      series.push(line(`rope strength Fu${fus.length > 1 ? ` ${k}` : ''} (kN)`, '#1a1a1a', 1.5, { dash: [6, 4] }));
      cols.push(t.map(() => fu / 1e3));
    });
    const markers = [];
    for (const e of ev) {
      if (e[2] !== 'cable' || !S.tension[e[3]]) continue;
      if (e[1] === 'cable_break') markers.push({ t: e[0], v: e[4] / 1e3, color: '#d62728', shape: 'cross', label: `cable ${e[3]} breaks`, vline: true });
      else if (e[1] === 'override' || e[1] === 'underride')
        markers.push({ t: e[0], v: valueAt(e[0], t, tension(e[3])), color: PALETTE[e[3] % PALETTE.length], shape: e[1] === 'override' ? 'triangle' : 'diamond', label: `${e[1] === 'override' ? 'rides over' : 'runs under'} cable ${e[3]}` });
    }
    out.push({
      key: 'cables',
      title: 'Cable tensions',
      caption:
        'Tension of each cable (its most loaded span). A cable breaks when its rope reaches its breaking strain (red ×, at the dashed rope strength Fu or beyond); a triangle marks where the vehicle rode over a cable (it slipped under the bumper) and a diamond where it ran under one: from there the vehicle no longer loads it, and the cable stays on its posts and anchors.',
      data: [t, ...cols],
      series,
      axes: [timeAxis, { label: 'tension (kN)' }, otherAxis('tension (kip)', 1e3 / KIP, 0)],
      yFromZero: true,
      markers,
    });
  }
  // 5, 6. the posts nearest the impact
  {
    const near = S.near_posts;
    const failTypes = new Set(['post_rotation_limit', 'post_down', 'post_shear', 'post_pullout']);
    const yieldTypes = new Set(['post_hinge', 'footing_rotation']);
    // a curve ends where its post fails: a failed post carries nothing
    const cut = (arr, p) => {
      const fe = ev.find((e) => e[2] === 'post' && e[3] === p && failTypes.has(e[1]));
      return arr.map((v, i) => (fe && t[i] > fe[0] + 1e-12 ? null : v));
    };
    const postLabel = (p) => `post ${p} at x = ${fmt(data.barrier.posts[p][0], 2)} m`;
    const mk = (ys) => {
      const markers = [];
      near.forEach((p, k) => {
        for (const e of ev) {
          if (e[2] !== 'post' || e[3] !== p) continue;
          if (failTypes.has(e[1])) markers.push({ t: e[0], v: valueAt(e[0], t, ys[k]), color: '#1a1a1a', shape: 'cross' });
          else if (yieldTypes.has(e[1])) markers.push({ t: e[0], v: valueAt(e[0], t, ys[k]), color: PALETTE[k % PALETTE.length], shape: 'circle' });
        }
      });
      return markers;
    };
    const tilts = near.map((p, k) => cut(S.post_tilt[k].map((v) => (v * 180) / Math.PI), p));
    const limits = [...new Set((S.post_rotation_limit || []).filter((v) => v !== null))];
    out.push({
      key: 'post_tilt',
      title: `Tilt of the ${near.length} posts nearest the impact`,
      caption:
        'How far each post leans from vertical. A dot marks where a post yields (a plastic hinge at its base, or its footing turning in the soil); a × where it fails (struck and ridden over: its top down to the vehicle’s edge, or past the dashed rotation limit of a post turning in the soil; sheared; or pulled out). A failed post leaves the barrier, so its curve ends there.',
      data: [t, ...tilts, ...limits.map((l) => t.map(() => (l * 180) / Math.PI))],
      series: [...near.map((p, k) => line(`${postLabel(p)} (deg)`, PALETTE[k % PALETTE.length], k % 2 ? 2.2 : 5)), ...limits.map((l) => line(`rotation limit ${fmt((l * 180) / Math.PI, 0)}°`, '#1a1a1a', 1.5, { dash: [6, 4] }))],
      axes: [timeAxis, { label: 'tilt (deg)' }],
      yFromZero: true,
      markers: mk(tilts),
    });
    const moments = near.map((p, k) => cut(S.post_moment[k].map((v) => v / 1e3), p));
    const caps = [...new Set(S.post_capacity)];
    out.push({
      key: 'post_moment',
      title: `Base moment of the ${near.length} posts nearest the impact`,
      caption: 'The bending moment the cables (or the vehicle’s face) put on each post’s base. It cannot exceed the dashed capacity, the weaker of the steel section’s plastic moment and the footing’s soil capacity (Eq. 21); at the capacity the post yields and keeps rotating. Mirror posts of a centred impact overlap (wide and narrow line).',
      data: [t, ...moments, ...caps.map((c) => t.map(() => c / 1e3))],
      series: [...near.map((p, k) => line(`${postLabel(p)} (kN·m)`, PALETTE[k % PALETTE.length], k % 2 ? 2.2 : 5)), ...caps.map((c) => line(`capacity ${fmt(c / 1e3, 1)} kN·m`, '#1a1a1a', 1.5, { dash: [6, 4] }))],
      axes: [timeAxis, { label: 'base moment (kN·m)' }, otherAxis('base moment (kip·ft)', 1e3 / KIP_FT, 0)],
      yFromZero: true,
      markers: mk(moments),
    });
  }
  // 7. the energy ledger, stacked
  {
    const terms = [
      ['crush', 'crush of the vehicle', '#cc3333'],
      ['post_plastic', 'post plastic (hinges)', '#338c40'],
      ['post_damping', 'post swing and anchor slide damping', '#66a673'],
      ['soil', 'soil (footings turning, posts and anchors sliding)', '#8c6138'],
      ['cable_plastic', 'cable plastic', '#e6801a'],
      ['rail_plastic', 'rail plastic (yield, buckling)', '#4d804d'],
      ['friction', 'friction (tyres, rope sliding)', '#8c66bf'],
      ['released', 'released at failures', '#d980b3'],
      ['post_elastic', 'post elastic', '#8ccc80'],
      ['post_kinetic', 'post kinetic (swing)', '#b3e09e'],
      ['anchor_elastic', 'anchor elastic (soil)', '#c8a27a'],
      ['anchor_kinetic', 'anchor kinetic (slide)', '#e0c9a8'],
      ['rail_elastic', 'rail elastic', '#a6cca6'],
      ['cable_elastic', 'cable elastic', '#fac766'],
      ['vehicle_potential', 'vehicle potential', '#b3b3b3'],
      ['vehicle_kinetic', 'vehicle kinetic', '#5999e6'],
    ];
    const E = S.energy;
    const ke0 = S.initial_kinetic || 1;
    const used = terms.filter(([k]) => E[k] && E[k].some((v) => Math.abs(v) > 1e-6 * ke0));
    const raw = used.map(([k]) => E[k].map((v) => v / 1e3));
    const stacked = [];
    raw.forEach((r, i) => stacked.push(r.map((v, j) => v + (i ? stacked[i - 1][j] : 0))));
    const series = used.map(([, label, color], i) => ({
      label: `${label} (kJ)`,
      stroke: color,
      width: 1,
      fill: `${color}cc`,
      points: { show: false },
      value: (_u, _v, _si, idx) => (idx === null || idx === undefined ? '–' : fmt(raw[i][idx], 1)),
    }));
    const bands = used.map((_, i) => (i ? { series: [i + 1, i], fill: `${used[i][2]}cc` } : null)).filter(Boolean);
    // the first band fills down to zero by itself; the others fill between their neighbours
    series.forEach((s, i) => {
      if (i) delete s.fill;
    });
    const ke = t.map(() => ke0 / 1e3);
    const last = E.balance_error.length ? E.balance_error[E.balance_error.length - 1] : 0;
    out.push({
      key: 'energy',
      wide: true,
      title: 'Where the energy went',
      caption: `The vehicle’s kinetic energy at the start (dashed) is moved, step by step, into the barrier and the vehicle: each band is one term of the ledger, stacked from what is gone for good (bottom) to what still moves (top). If the physics is consistent the top of the stack stays on the dashed line; here the error at the end is ${(100 * last).toFixed(2)} % of it.`,
      data: [t, ...stacked, ke],
      series: [...series, line('initial kinetic energy (kJ)', '#1a1a1a', 2, { dash: [8, 5] })],
      bands,
      axes: [timeAxis, { label: 'energy (kJ)' }, otherAxis('energy (ft·kip)', 1e3 / KIP_FT, 0)],
      yFromZero: true,
      markers: [],
    });
  }
  return out;
}

// Build every plot into container. Returns {plots, setTime(t)}; onSeek(t) is called on a click.
export function buildPlots(container, data, onSeek) {
  const plots = [];
  const list = specs(data);
  for (const spec of list) {
    const host = el('div', { class: 'plot' });
    const card = el('figure', { class: `plot-card${spec.wide ? ' wide' : ''}`, id: `plot-${spec.key}` }, el('h3', {}, spec.title), host, el('figcaption', {}, spec.caption));
    container.append(card);
    const width = Math.max(300, host.clientWidth || container.clientWidth || 560);
    const opts = {
      width,
      height: 300,
      cursor: { sync: { key: 'cablesim' }, drag: { x: true, y: false } },
      scales: { x: { time: false }, y: spec.yFromZero ? { range: (_u, min, max) => [Math.min(0, min), max > 0 ? max * 1.05 : 1] } : {} },
      legend: { live: true },
      series: [{ label: 't (s)', value: (_u, v) => (v === null ? '–' : v.toFixed(4)) }, ...spec.series],
      axes: spec.axes,
      bands: spec.bands,
      hooks: {
        draw: [(u) => { entry.labels = drawMarkers(u, spec.markers); }],
      },
    };
    const entry = { key: spec.key, title: spec.title, labels: [] };
    const u = new uPlot(opts, spec.data, host);
    const now = el('div', { class: 'now-line' });
    u.over.append(now);
    u.over.addEventListener('click', (e) => {
      const tq = u.posToVal(e.offsetX, 'x');
      if (Number.isFinite(tq)) onSeek(tq);
    });
    const points = spec.series.map((_, i) => spec.data[i + 1].filter((v) => v !== null && Number.isFinite(v)).length);
    plots.push(Object.assign(entry, { u, now, host, points, length: spec.data[0].length }));
  }
  // the path in plan, with MASH's exit box: a drawing, not a time history
  try {
    const rc = data.evaluation.roadside_criteria;
    const box = rc ? rc.exit_box : null;
    const plan = pathPlan(data, box, 1000);
    const legend = el('ul', { class: 'plan-legend' }, ...plan.legend.map(([color, dash, text]) => el('li', {}, el('i', { style: `border-top: 3px ${dash ? 'dashed' : 'solid'} ${color}` }), text)));
    const standardNote = !rc
      ? 'The run stands for no roadside test, so no exit box is drawn.'
      : rc.standard === 'mash'
        ? 'MASH asks that no wheel cross the box’s far side (A from the barrier’s face) within B of the point where the vehicle lost contact with the barrier.'
        : 'NCHRP Report 350 has no exit box (it judges the exit angle, criterion M): MASH’s box is drawn for reference.';
    container.append(
      el(
        'figure',
        { class: 'plot-card wide', id: 'plot-path' },
        el('h3', {}, 'Path of the vehicle in plan'),
        plan.svg,
        legend,
        el('figcaption', {}, `Seen from above: x along the barrier, y toward the protected side (the traffic side is below its line), at true scale. ${standardNote} After the run the path is not simulated; the exit box's crossing is judged on the wheels' path straight on along the last velocity.`),
      ),
    );
    plots.push({ key: 'path', title: 'Path of the vehicle in plan', points: [data.series.cg_x.length], length: data.series.cg_x.length, labels: [] });
  } catch (e) {
    container.append(el('p', { class: 'nogl' }, `The path in plan could not be drawn: ${e.message}`));
    console.error(`path in plan: ${e.message}`);
  }
  // each plot at its card's width, or at width (px), drawn before this returns
  const resize = (width = null) => {
    for (const p of plots) {
      if (!p.u) continue;
      const w = width || Math.max(300, p.host.clientWidth);
      if (Math.abs(w - p.u.width) > 2) p.u.batch(() => p.u.setSize({ width: w, height: 300 }));
    }
  };
  // A plot is a canvas as wide as its card on the screen. The whole report printed (body.print-all): each is
  // drawn PRINT_WIDTH wide before the page is laid out for the paper (a print lays out no ResizeObserver's
  // width), then scaled by the print styles to the page's width, and drawn for the screen again after; in
  // between, the observer leaves them so (the plots' new heights would call it).
  let printing = false;
  new ResizeObserver(() => {
    if (!printing) resize();
  }).observe(container);
  window.addEventListener('beforeprint', () => {
    printing = document.body.classList.contains('print-all');
    if (printing) resize(PRINT_WIDTH);
  });
  window.addEventListener('afterprint', () => {
    printing = false;
    resize();
  });
  let current = 0;
  return {
    plots,
    setTime(t) {
      current = t;
      for (const p of plots) {
        if (!p.u) continue;
        const x = p.u.valToPos(t, 'x');
        const inside = Number.isFinite(x) && x >= 0 && x <= p.u.over.clientWidth;
        p.now.style.display = inside ? 'block' : 'none';
        if (inside) p.now.style.left = `${x}px`;
      }
    },
    refresh() {
      this.setTime(current);
    },
  };
}
