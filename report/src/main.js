// SPDX-License-Identifier: MIT
// report.html: reads the run's JSON from the page and builds the summary, the 3D replay, the failure
// timeline and the plots. window.csReport exposes the page's state (the browser test reads it).
import uplotCss from 'uplot/dist/uPlot.min.css';
import { story, cards, summaryTable, designTable, timelineTable, designationsText, el } from './summary.js';
import { buildPlots } from './plots.js';
import { dataSheet } from './datasheet.js';
import { createReplay, POST_COLORS, BROKEN_CABLE, postState } from './replay.js';
import { gradient } from './colors.js';
import { pair, fmt, seconds, both } from './units.js';

const report = { ready: false, errors: [], plots: [], replay: null };
window.csReport = report;

function fail(where, e) {
  const msg = `${where}: ${e && e.message ? e.message : e}`;
  report.errors.push(msg);
  console.error(msg);
}

// Index of the last sorted value <= t (0 if none).
function indexAt(ts, t) {
  let lo = 0;
  let hi = ts.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (ts[mid] <= t + 1e-12) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

const SPEEDS = [
  [0.01, '1/100×'],
  [0.02, '1/50×'],
  [0.05, '1/20×'],
  [0.1, '1/10×'],
  [0.25, '1/4×'],
  [0.5, '1/2×'],
  [1, '1× (real time)'],
];

function main() {
  const style = document.createElement('style');
  style.textContent = uplotCss;
  document.head.append(style);
  const data = JSON.parse(document.getElementById('cs-data').textContent);
  report.data = { name: data.name, frames: data.frames.length, series: data.series.t.length, events: data.events.length };
  const $ = (id) => document.getElementById(id);
  const S = data.series;
  const frameT = data.frames.map((f) => f[0]);
  const tEnd = frameT[frameT.length - 1] || 0;

  const prov = data.cablesim;
  $('meta').textContent = `cablesim ${data.version} · model file ${data.file} · model hash ${prov.model_hash || '–'} · ${seconds(data.summary.t_end_s)} simulated with a ${fmt(data.scenario.dt * 1e3, 2)}-ms time step`;
  $('command').textContent = prov.command || '–';
  $('overrides').textContent = prov.overrides.length ? prov.overrides.join('  ') : 'none';
  $('designation').textContent = `Designation as run: ${designationsText(data)}.`;
  try {
    $('datasheet').append(dataSheet(data));
  } catch (e) {
    fail('data sheet', e);
  }
  // the print dialog prints the data sheet; this button the whole report
  $('print-all').addEventListener('click', () => {
    document.body.classList.add('print-all');
    window.print();
  });
  window.addEventListener('afterprint', () => document.body.classList.remove('print-all'));
  $('story').textContent = story(data);
  $('cards').append(cards(data));
  $('table').append(summaryTable(data));
  try {
    $('design').append(designTable(data));
  } catch (e) {
    fail('design table', e);
  }

  // the replay's time drives the timeline's highlight, the plots' time line and the HUD
  let plots = null;
  let replay = null;
  let rows = [];
  let rowEls = [];
  const scrub = $('scrub');
  scrub.max = String(Math.max(0, data.frames.length - 1));

  function hud(i) {
    const f = data.frames[i];
    const t = f[0];
    const k = indexAt(S.t, t);
    const failed = data.barrier.posts.filter((_, p) => postState(f[2][4 * p + 3]) === 'failed').length;
    const cableState = ['intact', 'broken', 'released', 'passed over or under'].map((word, s) => [f[3].filter((c) => c[0] === s).length, word]);
    const latest = rows.filter((r) => r.t <= t + 1e-9).pop();
    const lines = [
      ['t', seconds(t)],
      ['speed', pair('speed', S.speed[k])],
      ['penetration', pair('length', S.penetration[k])],
      ['50-ms decel.', S.decel50[k] === null ? 'from 50 ms' : `${fmt(S.decel50[k], 2)} g`],
      ['posts failed', `${failed} of ${data.barrier.posts.length}`],
      ['cables', cableState.filter(([n], s) => n > 0 || s === 0).map(([n, word]) => `${n} ${word}`).join(', ')],
    ];
    const box = $('hud');
    box.replaceChildren(...lines.map(([a, b]) => el('div', {}, el('span', { class: 'k' }, a), ' ', el('span', { class: 'v' }, b))));
    if (latest) box.append(el('div', { class: 'latest' }, `${fmt(latest.t, 4)} s: ${latest.text}`));
  }

  function onFrame(i) {
    const t = data.frames[i][0];
    scrub.value = String(i);
    $('clock').textContent = `t = ${t.toFixed(3)} s of ${tEnd.toFixed(3)} s`;
    if (plots) plots.setTime(t);
    let cur = -1;
    rows.forEach((r, k) => {
      if (r.t <= t + 1e-9) cur = k;
    });
    rowEls.forEach((tr, k) => {
      tr.classList.toggle('past', k <= cur);
      tr.classList.toggle('current', k === cur);
    });
    try {
      hud(i);
    } catch (e) {
      fail('HUD', e);
    }
  }

  let playing = false;
  let simT = 0;
  let last = null;
  let speed = 0.05;
  const playBtn = $('play');
  function setPlaying(on) {
    playing = on && !!replay;
    playBtn.textContent = playing ? '❚❚ Pause' : '▶ Play';
    playBtn.setAttribute('aria-pressed', String(playing));
    last = null;
    if (playing) requestAnimationFrame(tick);
  }
  function tick(now) {
    if (!playing) return;
    if (last !== null) simT += ((now - last) / 1000) * speed;
    last = now;
    if (simT >= tEnd) {
      simT = tEnd;
      setPlaying(false);
    }
    const i = indexAt(frameT, simT);
    if (i !== replay.frame) replay.showFrame(i);
    if (playing) requestAnimationFrame(tick);
  }
  function seekFrame(i) {
    if (!replay) return;
    replay.showFrame(i);
    simT = frameT[replay.frame];
  }
  function seekTime(t) {
    seekFrame(indexAt(frameT, t));
  }

  try {
    const tl = timelineTable(data, (t) => {
      seekTime(t);
      document.getElementById('replay-section').scrollIntoView({ behavior: 'smooth', block: 'start' });
    });
    rows = tl.rows;
    $('timeline').append(tl.table);
    rowEls = [...tl.table.querySelectorAll('tbody tr')];
  } catch (e) {
    fail('timeline', e);
  }

  // slider ticks at the events
  const ticks = $('ticks');
  for (const r of rows) {
    if (!(tEnd > 0)) break;
    ticks.append(el('span', { class: `tick ${r.group}`, style: `left:${(100 * r.t) / tEnd}%`, title: `${fmt(r.t, 4)} s: ${r.text}` }));
  }

  // speed: the playback of the whole run lasts about 8 s
  const sel = $('speed');
  let best = SPEEDS[0][0];
  for (const [v] of SPEEDS) if (Math.abs(Math.log(tEnd / v / 8)) < Math.abs(Math.log(tEnd / best / 8))) best = v;
  speed = best;
  for (const [v, label] of SPEEDS) sel.append(el('option', v === best ? { value: String(v), selected: '' } : { value: String(v) }, label));
  sel.addEventListener('change', () => {
    speed = Number(sel.value);
  });

  // the colour key of the replay
  let tmaxAll = 0;
  for (const f of data.frames) for (const c of f[3]) for (const v of c[3]) tmaxAll = Math.max(tmaxAll, v);
  if (!(tmaxAll > 0)) tmaxAll = 1;
  $('legend3d').append(
    el('div', { class: 'key' }, ...Object.entries(POST_COLORS).map(([k, c]) => el('span', { class: 'sw' }, el('i', { style: `background:${c}` }), `post ${k === 'yielding' ? 'yielding (hinge or soil)' : k}`))),
    el('div', { class: 'key' }, el('span', { class: 'sw' }, el('i', { style: 'background:#1d3f8f' }), 'front face of the vehicle'), el('span', { class: 'sw' }, el('i', { style: `background:${BROKEN_CABLE}` }), 'cable broken or released')),
    el(
      'div',
      { class: 'bar' },
      el('span', {}, 'cable span tension'),
      el('span', { class: 'grad', style: `background:${gradient()}` }),
      el('span', { class: 'ends' }, el('span', {}, '0'), el('span', {}, `${both.force(tmaxAll)[0]} (${both.force(tmaxAll)[1]})`)),
    ),
  );

  try {
    replay = createReplay($('replay'), data, onFrame);
    report.replay = {
      frameCount: data.frames.length,
      get frame() {
        return replay.frame;
      },
      seekFrame,
      seekTime,
      vehiclePosition: () => replay.vehiclePosition(),
      readPixels: () => replay.readPixels(),
      play: () => setPlaying(true),
      pause: () => setPlaying(false),
      get playing() {
        return playing;
      },
    };
  } catch (e) {
    $('replay').append(el('p', { class: 'nogl' }, `The 3D replay could not start (${e && e.message ? e.message : e}): this browser has no WebGL. Everything else in this report works.`));
    report.replay = { error: String(e && e.message ? e.message : e) };
    console.warn('3D replay unavailable:', e);
  }

  playBtn.addEventListener('click', () => {
    if (!playing && replay && replay.frame >= data.frames.length - 1) seekFrame(0);
    setPlaying(!playing);
  });
  $('restart').addEventListener('click', () => {
    setPlaying(false);
    seekFrame(0);
  });
  scrub.addEventListener('input', () => {
    setPlaying(false);
    seekFrame(Number(scrub.value));
  });
  $('view').addEventListener('change', (e) => replay && replay.setView(e.target.value));
  $('follow').addEventListener('change', (e) => replay && replay.setFollow(e.target.checked));
  document.addEventListener('keydown', (e) => {
    if (!replay || e.target.closest('input, select, button, tr')) return;
    if (e.key === ' ') {
      e.preventDefault();
      playBtn.click();
    } else if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
      setPlaying(false);
      seekFrame(replay.frame + (e.key === 'ArrowRight' ? 1 : -1));
    }
  });

  try {
    plots = buildPlots($('plots'), data, (t) => seekTime(t));
    report.plots = plots.plots.map((p) => ({ key: p.key, title: p.title, length: p.length, points: p.points, get labels() { return p.labels; } }));
  } catch (e) {
    fail('plots', e);
  }
  if (replay) onFrame(replay.frame);
  report.ready = true;
}

try {
  main();
} catch (e) {
  fail('report', e);
  const box = document.getElementById('summary');
  if (box) box.prepend(el('p', { class: 'nogl' }, `This report failed to build: ${e && e.message ? e.message : e}`));
}
