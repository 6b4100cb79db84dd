// SPDX-License-Identifier: MIT
// designer.html: the model's files and the engine (WebAssembly: web/designer.c) in one page. The form's
// values go to the engine as `--set PATH=VALUE` overrides of the model file, exactly as
// `cablesim run --set` takes them; each change runs the crash again and redraws the outcome, the response
// parameters, the rating, the plots and the replay. window.csDesigner exposes the page's state (the
// browser test reads it).
import uPlot from 'uplot';
import uplotCss from 'uplot/dist/uPlot.min.css';
import createCablesim from 'cablesim-wasm';
import { story, cards, summaryTable, designationsText, el } from '../src/summary.js';
import { buildPlots } from '../src/plots.js';
import { createReplay } from '../src/replay.js';
import { fmt } from '../src/units.js';

const designer = { ready: false, runs: 0, errors: [], last: null };
window.csDesigner = designer;
const $ = (id) => document.getElementById(id);

// The form: which values of the model file it shows, grouped, with the kind of part a name picks.
const FIELDS = [
  [/^barrier\.cables\[(\d+)\]\.(rope|pretension|height)$/, 'Ropes', 'rope'],
  [/^barrier\.posts\[(\d+)\]\.(section|spacing|embedment|yield_stress)$/, 'Posts', 'section'],
  [/^barrier\.posts\[(\d+)\]\.footing\.(diameter|width|length|depth|pullout_capacity)$/, 'Post footings'],
  [/^barrier\.anchors\.(start|end)\.footing\.(\w+)$/, 'Anchors'],
  [/^barrier\.soil\.(\w+)$/, 'Soil'],
  [/^vehicle$/, 'Vehicle and impact', 'vehicle'],
  [/^scenario\.(speed|angle|impact_x)$/, 'Vehicle and impact'],
];
const LABELS = { impact_x: 'impact point (x)', pullout_capacity: 'pullout capacity', yield_stress: 'yield stress', soil_pressure: 'soil pressure', soil_pressure_cap: 'soil pressure cap', coeff_depth: 'depth coefficient', coeff_height: 'height coefficient', dynamic_factor: 'dynamic factor', skin_friction: 'skin friction' };
// Each response of the sweep: its name, its value of a run's summary (null: none), and the text of a run
// without one where there is something to say. The max dynamic penetration is only a held run's, as in a
// study's outputs: a run that got through has how far it had got, a lower bound, written "beyond".
const RESPONSES = [
  ['max dynamic penetration (m)', (s) => s.max_dynamic_penetration_m, (s) => (s.penetration_beyond_m !== null ? `beyond ${fmt(s.penetration_beyond_m, 4)}` : '–')],
  ['max 50-ms deceleration (g)', (s) => s.max_50ms_decel_g],
  ['max cable tension (kN)', (s) => s.max_cable_tension_n / 1e3],
  ['barrier deflection (m)', (s) => s.max_barrier_deflection_m],
  ['working width (m)', (s) => s.working_width_m],
  ['exit speed (m/s)', (s) => s.exit_speed_mps],
  ['posts failed', (s) => s.posts_failed_left + s.posts_failed_right],
];

function fail(where, e) {
  const msg = `${where}: ${e && e.message ? e.message : e}`;
  designer.errors.push(msg);
  console.error(msg);
}

let engine = null;
let modelArg = '';
let modelFile = ''; // the model's file as `cablesim designer` was given it, as report.html names it
const fields = [];

function call(name, ...args) {
  const text = engine.ccall(name, 'string', args.map((a) => (typeof a === 'number' ? 'number' : 'string')), args);
  return JSON.parse(text);
}

function writeFiles(design) {
  for (const f of design.files) {
    const parts = f.path.split('/').filter(Boolean);
    let dir = '';
    for (const p of parts.slice(0, -1)) {
      dir += `/${p}`;
      if (p !== '..' && !engine.FS.analyzePath(dir).exists) engine.FS.mkdir(dir);
    }
    engine.FS.writeFile(f.path, f.text);
  }
  engine.FS.chdir('/model');
}

