// SPDX-License-Identifier: MIT
// The run in words and in numbers (SI with US units beside), and the failure timeline as a table.
import { pair, both, fmt, seconds } from './units.js';
import { timeline, GROUP_COLORS } from './events.js';

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) if (c !== null && c !== undefined) e.append(c);
  return e;
}
export { el };

const OUTCOME = {
  stopped: { word: 'Stopped', cls: 'good' },
  breakthrough: { word: 'Broke through', cls: 'bad' },
  redirected: { word: 'Redirected', cls: 'good' },
  override: { word: 'Rode over', cls: 'bad' },
  underride: { word: 'Ran under', cls: 'bad' },
  no_contact: { word: 'Never touched', cls: 'neutral' },
  did_not_converge: { word: 'Did not converge', cls: 'warn' },
  step_limit: { word: 'Step limit reached', cls: 'warn' },
  time_limit: { word: 'Time limit reached', cls: 'neutral' },
  running: { word: 'Did not finish', cls: 'neutral' },
};

// The penetration in words: what the vehicle reached ("3.89 m (12.8 ft)"), or how far it had got when the
// run ended with it through or still going ("beyond 5.92 m (19.4 ft)").
export function penetrationText(s) {
  if (s.max_dynamic_penetration_m !== null) return pair('length', s.max_dynamic_penetration_m);
  return s.penetration_beyond_m === null || s.penetration_beyond_m === undefined ? '–' : `beyond ${pair('length', s.penetration_beyond_m)}`;
}

// The designations of the test as run, one per standard, in the command's words ("ASTM F2656 M40/P4 (the
// vehicle got through)"): not the rating `cablesim rate` finds over the standard's speeds (docs/ratings.md).
export function designationsText(data) {
  const r = data.designations_as_run || [];
  return r.length ? r.map((x) => x.text).join('; ') : 'not rated: the vehicle is not a test vehicle of ASTM F2656 or SD-STD-02.01';
}

// When the run's outcome came, as the terminal's first line gives it: the loss of contact of a vehicle
// that left the barrier (exit_time_s: redirected, or its end for one through it), the stop, else the end.
export function outcomeTime(s) {
  if (typeof s.exit_time_s === 'number') return s.exit_time_s;
  return s.outcome === 'stopped' ? s.stop_time_s : s.t_end_s;
}

// The largest 50-ms deceleration and its time, the run's (every step, as the terminal and summary.json
// give them), and the words its plot marks it with.
export function decelPeak(s) {
  return { t: s.t_max_50ms_decel_s, g: s.max_50ms_decel_g, label: `max ${fmt(s.max_50ms_decel_g, 2)} g at ${seconds(s.t_max_50ms_decel_s)}` };
}

