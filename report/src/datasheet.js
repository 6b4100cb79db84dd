// SPDX-License-Identifier: MIT
// The data sheet that opens report.html: one page laid out as the crash-test standards' reporting chapters
// ask for a test's summary (NCHRP Report 350 and MASH, chapter 6; EN 1317-2's test report): the test
// article, the vehicle, the impact and exit conditions, sequential top and side pictures at fixed times,
// the deflection and working width, the occupant risk, and each evaluation criterion of the run's standard
// with its verdict. Criteria the model cannot judge say "not judged": never a pass.
import { el, outcomeTime } from './summary.js';
import { pair, seconds, MPH, FT, KIP_FT } from './units.js';
import { frame, picture, pictureBoxes } from './plan.js';

const STANDARD_TITLE = { 'nchrp-350': 'NCHRP Report 350', mash: 'MASH', 'astm-f2656': 'ASTM F2656', 'sd-std-02.01': 'SD-STD-02.01', 'sd-std-02.01a': 'SD-STD-02.01a' };
const PICTURES = 5;
const STEPS = [0.05, 0.1, 0.2, 0.25, 0.5, 1, 2];

// The fixed times of the sequential pictures, s after the first contact: 0 and every step up to the
// run's end, the step the largest of STEPS that fits PICTURES - 1 of them.
export function pictureTimes(t0, tEnd) {
  const span = tEnd - t0;
  let step = STEPS[0];
  for (const s of STEPS) if (s * (PICTURES - 1) <= span + 1e-9) step = s;
  const out = [];
  for (let k = 0; k < PICTURES && k * step <= span + 1e-9; k++) out.push(k * step);
  return out;
}

function nearestFrame(frames, t) {
  let best = 0;
  frames.forEach((f, i) => {
    if (Math.abs(f[0] - t) < Math.abs(frames[best][0] - t)) best = i;
  });
  return frames[best];
}

// A block of the sheet: a heading and rows of [label, value].
function block(title, rows) {
  return el(
    'table',
    { class: 'sheet-block' },
    el('thead', {}, el('tr', {}, el('th', { colspan: '2' }, title))),
    el('tbody', {}, ...rows.map(([k, v]) => el('tr', {}, el('th', { scope: 'row' }, k), el('td', {}, v)))),
  );
}

// fixed decimals, however small the value (a head-on run's lateral OIV of 6e-6 m/s reads 0.0)
const f = (v, digits = 1) => (v === null || v === undefined || !Number.isFinite(v) ? '–' : v.toFixed(digits));
const kmh = (v) => `${f(v * 3.6)} km/h (${f(v / MPH)} mph)`;
const deg = (v) => `${f(v)}°`;

// The test the run is, in words, and its criteria as rows {id, criterion, verdict, detail}.
function evaluation(data) {
  const rc = data.evaluation.roadside_criteria;
  if (rc)
    return {
      test: `${STANDARD_TITLE[rc.standard] || rc.standard} test ${rc.test} as run (its ${rc.vehicle})`,
      rows: rc.criteria.map((c) => ({ id: c.id, criterion: c.criterion, verdict: c.verdict, detail: c.detail })),
    };
  const d = data.designations_as_run || [];
  if (d.length)
    return {
      test: `${d.map((x) => STANDARD_TITLE[x.standard] || x.standard).join(' and ')} as run (anti-ram: rated by penetration)`,
      rows: d.map((x) => ({
        id: STANDARD_TITLE[x.standard] || x.standard,
        criterion: 'penetration rating: the designation the run earns at its own speed',
        verdict: x.label === 'not rated' ? 'not judged' : x.label,
        detail: x.text,
      })),
    };
  return {
    test: 'no standard test: the run’s vehicle, speed and angle are none of NCHRP 350’s, MASH’s, ASTM F2656’s or SD-STD-02.01’s',
    rows: [{ id: '–', criterion: 'every criterion', verdict: 'not judged', detail: 'the run stands for no test of a standard cablesim knows' }],
  };
}

