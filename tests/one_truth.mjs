// SPDX-License-Identifier: MIT
// One run's numbers in every output agree (tests/cli_one_truth.sh runs it): node tests/one_truth.mjs DIR
// TERMINAL where DIR is a `cablesim run --report` folder and TERMINAL the file of what that run printed.
// report.html's text is made as the page makes it, by report/src/summary.js on the page's own data, with a
// stand-in for the browser's document; its data's units are checked against the CSVs'. Prints "ok NAME" or
// "FAIL NAME: detail" per check.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

// The few parts of a DOM that summary.js builds with: elements with children, and their text.
class Node {
  constructor(tag) {
    Object.assign(this, { tag, children: [], attrs: {}, dataset: {}, className: '' });
  }
  append(...c) {
    this.children.push(...c);
  }
  setAttribute(k, v) {
    this.attrs[k] = v;
  }
  addEventListener() {}
  get textContent() {
    return this.children.map((c) => (c instanceof Node ? c.textContent : String(c))).join('');
  }
}
globalThis.document = { createElement: (tag) => new Node(tag) };
const { summaryTable, designTable, designationsText, cards, decelPeak, timelineTable } = await import('../report/src/summary.js');
const { timeline } = await import('../report/src/events.js');

const [dir, termFile] = process.argv.slice(2);
const term = readFileSync(termFile, 'utf8');
const summary = JSON.parse(readFileSync(join(dir, 'summary.json'), 'utf8'));
const html = readFileSync(join(dir, 'report.html'), 'utf8');
const page = JSON.parse(html.match(/<script type="application\/json" id="cs-data">([\s\S]*?)<\/script>/)[1]);
const csv = (f) => readFileSync(join(dir, f), 'utf8').trim().split('\n').map((l) => l.split(','));
const events = csv('events.csv');
const series = csv('timeseries.csv');

let failed = 0;
function check(name, ok, detail = '') {
  if (!ok) failed++;
  console.log(ok ? `ok ${name}` : `FAIL ${name}: ${detail}`);
}
// A table's body rows (every <tr> outside its <thead>), each as its cells' texts.
function rows(node) {
  if (!(node instanceof Node) || node.tag === 'thead') return [];
  if (node.tag === 'tr') return [node.children.map((c) => c.textContent)];
  return node.children.flatMap(rows);
}
const row = (table, name) => rows(table).find((r) => r[0] === name) || [];
const summaryRows = summaryTable(page);
const termLine = (re) => (term.match(re) || [])[1];

// (a) the designation as run: the terminal's lines, summary.json, the page's data and its text
// (a roadside run's vehicle is no anti-ram test vehicle: none anywhere, and the page says it is not rated)
const termDesignations = [...term.matchAll(/^ {2}(?:designation \(as run\)| {20}) (ASTM F2656 .*|SD-STD-02\.01 .*)$/gm)].map((m) => m[1]);
const jsonDesignations = summary.designations_as_run.map((d) => d.text);
const roadside = summary.roadside_criteria !== null;
check('designations: terminal = summary.json', JSON.stringify(termDesignations) === JSON.stringify(jsonDesignations) && jsonDesignations.length === (roadside ? 0 : 2), JSON.stringify([termDesignations, jsonDesignations]));
check('designations: summary.json = report.html data', JSON.stringify(page.designations_as_run.map((d) => d.text)) === JSON.stringify(jsonDesignations));
check('designations: report.html text', roadside ? /^not rated/.test(designationsText(page)) : row(summaryRows, 'Designation as run')[1] === jsonDesignations.join('; ') && designationsText(page) === jsonDesignations.join('; '), row(summaryRows, 'Designation as run')[1]);
check('no output calls the designation as run a rating', !/\bratings?\b/i.test(term) && !/\bratings?\b/i.test(JSON.stringify(rows(summaryRows).map((r) => r.slice(0, 2)))) && !('ratings' in summary) && !('ratings' in page));