// The field's name for a person: "line posts: spacing", "cable 1: pretension". Cables and post groups are
// counted from 0, as in every output and in the --set paths (barrier.cables[1] is cable 1); a group without
// a name is "post group i", since "post i" is the i-th post along the barrier in every output.
function label(values, path, m) {
  const key = path.split('.').pop();
  const word = LABELS[key] || key;
  if (path.startsWith('barrier.cables')) return `cable ${Number(m[1])}: ${word}`;
  if (path.startsWith('barrier.posts')) {
    const name = values.get(`barrier.posts[${m[1]}].name`);
    const part = path.includes('.footing.') ? `footing ${word}` : word;
    return `${name || `post group ${Number(m[1])}`}: ${part}`; // group i, not post i
  }
  if (path.startsWith('barrier.anchors')) return `${m[1]} anchor: footing ${word}`;
  return word;
}

function buildForm(values, parts) {
  const form = $('form');
  const byPath = new Map(values.map((v) => [v.path, v.text]));
  const groups = new Map();
  for (const v of values) {
    for (const [re, group, kind] of FIELDS) {
      const m = v.path.match(re);
      if (!m) continue;
      const isPart = kind && (v.path.endsWith(`.${kind}`) || v.path === kind);
      if (!groups.has(group)) groups.set(group, el('fieldset', {}, el('legend', {}, group)));
      const id = `f-${fields.length}`;
      let input;
      if (isPart && parts[kind]) {
        input = el('select', { id });
        const names = parts[kind].includes(v.text) ? parts[kind] : [v.text, ...parts[kind]];
        for (const n of names) input.append(el('option', n === v.text ? { value: n, selected: '' } : { value: n }, n));
      } else {
        input = el('input', { id, type: 'text', value: v.text, spellcheck: 'false' });
      }
      const error = el('div', { class: 'error', id: `${id}-error` });
      const row = el('div', { class: 'field', 'data-path': v.path }, el('label', { for: id, title: v.path }, label(byPath, v.path, m)), input, error);
      groups.get(group).append(row);
      const f = { path: v.path, original: v.text, input, row, error, numeric: !isPart };
      input.addEventListener('change', () => run());
      fields.push(f);
      break;
    }
  }
  for (const name of new Set(FIELDS.map(([, group]) => group))) if (groups.has(name)) form.append(groups.get(name));
}

// The form's overrides: "PATH=VALUE" for each value changed from the file's.
function sets(extra = null) {
  const out = [];
  for (const f of fields) {
    const v = extra && extra.path === f.path ? extra.value : f.input.value.trim();
    if (v !== f.original) out.push(`${f.path}=${v}`);
  }
  return out;
}

// Each problem beside its field: "--set PATH=VALUE: what" names the field, as does a problem of the file
// at a path the form shows; the rest under the form.
function showErrors(errors) {
  for (const f of fields) {
    f.error.textContent = '';
    f.row.classList.remove('bad');
    f.row.classList.toggle('changed', f.input.value.trim() !== f.original);
  }
  const rest = [];
  for (const e of errors) {
    const m = e.match(/^--set ([^=]+)=/) || e.match(/^[^:]+:\d+:\d+: ([\w.[\]]+): /);
    const f = m && fields.find((x) => x.path === m[1]);
    if (f) {
      f.error.textContent = (f.error.textContent ? `${f.error.textContent}\n` : '') + e.replace(/^--set [^:]*: |^[^:]+:\d+:\d+: [\w.[\]]+: /, '');
      f.row.classList.add('bad');
    } else rest.push(e);
  }
  $('errors').textContent = rest.join('\n');
}