export function story(data) {
  const s = data.summary;
  const sc = data.scenario;
  const posts = data.barrier.posts.length;
  const cables = data.barrier.cables.length;
  const angle = (sc.angle * 180) / Math.PI;
  const failed = s.posts_failed_left + s.posts_failed_right;
  const parts = [];
  if (s.first_contact_time_s === null)
    return (
      `A ${pair('mass', data.vehicle.mass)} vehicle drove at ${pair('speed', sc.speed)} toward the ${data.name} barrier ` +
      `(${cables} cable${cables === 1 ? '' : 's'} on ${posts} posts) but had not reached it when the simulation ended at t = ${seconds(s.t_end_s)}: nothing was loaded and nothing failed.`
    );
  parts.push(
    `A ${pair('mass', data.vehicle.mass)} vehicle struck the ${data.name} barrier (${cables} cable${cables === 1 ? '' : 's'} on ${posts} posts) ` +
      `${Math.abs(angle - 90) < 0.5 ? 'head-on' : `at ${fmt(angle, 1)}° to the barrier line`} at ${pair('speed', sc.speed)}, ` +
      `${sc.impact_at_corner ? 'its leading front corner' : 'centred'} at x = ${pair('length', sc.impact_x)} along the barrier.`,
  );
  if (s.outcome === 'stopped')
    parts.push(`The barrier stopped it at t = ${seconds(s.stop_time_s)}, ${pair('length', s.max_dynamic_penetration_m)} past the cable line.`);
  else if (s.outcome === 'override' || s.outcome === 'underride')
    parts.push(`It ${s.outcome === 'override' ? 'rode over' : 'ran under'} the cables and got past the barrier line at t = ${seconds(s.t_end_s)}, still moving at ${pair('speed', s.exit_speed_mps)}.`);
  else if (s.outcome === 'breakthrough')
    parts.push(`It broke through at t = ${seconds(s.t_end_s)}, still moving at ${pair('speed', s.exit_speed_mps)}; its front was ${pair('length', s.penetration_beyond_m)} past the cable line when the simulation ended, and going on.`);
  else if (s.outcome === 'redirected')
    parts.push(
      `The barrier redirected it: it left on the traffic side at t = ${seconds(s.exit_time_s)} at ${pair('speed', s.exit_speed_mps)}, ` +
        `${fmt(s.exit_angle_deg, 1)}° away from the barrier line, after deflecting the cables ${pair('length', s.max_barrier_deflection_m)} (working width ${pair('length', s.working_width_m)}).`,
    );
  else if (s.outcome === 'step_limit') parts.push(`The simulation took its scenario.max_steps steps at t = ${seconds(s.t_end_s)}, before its end time, with the vehicle still moving, ${penetrationText(s)} past the cable line.`);
  else if (s.outcome === 'did_not_converge') parts.push(`The simulation did not converge: its barrier solves used up their budget at t = ${seconds(s.t_end_s)}, with the vehicle still moving, ${penetrationText(s)} past the cable line.`);
  else parts.push(`The simulation ended at its time limit, t = ${seconds(s.t_end_s)}, with the vehicle still moving, ${penetrationText(s)} past the cable line.`);
  parts.push(
    `${failed} of ${posts} posts failed (${s.posts_failed_left} on the low-x side of the impact, ${s.posts_failed_right} on the high-x side) and ` +
      `${s.cables_broken === 0 ? 'no cable broke' : `${s.cables_broken} of ${cables} cables broke`}. ` +
      `The largest 50-ms average deceleration was ${fmt(s.max_50ms_decel_g, 2)} g at t = ${seconds(s.t_max_50ms_decel_s)}.`,
  );
  for (const [type, what] of [
    ['override', 'slipped under the front bumper: the vehicle rode over'],
    ['underride', 'slipped over the front face: the vehicle ran under'],
  ]) {
    const cs = [...new Set(data.events.filter((e) => e[1] === type).map((e) => e[3]))];
    if (cs.length === 1) parts.push(`Cable ${cs[0]} ${what} it.`);
    else if (cs.length > 1) parts.push(`Cables ${cs.slice(0, -1).join(', ')} and ${cs[cs.length - 1]} ${what} them.`);
  }
  return parts.join(' ');
}

function card(label, si, us, note, cls = '') {
  return el('div', { class: `card ${cls}` }, el('div', { class: 'label' }, label), el('div', { class: 'value' }, si), el('div', { class: 'us' }, us || '\u00a0'), el('div', { class: 'note' }, note || '\u00a0'));
}

export function cards(data) {
  const s = data.summary;
  const o = OUTCOME[s.outcome] || OUTCOME.running;
  const posts = data.barrier.posts.length;
  const cables = data.barrier.cables.length;
  const final = s.max_dynamic_penetration_m !== null;
  const [penSI, penUS] = both.length(final ? s.max_dynamic_penetration_m : s.penetration_beyond_m);
  const [exitSI, exitUS] = s.exit_speed_mps !== null ? both.speed(s.exit_speed_mps) : ['–', s.outcome === 'stopped' ? 'the vehicle stopped' : 'not through'];
  const exitNote =
    s.outcome === 'redirected'
      ? `leaving at ${fmt(s.exit_angle_deg, 1)}° to the barrier`
      : s.exit_speed_mps !== null
        ? 'speed as it got through'
        : s.outcome === 'stopped'
          ? 'it did not get through'
          : 'by the end of the run';
  const [keSI, keUS] = both.energy(s.initial_kinetic_energy_j);
  return el(
    'div',
    { class: 'cards' },
    card('Outcome', o.word, `at t = ${seconds(outcomeTime(s))}`, `run of ${seconds(s.t_end_s)} simulated`, o.cls),
    card('Max 50-ms deceleration', `${fmt(s.max_50ms_decel_g, 2)} g`, `at t = ${seconds(s.t_max_50ms_decel_s)}`, 'average over the worst 50 ms'),
    card('Penetration', final ? penSI : `beyond ${penSI}`, final ? penUS : `beyond ${penUS}`, final ? 'front face past the cable line' : s.exit_speed_mps !== null ? 'the vehicle got through' : 'still going at the end'),
    card('Exit speed', exitSI, exitUS, exitNote),
    card('Posts failed', `${s.posts_failed_left + s.posts_failed_right} of ${posts}`, `${s.posts_failed_left} left, ${s.posts_failed_right} right`, `cables broken: ${s.cables_broken} of ${cables}`),
    card('Energy balance', `${(100 * s.energy_balance_error).toFixed(2)} %`, `of ${keSI} (${keUS})`, 'ledger error, largest over the run', s.energy_balance_warning ? 'warn' : ''),
  );
}