// Where a wheel track crosses the exit box's far side, as the exit box criterion says it (criteria.c): in
// the run, or on the path extrapolated from the run's end (a vehicle's length past the loss of contact).
function exitBox(box) {
  if (!box) return '– (no roadside test)';
  if (box.heading_back) return "not judged: no wheel crossed in the run, and at its end the vehicle moves back toward the barrier";
  if (!Number.isFinite(box.cross_along_m)) return 'not crossed';
  return `crossed ${f(box.cross_along_m)} m along${box.crossed_in_run ? '' : " on the path extrapolated from the run's end"} (B = ${f(box.b_m)} m)`;
}

function verdictClass(v) {
  return v === 'pass' ? 'pass' : v === 'FAIL' ? 'fail' : v === 'not judged' ? 'nj' : 'rating';
}

export function dataSheet(data) {
  const s = data.summary;
  const sc = data.scenario;
  const v = data.vehicle;
  const ev = data.evaluation;
  const o = ev.occupant_risk;
  const S = data.series;
  const posts = data.barrier.posts;
  const test = evaluation(data);

  // sequential pictures at fixed times from the first contact
  const t0 = s.first_contact_time_s === null ? 0 : s.first_contact_time_s;
  const times = pictureTimes(t0, s.t_end_s);
  const frames = times.map((dt) => nearestFrame(data.frames, t0 + dt));
  const boxes = pictureBoxes(data, frames);
  const topF = frame(...boxes.top, 200);
  const sideF = frame(...boxes.side, 200 * ((boxes.side[1] - boxes.side[0]) / (boxes.top[1] - boxes.top[0])));
  const pics = el(
    'div',
    { class: 'sheet-pics' },
    ...frames.map((fr, k) =>
      el('figure', {}, picture(data, fr, 'top', topF), picture(data, fr, 'side', sideF), el('figcaption', {}, `${times[k].toFixed(3)} s`)),
    ),
  );

  const spacing = posts.length > 1 ? (posts[posts.length - 1][0] - posts[0][0]) / (posts.length - 1) : NaN;
  const length = data.barrier.anchors[1][0] - data.barrier.anchors[0][0];
  const heights = `${data.barrier.cables.map((c) => f(c[0], 2)).join(', ')} m (${data.barrier.cables.map((c) => f(c[0] / FT, 2)).join(', ')} ft)`;
  const angle = (sc.angle * 180) / Math.PI;
  const severity = 0.5 * v.mass * (sc.speed * Math.sin(sc.angle)) ** 2;
  const yaw0 = S.yaw.length ? S.yaw[0] : 0;
  const yawPeak = S.yaw.reduce((m, y) => Math.max(m, Math.abs(y - yaw0)), 0);
  const exits = s.exit_speed_mps !== null;
  const box = ev.roadside_criteria ? ev.roadside_criteria.exit_box : null;

  const left = [
    block('Test article', [
      ['type', `cable barrier, ${data.barrier.cables.length} cables on ${posts.length} posts`],
      ['installation length', pair('length', length)],
      ['cable heights', heights],
      ['post spacing', Number.isFinite(spacing) ? `${pair('length', spacing)} (mean)` : '–'],
      ['soil, posts, ropes', 'as the model gives them (the design as run, below)'],
    ]),
    block('Test vehicle', [
      ['designation', ev.roadside_criteria ? ev.roadside_criteria.vehicle : data.designations_as_run.length ? `${data.designations_as_run[0].vehicle_class} (ASTM F2656)` : 'none of the standards’'],
      ['test inertial mass', pair('mass', v.mass)],
      ['CG height', pair('length', v.cg_height)],
      ['length, width', `${f(v.cg_to_front + v.cg_to_rear, 2)} m, ${f(v.front_width, 2)} m`],
    ]),
  ];
  const middle = [
    block('Impact conditions', [
      ['speed', kmh(sc.speed)],
      ['angle', deg(angle)],
      ['location', `x = ${pair('length', sc.impact_x)}, ${sc.impact_at_corner ? 'leading front corner' : 'centre of the front'}`],
      ['impact severity', `${f(severity / 1e3)} kJ (${f(severity / KIP_FT)} kip·ft)`],
    ]),
    block('Exit conditions', [
      ['outcome', `${s.outcome.replace(/_/g, ' ')} at ${seconds(outcomeTime(s))}`],
      ['speed', exits ? kmh(s.exit_speed_mps) : '– (did not leave)'],
      ['angle', exits && s.exit_angle_deg !== null ? deg(s.exit_angle_deg) : '–'],
      ['exit box (MASH)', exitBox(box)],
      ['after loss of contact', "simulated for the vehicle's length, then not"],
    ]),
    block('Vehicle angles (max)', [
      ['roll, pitch', ev.max_roll_deg === undefined ? '–' : `${deg(ev.max_roll_deg)}, ${deg(ev.max_pitch_deg)}`],
      ['yaw from heading', deg((yawPeak * 180) / Math.PI)],
    ]),
  ];
  const right = [
    block('Occupant risk', o
      ? [
          // at a point of the vehicle (run --occupant-at), not the CG the standards and the criteria take
          ...(o.point_m && o.point_m.some((c) => c !== 0)
            ? [['at a point', `${o.point_m.map((c) => f(c, 2)).join(', ')} m from the CG; criteria: the CG's`]]
            : []),
          ['OIV long., lat.', `${f(o.oiv_longitudinal_mps, 2)}, ${f(o.oiv_lateral_mps, 2)} m/s`],
          ['ORA long., lat.', `${f(o.ora_longitudinal_g, 2)}, ${f(o.ora_lateral_g, 2)} g`],
          ['THIV', `${f(o.thiv_kmh)} km/h`],
          ['PHD', `${f(o.phd_g, 2)} g`],
          ['ASI', f(o.asi, 2)],
          ['max 50-ms decel.', `${f(s.max_50ms_decel_g, 2)} g`],
        ]
      : [['none', ev.occupant_risk_note || '–']]),
    block('Test article deflections', [
      ['dynamic', pair('length', s.max_barrier_deflection_m)],
      ['working width', pair('length', s.working_width_m)],
      ['permanent', 'not computed'],
      ['posts failed, cables broken', `${s.posts_failed_left + s.posts_failed_right}, ${s.cables_broken}`],
    ]),
  ];
  const criteria = el(
    'table',
    { class: 'sheet-criteria' },
    el('thead', {}, el('tr', {}, el('th', {}, 'criterion'), el('th', {}, 'what it asks'), el('th', {}, 'verdict'), el('th', {}, 'the run'))),
    el(
      'tbody',
      {},
      ...test.rows.map((r) => el('tr', {}, el('th', { scope: 'row' }, r.id), el('td', {}, r.criterion), el('td', { class: `verdict ${verdictClass(r.verdict)}` }, r.verdict), el('td', {}, r.detail))),
    ),
  );
  const judged = test.rows.filter((r) => r.verdict === 'not judged').map((r) => r.id);
  return el(
    'div',
    { class: 'sheet' },
    el('h2', {}, `Data sheet: ${data.name}`),
    el('p', { class: 'sheet-test' }, `${test.test}. Simulated by cablesim ${data.version} from ${data.file} (model hash ${data.cablesim.model_hash || '–'}): a prediction, not a crash test.`),
    pics,
    el('p', { class: 'sheet-note' }, `Top (x-y, the barrier’s line dashed) and along the barrier (y-z), at fixed times after the first contact (t = ${seconds(t0)}); posts green elastic, purple yielding, black failed; cables blue, grey dashed once broken; the vehicle’s front face dark blue.`),
    el('div', { class: 'sheet-cols' }, el('div', {}, ...left), el('div', {}, ...middle), el('div', {}, ...right)),
    criteria,
    el('p', { class: 'sheet-note' }, judged.length ? `Not judged (${judged.join(', ')}): the model cannot tell; no pass is implied.` : 'Every criterion of the test was judged.'),
  );
}