// (b) the same quantity, the same value: the peak deceleration and its time, at the terminal's precision
const [termG, termT] = [termLine(/max 50-ms deceleration ([0-9.]+) g/), termLine(/max 50-ms deceleration [0-9.]+ g at t = ([0-9.]+) s/)];
const decelRow = row(summaryRows, 'Max 50-ms deceleration');
check('peak 50-ms deceleration: terminal = report.html', decelRow[1] === `${termG} g`, `${termG} vs ${decelRow[1]}`);
check('its time: terminal = report.html (same rounding)', decelRow[2] === `at t = ${termT} s`, `${termT} vs ${decelRow[2]}`);
check('its time: terminal = summary.json (to its 3 places)', Math.abs(Number(termT) - summary.t_max_50ms_decel_s) <= 0.0005 + 1e-12, `${termT} vs ${summary.t_max_50ms_decel_s}`);
check('its time: summary.json = report.html data (1e-9 s)', Math.abs(page.summary.t_max_50ms_decel_s - summary.t_max_50ms_decel_s) < 1e-9);
check('its plot\'s marker: the run\'s peak at the terminal\'s time, not the frames\' largest', decelPeak(page.summary).label === `max ${summary.max_50ms_decel_g.toFixed(2)} g at ${termT} s` && Math.abs(decelPeak(page.summary).t - summary.t_max_50ms_decel_s) < 1e-9, decelPeak(page.summary).label);
// the outcome's time: the terminal's first line's (the stop, or the loss of contact of a vehicle that left),
// report.html's summary table and its card
const termOutcomeT = termLine(/^[^\n]*: the vehicle .* at t = ([0-9.]+) s$/m);
if (termOutcomeT !== undefined) {
  const card = cards(page).children.find((c) => c.children[0].textContent === 'Outcome');
  check('the outcome\'s time: terminal = report.html table and card', row(summaryRows, 'Outcome')[2] === `at t = ${termOutcomeT} s` && card.children[2].textContent === `at t = ${termOutcomeT} s`, `${termOutcomeT} vs ${row(summaryRows, 'Outcome')[2]}, ${card.children[2].textContent}`);
}
// a redirected run's end event comes a vehicle's length after the loss of contact: the timeline says when
// the vehicle left, at the terminal's time
if (summary.outcome === 'redirected') {
  const end = timeline(page).find((r) => r.type === 'redirected');
  check('redirected: the timeline\'s end row names the loss of contact at the terminal\'s time', end && end.text.includes(`left the barrier on the traffic side at t = ${termOutcomeT} s`), end && end.text);
}
// the penetration: a number where the vehicle stopped, "beyond" where it got through, everywhere
const through = summary.max_dynamic_penetration_m === null;
const pen = through ? summary.penetration_beyond_m : summary.max_dynamic_penetration_m;
const termPen = Number(termLine(through ? /penetration +beyond ([0-9.]+) m/ : /max penetration +([0-9.]+) m/));
const penRow = row(summaryRows, 'Max dynamic penetration (front face)');
check('penetration: terminal = summary.json (1 mm)', Math.abs(termPen - pen) <= 0.0005 + 1e-12, `${termPen} vs ${pen}`);
check('penetration: report.html = summary.json (1 cm)', penRow[1] === `${through ? 'beyond ' : ''}${pen.toFixed(2)} m`, penRow[1]);
check('penetration: one of max_dynamic_penetration_m and penetration_beyond_m is null, in summary.json and the page', (summary.max_dynamic_penetration_m === null) !== (summary.penetration_beyond_m === null) && (page.summary.max_dynamic_penetration_m === null) === through && (page.summary.penetration_beyond_m === null) === !through);
// cables counted from 0 in every output, with the same peak tension
summary.cables.forEach((c, i) => {
  const t = termLine(new RegExp(`^  cable ${i} +peak ([0-9.]+) kN`, 'm'));
  check(`cable ${i}: the terminal's, summary.json's and the page's cable ${i} (0.1 kN)`, c.index === i && Math.abs(Number(t) - c.peak_tension_n / 1e3) <= 0.05 + 1e-9 && row(summaryRows, `Cable ${i}: peak tension`).length === 3 && series[0].includes(`cable${i}_max_tension [N]`), `${t} vs ${c.peak_tension_n}`);
  // its time as the terminal prints it, every digit of summary.json's (a step of 0.25 ms: 0.49425 s)
  const at = termLine(new RegExp(`^  cable ${i} +peak [0-9.]+ kN \\([0-9.]+ kip\\) at ([0-9.]+) s;`, 'm'));
  check(`cable ${i}: its peak's time, terminal = summary.json = report.html`, at !== undefined && Math.abs(Number(at) - c.peak_tension_time_s) < 1e-9 && row(summaryRows, `Cable ${i}: peak tension`)[1].endsWith(` at t = ${at} s`), `${at} vs ${c.peak_tension_time_s}, ${row(summaryRows, `Cable ${i}: peak tension`)[1]}`);
});
// the end fittings: summary.json's inputs give the strength the report states
const fittings = rows(designTable(page)).filter((r) => r[0].startsWith('End fitting')).map((r) => r[1]);
const inputs = summary.inputs.barrier.cables.map((c) => `${c.ends[0].termination}, ${(100 * c.ends[0].termination_efficiency).toFixed(0)} % of Fu`);
check('end fittings: summary.json inputs = report.html design', fittings.length === inputs.length && fittings.every((f, i) => f.startsWith(inputs[i])) && summary.inputs.barrier.cables.every((c) => c.termination_efficiency > 0), JSON.stringify([fittings, inputs]));
// events: events.csv, summary.json and the terminal's list in the same order and times
check('events: events.csv rows = summary.json events', events.length - 1 === summary.events.length, `${events.length - 1} vs ${summary.events.length}`);
const listed = [...term.matchAll(/^ {4} +([0-9.]+) s {2}(\S+)(?: +(\w+) (\d+))?/gm)].map((m) => [m[1], m[2], m[4]]);
const failures = events.slice(1).filter((e) => !['post_hinge', 'footing_rotation'].includes(e[1]));
check('events: the terminal lists events.csv\'s failures in order, at the same times (every digit)', listed.length === Math.min(30, failures.length) && listed.every(([t, type, el], k) => type === failures[k][1] && Math.abs(Number(t) - Number(failures[k][0])) < 1e-9 && (el === undefined || el === failures[k][3])), JSON.stringify([listed.slice(0, 3), failures.slice(0, 3)]));
// report.html's timeline: each row's time is its events' (events.csv's, every digit)
const tlRows = rows(timelineTable(page, () => {}).table);
const csvTimes = new Set(events.slice(1).map((e) => Number(e[0])));
check('timeline: report.html\'s times are events.csv\'s (every digit)', tlRows.length > 1 && tlRows.slice(1).every((r) => [...csvTimes].some((t) => Math.abs(Number(r[0]) - t) < 1e-9)), JSON.stringify(tlRows.slice(0, 3).map((r) => r[0])));
// a rope broken at a threaded post's hole: events.csv's post, summary.json's, the terminal's "at post N's
// hole" and the report's events list in the same words, for every such break (checked when the run has
// one; tests/cli_one_truth.sh runs one that must)
const atHole = events.slice(1).filter((e) => e[1] === 'cable_break' && e[8] !== undefined && e[8] !== '');
const termHoles = [...term.matchAll(/^ {4} +([0-9.]+) s {2}cable_break +cable (\d+) at post (\d+)'s hole$/gm)].map((m) => [m[2], m[3]]);
const jsonHoles = summary.events.filter((e) => e.type === 'cable_break' && e.post !== undefined).map((e) => [e.element.split(' ')[1], String(e.post)]);
const pageHoles = timeline(page).filter((r) => r.type === 'cable_break' && r.post !== undefined).flatMap((r) => r.elements.map((c) => [String(c), String(r.post), r.text]));
if (atHole.length || termHoles.length || jsonHoles.length || pageHoles.length) {
  const csvHoles = atHole.map((e) => [e[3], e[8]]);
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  check('breaks at a hole: events.csv = summary.json = the terminal (cable and post)', same(csvHoles, jsonHoles) && same(csvHoles, termHoles), JSON.stringify([csvHoles, jsonHoles, termHoles]));
  check('breaks at a hole: report.html says "at post N\'s hole" for the same cables and posts', same(pageHoles.map((h) => h.slice(0, 2)), csvHoles) && pageHoles.every(([c, p, text]) => text.startsWith(`Cable ${c} `) && text.endsWith(`breaks at post ${p}'s hole`)), JSON.stringify(pageHoles));
}
// summary.json: every number outside inputs ends its key with a unit docs/tutorial.md lists ("Elsewhere a
// number's unit ends its key (`_m`, ...)"), or is one of the pure numbers it names or counts
const listedUnits = [...(readFileSync(new URL('../docs/tutorial.md', import.meta.url), 'utf8').replace(/\s+/g, ' ').match(/a number's unit ends its key \(([^;]*)\); a key with/) || ['', ''])[1].matchAll(/`(_[a-z]+)`/g)].map((m) => m[1]);
const pure = /^(posts_failed_[a-z_]+|cables_broken|solver_warnings|cable_count|sudden_loss_count|index|cable|post|energy_share|energy_balance_error|asi|max_solver_residual|direction|value)$/;
const keyed = new Set();
(function keys(v, k) {
  if (typeof v === 'number') keyed.add(k);
  else if (Array.isArray(v)) v.forEach((e) => keys(e, k));
  else if (v !== null && typeof v === 'object') for (const [kk, e] of Object.entries(v)) if (kk !== 'inputs' && kk !== 'input_units') keys(e, kk);
})(summary, '');
const unlisted = [...keyed].filter((k) => !pure.test(k) && !listedUnits.some((u) => k.endsWith(u)));
check(`summary.json: every number's key ends in a unit docs/tutorial.md lists (${listedUnits.join(' ')}) or is a pure number`, listedUnits.length >= 8 && unlisted.length === 0, unlisted.join(' '));
// (c) every number of the page's data carries its unit: page.units, shaped as the data
// (src/io/out/report_html.h): an object's by key, a list's one unit for all its numbers or a list whose
// element i % length gives element i's; "" (no unit) only for an integer (a count, an index, a state)
const unitless = [];
const used = new Set();
let numbers = 0;
function walk(v, u, path) {
  if (typeof v === 'number') {
    numbers++;
    if (typeof u !== 'string') unitless.push(`${path} (${v}): no unit`);
    else if (u === '' && !Number.isInteger(v)) unitless.push(`${path} (${v}): "" for a number that is no count`);
    else used.add(u);
  } else if (Array.isArray(v)) {
    v.forEach((e, i) => walk(e, typeof u === 'string' ? u : Array.isArray(u) && u.length ? u[i % u.length] : undefined, `${path}[${i}]`));
  } else if (v !== null && typeof v === 'object') {
    for (const [k, e] of Object.entries(v)) walk(e, u !== null && typeof u === 'object' && !Array.isArray(u) ? u[k] : undefined, `${path}.${k}`);
  }
}
for (const [k, v] of Object.entries(page)) if (k !== 'units') walk(v, (page.units || {})[k], k);
check(`report.html data: every number has its unit (${numbers} numbers)`, numbers > 1000 && unitless.length === 0, unitless.slice(0, 5).join('; '));
// each unit as the CSVs write it (udunits2: "m/s^2", "N m", "1"), the same as the CSVs' for the same quantity
const udunits = /^(1|[A-Za-z]+(\^-?[0-9]+)?([ /][A-Za-z]+(\^-?[0-9]+)?)*)$/;
check('report.html data: each unit written as udunits2 writes it', [...used].every((u) => u === '' || udunits.test(u)), JSON.stringify([...used]));
const header = (name) => (series[0].find((h) => h.startsWith(`${name} [`)) || '').slice(name.length + 2, -1);
const U = page.units || {};
check('report.html data: the units of time, speed, tension, tilt and energy are timeseries.csv\'s', U.series && U.series.t === header('t') && U.series.speed === header('forward_speed') && U.series.tension === header('cable0_max_tension') && U.series.post_tilt === header('post0_tilt') && U.series.energy.friction === header('friction') && U.series.energy.balance_error === header('energy_balance_error') && U.series.decel50 === header('decel_50ms'), JSON.stringify(U.series));
check('report.html data: each event\'s value in events.csv\'s value_unit', events.length - 1 === page.events.length && page.events.every((e, i) => U.events[i][4] === events[i + 1][5] && U.events[i][0] === 's'), JSON.stringify((U.events || []).slice(0, 3)));
process.exit(failed ? 1 : 0);