export function summaryTable(data) {
  const s = data.summary;
  const sc = data.scenario;
  const rows = [
    ['Outcome', (OUTCOME[s.outcome] || OUTCOME.running).word, `at t = ${seconds(outcomeTime(s))}`],
    ['Model', data.name, data.file],
    ['Model hash (FNV-1a 64 of its definitions)', data.cablesim.model_hash || '–', null],
    ['Designation as run', designationsText(data), 'docs/ratings.md'],
    ['Vehicle mass', ...both.mass(data.vehicle.mass)],
    ['Impact speed', ...both.speed(sc.speed)],
    ['Impact angle (90° = head-on)', ...both.angle(sc.angle)],
    ['Impact point along the barrier', ...both.length(sc.impact_x)],
    ['Initial kinetic energy', ...both.energy(s.initial_kinetic_energy_j)],
    ['First contact', s.first_contact_time_s === null ? 'none' : seconds(s.first_contact_time_s), null],
    ['Max 50-ms deceleration', `${fmt(s.max_50ms_decel_g, 3)} g`, `at t = ${seconds(s.t_max_50ms_decel_s)}`],
    ['Max dynamic penetration (front face)', ...(s.max_dynamic_penetration_m !== null ? both.length(s.max_dynamic_penetration_m) : both.length(s.penetration_beyond_m).map((x) => `beyond ${x}`))],
    ['Max barrier deflection (cable)', ...both.length(s.max_barrier_deflection_m)],
    ['Working width (vehicle, cables or posts)', ...both.length(s.working_width_m)],
    ['Max cable tension', ...both.force(s.max_cable_tension_n)],
    ...(s.cables || []).flatMap((c) => {
      const [peakSI, peakUS] = both.force(c.peak_tension_n);
      const [workSI, workUS] = both.energy(c.work_on_vehicle_j);
      return [
        [`Cable ${c.index}: peak tension`, `${peakSI} at t = ${seconds(c.peak_tension_time_s)}`, peakUS],
        [`Cable ${c.index}: work on the vehicle`, `${workSI}, ${fmt(100 * c.energy_share, 1)} % of the initial kinetic energy taken`, workUS],
      ];
    }),
    ...(s.sudden_losses || []).map((w) => {
      const [beforeSI, beforeUS] = both.force(w.force_before_n);
      const [afterSI, afterUS] = both.force(w.force_after_n);
      return [
        'Sudden loss of the barrier\'s force on the vehicle (warning)',
        `${beforeSI} to ${afterSI} between t = ${seconds(w.t_start_s).slice(0, -2)} and ${seconds(w.t_end_s)}`,
        `${beforeUS} to ${afterUS}; no rope, fitting or attachment failed and no rope was passed over or under`,
      ];
    }),
    ['Posts failed', `${s.posts_failed_left + s.posts_failed_right} of ${data.barrier.posts.length}`, `${s.posts_failed_left} at lower x than the impact (${s.posts_failed_rotation_left} past the rotation limit, ${s.posts_failed_shear_left} sheared, ${s.posts_failed_pullout_left} pulled out); ${s.posts_failed_right} at higher x (${s.posts_failed_rotation_right} past the rotation limit, ${s.posts_failed_shear_right} sheared, ${s.posts_failed_pullout_right} pulled out)`],
    ['Cables broken', `${s.cables_broken} of ${data.barrier.cables.length}`, null],
    ['Exit speed', ...(s.exit_speed_mps === null ? ['none', null] : both.speed(s.exit_speed_mps))],
    ['Exit angle (from the barrier line)', ...(s.exit_angle_deg === null ? ['none', null] : both.angle((s.exit_angle_deg * Math.PI) / 180))],
    ['Stop time', s.stop_time_s === null ? 'did not stop' : seconds(s.stop_time_s), null],
    ['Energy balance error', `${(100 * s.energy_balance_error).toFixed(3)} %`, 'of the initial kinetic energy'],
    ['Solver warnings', `${s.solver_warnings} steps`, s.solver_warnings ? `steps whose barrier equilibrium stopped short of its tolerance (largest relative residual ${fmt(s.max_solver_residual, 2)})` : 'every step reached equilibrium'],
    ['Time step / recording interval', `${fmt(sc.dt * 1e3, 2)} ms / ${fmt(sc.output_interval * 1e3, 2)} ms`, null],
  ];
  const tbody = el('tbody');
  for (const [name, si, us] of rows) tbody.append(el('tr', {}, el('th', { scope: 'row' }, name), el('td', {}, si), el('td', { class: 'us' }, us || '')));
  return el('table', { class: 'summary' }, el('thead', {}, el('tr', {}, el('th', {}, 'Quantity'), el('th', {}, 'SI'), el('th', {}, 'US customary'))), tbody);
}