let replay = null;
function showRun(r) {
  // the page runs the model from its folder; its outputs name the file as the command's do
  const data = { ...r.report, file: modelFile };
  $('story').textContent = story(data);
  $('cards').replaceChildren(cards(data));
  $('designation').textContent = `Designation as run: ${designationsText(data)}.`;
  $('table').replaceChildren(summaryTable(data));
  const plotsHost = el('div', { class: 'plots' });
  $('plots').replaceWith(plotsHost);
  plotsHost.id = 'plots';
  const scrub = $('scrub');
  const frameT = data.frames.map((f) => f[0]);
  const onFrame = (i) => {
    scrub.value = String(i);
    $('clock').textContent = `t = ${frameT[i].toFixed(3)} s`;
    if (plots) plots.setTime(frameT[i]);
  };
  let plots = null;
  try {
    plots = buildPlots(plotsHost, data, (t) => replay && replay.showFrame(frameT.findIndex((x) => x >= t - 1e-9)));
  } catch (e) {
    fail('plots', e);
  }
  if (replay) replay.dispose();
  replay = null;
  scrub.max = String(Math.max(0, data.frames.length - 1));
  try {
    replay = createReplay($('replay'), data, onFrame);
    replay.showFrame(data.frames.length - 1);
  } catch (e) {
    $('replay').replaceChildren(el('p', { class: 'nogl' }, `The 3D replay could not start (${e && e.message ? e.message : e}): this browser has no WebGL.`));
  }
  scrub.oninput = () => replay && replay.showFrame(Number(scrub.value));
}

// Run the model with the form's values: the page updates, and designer.last holds the run.
function run() {
  const s = sets();
  const t0 = performance.now();
  let r;
  try {
    r = call('cs_web_run', modelArg, s.join('\n'), 1);
  } catch (e) {
    r = { ok: false, errors: [`the engine failed: ${e && e.message ? e.message : e}`] };
  }
  const pageMs = performance.now() - t0;
  designer.runs++;
  designer.last = { ok: r.ok, sets: s, errors: r.errors || [], summary: r.ok ? r.summary : null, ms: r.ms, pageMs };
  showErrors(r.errors || []);
  document.querySelector('main').classList.toggle('stale', !r.ok); // the results shown are an earlier run's
  if (!r.ok) {
    $('status').textContent = `Not run: ${r.errors.length} problem${r.errors.length === 1 ? '' : 's'} in the values (beside the fields); below, the last run.`;
    return designer.last;
  }
  $('status').textContent = `Run ${designer.runs}: the crash computed in ${r.ms.toFixed(1)} ms in this page${s.length ? ` with ${s.length} value${s.length === 1 ? '' : 's'} changed` : ''}; model hash ${r.summary.cablesim.model_hash}.`;
  try {
    showRun(r);
  } catch (e) {
    fail('page', e);
  }
  return designer.last;
}

// One run without redrawing (the sweep, the timing): its summary, or its problems.
function runQuiet(extra) {
  const r = call('cs_web_run', modelArg, sets(extra).join('\n'), 0);
  return r;
}

// "8 ft" -> [8, "ft"].
function splitValue(text) {
  const m = String(text).trim().match(/^([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)$/);
  return m ? [Number(m[1]), m[2]] : null;
}

function setupSweep() {
  const fieldSel = $('sweep-field');
  const numeric = fields.filter((f) => f.numeric && splitValue(f.original));
  for (const f of numeric) fieldSel.append(el('option', { value: f.path }, f.row.querySelector('label').textContent));
  for (const [name] of RESPONSES) $('sweep-response').append(el('option', { value: name }, name));
  const fill = () => {
    const f = numeric.find((x) => x.path === fieldSel.value);
    const v = f && splitValue(f.input.value);
    if (!v) return;
    $('sweep-from').value = `${+(v[0] * 0.5).toPrecision(4)} ${v[1]}`.trim();
    $('sweep-to').value = `${+(v[0] * 1.5).toPrecision(4)} ${v[1]}`.trim();
  };
  const spacing = numeric.find((f) => f.path.endsWith('.spacing'));
  if (spacing) fieldSel.value = spacing.path;
  fieldSel.addEventListener('change', fill);
  fill();
  let chart = null;
  $('sweep-run').addEventListener('click', () => {
    const path = fieldSel.value;
    const a = splitValue($('sweep-from').value);
    const b = splitValue($('sweep-to').value);
    const n = Math.max(2, Math.min(41, Number($('sweep-steps').value) || 7));
    const response = RESPONSES.find(([name]) => name === $('sweep-response').value);
    if (!a || !b) {
      $('sweep-table').replaceChildren(el('tr', {}, el('td', {}, 'from and to: a number with the unit of the value, "6 ft"')));
      return;
    }
    const unit = a[1];
    const rows = [];
    const xs = [];
    const ys = [];
    for (let i = 0; i < n; i++) {
      const x = +(a[0] + ((b[0] - a[0]) * i) / (n - 1)).toPrecision(6);
      const text = `${x} ${unit}`.trim();
      const r = runQuiet({ path, value: text });
      const y = r.ok ? response[1](r.summary) : null;
      xs.push(x);
      ys.push(y);
      rows.push(el('tr', {}, el('td', {}, text), el('td', {}, r.ok ? r.summary.outcome : 'not run'), el('td', {}, y !== null ? fmt(y, 4) : r.ok && response[2] ? response[2](r.summary) : '–'), el('td', {}, r.ok ? '' : r.errors.join('; '))));
    }
    designer.sweep = { path, xs, ys };
    $('sweep-table').replaceChildren(el('thead', {}, el('tr', {}, el('th', {}, path), el('th', {}, 'outcome'), el('th', {}, response[0]), el('th', {}, ''))), el('tbody', {}, ...rows));
    if (chart) chart.destroy();
    const host = $('sweep-plot');
    chart = new uPlot(
      {
        width: Math.max(300, host.clientWidth || 600),
        height: 260,
        scales: { x: { time: false } },
        series: [{ label: `${path}${unit ? ` (${unit})` : ''}` }, { label: response[0], stroke: '#0d3f99', width: 2, spanGaps: true, points: { show: true, size: 6 } }],
        axes: [{ label: `${path}${unit ? ` (${unit})` : ''}` }, { label: response[0] }],
      },
      [xs, ys],
      host,
    );
  });
}

function download() {
  const r = call('cs_web_edit', modelArg, sets().join('\n'));
  if (!r.ok) {
    $('errors').textContent = `No download: ${r.errors.join('; ')}`;
    return;
  }
  designer.downloaded = r.yaml;
  const a = el('a', { href: URL.createObjectURL(new Blob([r.yaml], { type: 'application/yaml' })), download: modelArg.split('/').pop() });
  document.body.append(a);
  a.click();
  a.remove();
}

async function main() {
  const style = document.createElement('style');
  style.textContent = uplotCss;
  document.head.append(style);
  const design = JSON.parse($('cs-data').textContent);
  engine = await createCablesim();
  writeFiles(design);
  modelArg = design.model.replace(/^\/model\//, '');
  modelFile = design.file;
  const opened = call('cs_web_open', design.units, design.data_dir);
  if (!opened.ok) throw new Error(opened.errors.join('; '));
  const values = call('cs_web_values', modelArg);
  if (!values.ok) throw new Error(values.errors.join('; '));
  buildForm(values.values, call('cs_web_parts'));
  $('meta').textContent = `cablesim ${design.version} · model file ${modelFile} · the engine runs in this page (WebAssembly); values take units as in the file ("8 ft", "2.4 m"); each change runs the crash again`;
  $('reset').addEventListener('click', () => {
    for (const f of fields) f.input.value = f.original;
    run();
  });
  $('download').addEventListener('click', download);
  setupSweep();
  run();
  designer.fields = fields.map((f) => f.path);
  designer.run = run;
  // the time of n runs of the model as the form has it, in ms: the engine's (cs_run, as the engine's own
  // clock has it) and the whole call (the model loaded from the page's files, run, its summary written)
  designer.time = (n = 5) => {
    const engineMs = [];
    const loadMs = [];
    const callMs = [];
    for (let i = 0; i < n; i++) {
      const t0 = performance.now();
      const r = runQuiet(null);
      callMs.push(performance.now() - t0);
      engineMs.push(r.ms);
      loadMs.push(r.load_ms);
    }
    return { engineMs, loadMs, callMs };
  };
  designer.ready = true;
}

main().catch((e) => {
  fail('designer', e);
  $('status').textContent = `The designer failed to start: ${e && e.message ? e.message : e}`;
});