// The timeline table; seek(t) moves the replay there when a row is clicked.
export function timelineTable(data, seek) {
  const rows = timeline(data);
  // every time with the places that show it exactly (seconds()), the most any row needs, as the terminal
  // lists the events
  const places = Math.max(4, ...rows.map((r) => seconds(r.t).length - seconds(r.t).indexOf('.') - 3));
  const tbody = el('tbody');
  for (const r of rows) {
    const tr = el(
      'tr',
      { class: `ev ${r.group}`, title: 'show this moment in the 3D replay', tabindex: '0', onclick: () => seek(r.t), onkeydown: (e) => e.key === 'Enter' && seek(r.t) },
      el('td', { class: 'num' }, r.t.toFixed(places)),
      el('td', {}, el('span', { class: 'dot', style: `background:${GROUP_COLORS[r.group]}` }), r.text),
      el('td', { class: 'val' }, r.value),
    );
    tr.dataset.t = r.t;
    tbody.append(tr);
  }
  return {
    rows,
    table: el('table', { class: 'timeline' }, el('thead', {}, el('tr', {}, el('th', {}, 'time (s)'), el('th', {}, 'what happened'), el('th', {}, 'value'))), tbody),
  };
}

// "0–5, 7, 8, 10–15" for sorted post numbers.
function ranges(ns) {
  const out = [];
  for (let i = 0; i < ns.length; ) {
    let k = i;
    while (k + 1 < ns.length && ns[k + 1] === ns[k] + 1) k++;
    out.push(k - i >= 2 ? `${ns[i]}–${ns[k]}` : ns.slice(i, k + 1).join(', '));
    i = k + 1;
  }
  return out.join(', ');
}

// The barrier as the run loaded it (data.design, SI from the model's definitions): ropes, the kinds of
// post (section, footing), the posts' spacing, the soil and the anchors, SI with US customary beside.
export function designTable(data) {
  const d = data.design;
  const groups = [];
  const row = (name, [si, us], id) => ({ name, si, us, id });
  const text = (name, si, us = null) => ({ name, si, us });
  // rope c's end fittings: one row where both ends have the same kind, efficiency and slip, else one an end
  const fittings = (ends, c) => {
    const slip = (e) => (e.slip_load_n > 0 ? `; slips at ${pair('force', e.slip_load_n)}, runs out after ${pair('length', e.slip_travel_m)}` : '');
    const [start, end] = ends.map((e) => `${e.termination}, ${fmt(100 * e.termination_efficiency, 0)} % of Fu${slip(e)}`);
    const keys = ['termination', 'termination_efficiency', 'slip_load_n', 'slip_travel_m'];
    const same = keys.every((k) => ends[0][k] === ends[1][k]);
    if (same) return [{ ...text('End fitting at the anchors', start), id: `rope-${c}-fitting` }];
    return [
      { ...text('End fitting at the start anchor', start), id: `rope-${c}-fitting-start` },
      { ...text('End fitting at the end anchor', end), id: `rope-${c}-fitting-end` },
    ];
  };
  d.ropes.forEach((r, c) => {
    groups.push([
      `Cable ${c}: wire rope`,
      [
        row('Height at the posts', both.length(r.height_m)),
        r.diameter_m > 0 ? row('Rope size (nominal diameter)', both.diameter(r.diameter_m), `rope-${c}-diameter`) : text('Rope size (nominal diameter)', 'not given'),
        row('Metallic area', both.area(r.area_m2)),
        row('Breaking strength Fu', both.force(r.strength_n)),
        row('Pretension', both.force(r.pretension_n), `rope-${c}-pretension`),
        ...fittings(r.ends, c),
      ],
    ]);
  });
  d.post_kinds.forEach((k, i) => {
    const f = k.footing;
    groups.push([
      `Post section ${d.post_kinds.length > 1 ? `${i} ` : ''}(post${k.posts.length === 1 ? '' : 's'} ${ranges(k.posts)}: ${k.posts.length})`,
      [
        row('Plastic section modulus Zx', both.sectionModulus(k.plastic_modulus_m3)),
        row('Moment of inertia Ix', both.inertia(k.inertia_m4)),
        row('Yield stress Fy', both.stress(k.yield_stress_pa), `post-kind-${i}-fy`),
        ...(k.fill_strength_pa !== undefined ? [row("Concrete fill f'c", both.stress(k.fill_strength_pa), `post-kind-${i}-fill`)] : []),
        row(k.fill_strength_pa !== undefined ? 'Plastic moment, steel and fill' : 'Plastic moment Zx Fy', both.moment(k.plastic_moment_nm), `post-kind-${i}-mp`),
        row('Elastic modulus E', both.stress(k.modulus_pa)),
        row('Mass per length', both.massPerLength(k.mass_per_length_kg_m)),
        row('Height above grade', both.length(k.height_m)),
        text('Cables held', k.face ? `${k.attachment}, on the ${k.face} face` : k.attachment),
        ...(k.release_force_n !== undefined ? [row('Release force along the post', both.force(k.release_force_n))] : []),
        ...(k.lateral_release_force_n !== undefined ? [row('Release force off the face', both.force(k.lateral_release_force_n))] : []),
        text('Rotation limit', both.angle(k.rotation_limit_rad)[0]),
        row('Footing diameter (width facing the soil)', both.length(f.diameter_m)),
        row('Footing depth', both.length(f.depth_m)),
        text('Footing rotation limit in the soil', both.angle(f.rotation_limit_rad)[0]),
        f.pullout_capacity_n !== null ? row('Pullout capacity', both.force(f.pullout_capacity_n)) : text('Pullout capacity', f.pullout_capacity_n_rule),
      ],
    ]);
  });
  const x = d.post_x_m;
  const gaps = x.slice(1).map((v, i) => v - x[i]);
  const lo = Math.min(...gaps);
  const hi = Math.max(...gaps);
  const spacing = [];
  if (x.length) spacing.push(text('Posts', `${x.length}, x = ${pair('length', x[0])} to ${pair('length', x[x.length - 1])}`));
  if (gaps.length)
    spacing.push(
      hi - lo < 1e-6
        ? row('Spacing', both.length(lo), 'spacing')
        : { name: 'Spacing', si: `${both.length(lo)[0]} to ${both.length(hi)[0]}`, us: `${both.length(lo)[1]} to ${both.length(hi)[1]}`, id: 'spacing' },
    );
  groups.push(['Post spacing', spacing]);
  const s = d.soil;
  groups.push([
    'Soil (Eq. 21)',
    [
      row('Soil pressure S1', both.pressure(s.soil_pressure_pa), 'soil-pressure'),
      row('Cap on S1', both.pressure(s.soil_pressure_cap_pa)),
      text('Coefficients c_d, c_h', `${fmt(s.coeff_depth, 2)}, ${fmt(s.coeff_height, 2)}`),
      text('Dynamic factor', `${fmt(s.dynamic_factor, 2)} (the posts' footings: ${s.width_scaling === 'none' ? 'at any width' : 'scaled to their width'})`),
      text('Friction angle', both.angle(s.friction_angle_rad)[0]),
      row('Skin friction', both.pressureGradient(s.skin_friction_pa_m)),
    ],
  ]);
  d.anchors.forEach((a, k) => {
    const rigid = a.diameter_m === 0;
    groups.push([
      `${k ? 'End' : 'Start'} anchor`,
      [
        row('Position x', both.length(a.x_m)),
        row('Cables tied at height', both.length(a.z_m)),
        ...(rigid
          ? [text('Footing', 'rigid (never moves)')]
          : [
              row('Footing diameter', both.length(a.diameter_m)),
              row('Footing depth', both.length(a.depth_m)),
              row('Plan size across the pull', both.length(a.length_m)),
              text('Soil dynamic factor', a.width_scaling === 'none' ? "the bogie post's, at any width" : 'scaled to its width'),
              a.mass_kg !== null ? row('Mass', both.mass(a.mass_kg)) : text('Mass', 'its concrete'),
              a.pullout_capacity_n !== null ? row('Pullout capacity', both.force(a.pullout_capacity_n)) : text('Pullout capacity', a.pullout_capacity_n_rule),
            ]),
      ],
    ]);
  });
  const table = el('table', { class: 'design', id: 'design-table' }, el('thead', {}, el('tr', {}, el('th', {}, 'Design value'), el('th', {}, 'SI'), el('th', {}, 'US customary'))));
  for (const [title, rows] of groups) {
    const tbody = el('tbody', {}, el('tr', { class: 'group' }, el('th', { colspan: '3', scope: 'rowgroup' }, title)));
    for (const r of rows) {
      const tr = el('tr', {}, el('th', { scope: 'row' }, r.name), el('td', {}, r.si), el('td', { class: 'us' }, r.us || ''));
      if (r.id) tr.dataset.design = r.id;
      tbody.append(tr);
    }
    table.append(tbody);
  }
  return table;
}
