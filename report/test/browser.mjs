// SPDX-License-Identifier: MIT
// report.html in a real browser: Debian's headless chromium driven by playwright-core. Runs a short real
// simulation with --report, opens the page from file:// and checks what a reader would see: no console
// errors and no network requests, the summary and the timeline filled, the 3D replay drawn (pixels read
// back), scrubbing to the end moves the vehicle, playing advances, every plot has data, the design table
// gives the model's values in their units; printed as it opens (print media) it is the data sheet alone on one
// page of A4 and of Letter with no text under 8 pt, and printed whole (print media, A4) the page drops the
// replay and its controls, shows every timeline row and nothing wider than the page, and makes a PDF; printed
// whole from a window wider than the paper, each plot is drawn for the paper and as wide as its card. Screenshots and the
// PDF go to OUT (a build dir: test artifacts, never committed).
//
//   node report/test/browser.mjs --cablesim BUILD/cablesim --modules BUILD/report/node_modules --out DIR
//        [--report FILE]      check this report instead of running one
//        [--model FILE] [--t-end T]   the run (default examples/aps3.yaml, 55 ms: the 50-ms average exists)
//        [--docs-shot FILE] [--docs-at F]   also the story, the cards and the replay (the data sheet above them
//                             scrolled past), replay at F of the run (0.6), 1200 x 1080 (docs/report.png)
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, chromiumPath, finish, launch, parseArgs } from './harness.mjs';

const args = parseArgs();
if (!args.modules || !args.out || (!args.cablesim && !args.report)) {
  console.error('usage: node report/test/browser.mjs --cablesim CABLESIM --modules NODE_MODULES --out DIR [--report FILE]');
  process.exit(2);
}
const out = resolve(args.out);
mkdirSync(out, { recursive: true });


let report = args.report && resolve(args.report);
if (!report) {
  const dir = join(out, 'run');
  rmSync(dir, { recursive: true, force: true });
  const t0 = Date.now();
  const r = spawnSync(args.cablesim, ['run', args.model || 'examples/aps3.yaml', '--t-end', args['t-end'] || '55 ms', '-o', dir, '--report'], { encoding: 'utf8' });
  check('cablesim run --report exits 0', r.status === 0, `${r.status} ${r.stderr}`);
  check('the summary names report.html', /report\.html/.test(r.stdout), r.stdout);
  report = join(dir, 'report.html');
  console.log(`run: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
}
check('report.html exists', existsSync(report));
if (!existsSync(report)) finish();
const size = statSync(report).size;
check('report.html is at most a few MB', size > 100e3 && size < 8e6, `${size} bytes`);
if (!existsSync(chromiumPath)) {
  check(`a browser at ${chromiumPath}`, false, 'install Debian chromium (bash scripts/install-deps.sh)');
  finish();
}

const context = await launch(args.modules, out, { width: 1400, height: 1000 });
const page = context.pages()[0] || (await context.newPage());
const consoleErrors = [];
const requests = [];
page.on('console', (m) => {
  if (m.type() === 'error') consoleErrors.push(m.text());
});
page.on('pageerror', (e) => consoleErrors.push(`page error: ${e.message}`));
page.on('request', (r) => {
  if (!/^(file|data|blob):/.test(r.url())) requests.push(r.url());
});

try {
  const t0 = Date.now();
  await page.goto(pathToFileURL(report).href, { waitUntil: 'load' });
  await page.waitForFunction(() => window.csReport && window.csReport.ready, null, { timeout: 60000 });
  console.log(`page ready: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  const state = await page.evaluate(() => ({ errors: window.csReport.errors, data: window.csReport.data, replayError: window.csReport.replay && window.csReport.replay.error }));
  check('the page reports no errors of its own', state.errors.length === 0, state.errors.join('; '));

  // summary and timeline
  const story = await page.textContent('#story');
  check('the story says what happened', story.length > 100 && /vehicle/.test(story), story);
  check('six summary cards', (await page.locator('.card').count()) === 6);
  const rows = await page.locator('table.timeline tbody tr').count();
  check('the timeline lists the events', rows >= Math.min(2, state.data.events) && rows <= state.data.events + 2, `${rows} rows for ${state.data.events} events`);
  const meta = await page.textContent('header');
  check('the header gives the version and the model hash', /cablesim \d+\.\d+\.\d+/.test(meta) && /model hash [0-9a-f]{16}\b/.test(meta), meta);
  if (!args.report) {
    check('the header gives the command line and its overrides', /command: .*cablesim.* run /.test(meta) && /overrides: --t-end 55 ms/.test(meta), meta);
    // a 55-ms run ends at its time limit: no penetration as such, only how far the vehicle got
    const pen = await page.locator('.card').nth(2).textContent();
    check('a run still going gives its penetration as "beyond"', /^Penetrationbeyond \d/.test(pen), pen);
  }
  const designation = await page.textContent('#designation');
  check('the designation as run is stated', /^Designation as run: (ASTM F2656|not rated)/.test(designation), designation);
  const table = await page.textContent('table.summary');
  check('the summary table gives SI and US units', /m\/s/.test(table) && /mph/.test(table) && /kip/.test(table) && /ft/.test(table));

  // the 3D replay
  check('the 3D replay started (WebGL)', !state.replayError, state.replayError);
  if (!state.replayError) {
    const first = await page.evaluate(() => {
      window.csReport.replay.seekFrame(0);
      return { pos: window.csReport.replay.vehiclePosition(), px: window.csReport.replay.readPixels(), n: window.csReport.replay.frameCount };
    });
    check('the replay has frames', first.n >= 10, `${first.n}`);
    check('the 3D canvas drew a non-blank frame', first.px.nonBackground > 0.2 && first.px.colours > 30, JSON.stringify(first.px));
    await page.screenshot({ path: join(out, 'replay-start.png') });
    // scrub to the end with the slider, as a reader would
    await page.focus('#scrub');
    await page.keyboard.press('End');
    const last = await page.evaluate(() => ({ frame: window.csReport.replay.frame, pos: window.csReport.replay.vehiclePosition(), px: window.csReport.replay.readPixels(), clock: document.getElementById('clock').textContent }));
    check('the slider scrubs to the last frame', last.frame === first.n - 1, `${last.frame} of ${first.n}`);
    const moved = Math.hypot(...last.pos.map((v, i) => v - first.pos[i]));
    check('scrubbing to the end moves the vehicle', moved > 0.3, `${moved.toFixed(3)} m`);
    check('the rendered frame changes with it', last.px.hash !== first.px.hash && last.px.nonBackground > 0.2);
    check('the clock shows the time', /t = \d/.test(last.clock), last.clock);
    await page.screenshot({ path: join(out, 'replay-end.png') });
    // play from the start for a moment, then pause
    await page.click('#restart');
    await page.click('#play');
    await page.waitForTimeout(1500);
    const playing = await page.evaluate(() => ({ frame: window.csReport.replay.frame, playing: window.csReport.replay.playing }));
    await page.click('#play');
    const paused = await page.evaluate(() => window.csReport.replay.frame);
    await page.waitForTimeout(400);
    const still = await page.evaluate(() => window.csReport.replay.frame);
    check('play advances the replay', playing.frame > 0, JSON.stringify(playing));
    check('pause stops it', paused === still, `${paused} -> ${still}`);
    // a timeline row moves the replay to its time
    if (rows >= 2) {
      await page.locator('table.timeline tbody tr').nth(1).click();
      const rowT = Number(await page.locator('table.timeline tbody tr').nth(1).getAttribute('data-t'));
      const at = await page.evaluate(() => window.csReport.replay.frame);
      const frameT = await page.evaluate((i) => JSON.parse(document.getElementById('cs-data').textContent).frames[i][0], at);
      check('a timeline row seeks the replay', Math.abs(frameT - rowT) < 0.01, `${frameT} vs ${rowT}`);
    }
  }

  // the plots
  const plots = await page.evaluate(() =>
    window.csReport.plots.map((p) => {
      const canvas = document.querySelector(`#plot-${p.key} canvas`);
      // the path in plan is a drawing (SVG): the CG's path and the four wheels' tracks
      if (!canvas) return { ...p, ink: document.querySelectorAll(`#plot-${p.key} svg polyline`).length >= 5 ? 1 : 0 };
      const ctx = canvas.getContext('2d');
      const img = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
      let ink = 0;
      for (let i = 0; i < img.length; i += 4) if (img[i + 3] > 0 && img[i] + img[i + 1] + img[i + 2] < 600) ink++;
      return { key: p.key, points: p.points, length: p.length, labels: p.labels, ink: ink / (canvas.width * canvas.height) };
    }),
  );
  const expected = ['deceleration', 'speed', 'penetration', 'angles', 'cables', 'post_tilt', 'post_moment', 'energy', 'path'];
  check('every plot is there', expected.every((k) => plots.some((p) => p.key === k)), plots.map((p) => p.key).join(','));
  for (const p of plots) {
    check(`plot ${p.key} has its time axis`, p.length >= 10, `${p.length}`);
    check(`plot ${p.key}: every series has data`, p.points.length > 0 && p.points.every((n) => n > 0), JSON.stringify(p.points));
    check(`plot ${p.key} is drawn`, p.ink > 0.01, `${(100 * p.ink).toFixed(2)} % ink`);
    check(`plot ${p.key}: every marker's note inside the plotting area`, p.labels.every((l) => l.x0 >= l.left && l.x1 <= l.right), JSON.stringify(p.labels));
  }

  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(out, 'report-top.png') });
  for (const id of ['summary', 'replay-section', 'timeline-section', 'plots-section', 'design-section', 'numbers'])
    await page.locator(`#${id}`).screenshot({ path: join(out, `section-${id}.png`) });
  await page.screenshot({ path: join(out, 'report-full.png'), fullPage: true });
  if (args['docs-shot']) {
    await page.setViewportSize({ width: 1200, height: 1080 });
    await page.evaluate((f) => {
      window.csReport.replay.seekFrame(Math.round(f * (window.csReport.replay.frameCount - 1)));
      document.getElementById('summary').scrollIntoView();
    }, Number(args['docs-at'] || 0.6));
    await page.waitForTimeout(500);
    await page.screenshot({ path: resolve(args['docs-shot']) });
  }
  // the design table: the model's values in their own units (examples/aps3.yaml: 1.75-in ropes at 5 kip,
  // line posts of 50-ksi steel 8 ft apart, 8000-psf soil), and the engine's in SI
  const design = await page.evaluate(() => {
    const cells = {};
    for (const tr of document.querySelectorAll('#design-table tr[data-design]')) cells[tr.dataset.design] = [tr.children[1].textContent, tr.children[2].textContent];
    return { cells, rows: document.querySelectorAll('#design-table tbody tr').length, json: JSON.parse(document.getElementById('cs-data').textContent).design };
  });
  check('the design table is there', design.rows > 20 && design.cells['rope-0-pretension'], `${design.rows} rows`);
  if (design.cells['rope-0-pretension']) {
    const num = (text, unit) => Number((text.match(new RegExp(`^([0-9.]+) ${unit}$`)) || [])[1]);
    const ropes = design.json.ropes;
    check('the rope pretension is the model\'s, in kN', ropes.every((r, c) => Math.abs(num(design.cells[`rope-${c}-pretension`][0], 'kN') - r.pretension_n / 1e3) < 0.05), JSON.stringify(design.cells['rope-0-pretension']));
    if (!args.report || args.model === 'examples/aps3.yaml') {
      const near = (id, col, unit, want, tol) => {
        const got = num(design.cells[id][col], unit);
        check(`design: ${id} is ${want} ${unit}`, Math.abs(got - want) <= tol, `${design.cells[id][col]}`);
      };
      near('rope-0-pretension', 1, 'kip', 5, 0.005);
      near('rope-1-pretension', 1, 'kip', 5, 0.005);
      near('rope-0-diameter', 1, 'in', 1.75, 0.005);
      near('post-kind-0-fy', 1, 'ksi', 50, 0.05);
      near('spacing', 1, 'ft', 8, 0.05);
      near('soil-pressure', 1, 'psf', 8000, 0.5);
      // clips at both ends of each rope: one row
      for (const c of [0, 1]) check(`design: rope ${c}'s end fittings`, (design.cells[`rope-${c}-fitting`] || [])[0] === 'clips, 90 % of Fu', JSON.stringify(design.cells[`rope-${c}-fitting`]));
    }
  }

  // printed as it opens: the data sheet alone, on one page of A4 and of Letter, no text under 8 pt
  await page.emulateMedia({ media: 'print' });
  const sheet = await page.evaluate(() => {
    const visible = (e) => e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden';
    const texts = [...document.querySelectorAll('body *')].filter((e) => visible(e) && [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim()));
    return {
      others: [...document.querySelectorAll('main > section, header, footer')].filter((e) => e.id !== 'datasheet-section' && visible(e)).map((e) => e.tagName + (e.id ? `#${e.id}` : '')),
      small: texts.filter((e) => parseFloat(getComputedStyle(e).fontSize) < (8 * 96) / 72 - 0.01).map((e) => `${e.tagName}.${e.className} ${getComputedStyle(e).fontSize}: ${e.textContent.slice(0, 30)}`).slice(0, 5),
      texts: texts.length,
    };
  });
  check('printed as it opens: the data sheet alone', sheet.others.length === 0, sheet.others.join(' '));
  check('printed data sheet: no text under 8 pt', sheet.texts > 50 && sheet.small.length === 0, `${sheet.texts} texts; ${sheet.small.join(' | ')}`);
  for (const format of ['A4', 'Letter']) {
    const one = await page.pdf({ format });
    const n = (one.toString('latin1').match(/\/Type\s*\/Page\b/g) || []).length;
    check(`printed data sheet: one page of ${format}`, n === 1, `${n} pages`);
    writeFileSync(join(out, `datasheet-${format}.pdf`), one);
  }
  await page.emulateMedia({ media: 'screen' });

  // printed whole from a window wider than the paper, as the button prints it: window.print() fires
  // beforeprint, then lays the page out for the paper with no frame between (no ResizeObserver's width). Each
  // plot drawn for the paper, no wider than A4's printable width (190 mm, 718 px), and shown as wide as its
  // card; after the print, drawn for the screen again.
  const plotWidths = () => page.evaluate(() => [...document.querySelectorAll('.plot')].map((h) => {
    const c = h.querySelector('canvas');
    return [c.width / devicePixelRatio, Math.round(c.getBoundingClientRect().width), h.clientWidth];
  }));
  // the plots as the screen has them again after the print media above (the ResizeObserver's callbacks
  // come before the next frames: wait for two)
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const onScreen = await plotWidths();
  await page.evaluate(() => {
    document.body.classList.add('print-all');
    window.dispatchEvent(new Event('beforeprint'));
  });
  await page.emulateMedia({ media: 'print' });
  const drawn = await plotWidths();
  check('printed whole from a wide window: each plot drawn for the paper (at most 718 px) and as wide as its card', drawn.length > 0 && drawn.every(([w, shown, card]) => w <= 718 && Math.abs(shown - card) <= 1), JSON.stringify(drawn));
  // a browser lays the page out for the screen again before it fires afterprint; the observer's redraws
  // come before the next frames
  await page.emulateMedia({ media: 'screen' });
  await page.evaluate(() => window.dispatchEvent(new Event('afterprint')));
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const after = await plotWidths();
  check('after the print: each plot drawn for the screen again', onScreen.some(([w]) => w > 718) && JSON.stringify(after) === JSON.stringify(onScreen), JSON.stringify([onScreen, after]));

  // printed whole (the sheet's "Print the whole report"): no controls or replay, every timeline row,
  // nothing wider than an A4 page, a PDF of a few pages
  await page.evaluate(() => document.body.classList.add('print-all'));
  await page.setViewportSize({ width: 720, height: 1000 });
  await page.emulateMedia({ media: 'print' });
  // the plots follow their container's width by a ResizeObserver, whose callbacks come before the next
  // frames: wait for two, as a printed page is laid out after them
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const printed = await page.evaluate(() => {
    const shown = (sel) => getComputedStyle(document.querySelector(sel)).display !== 'none';
    const wrap = document.querySelector('.timeline-wrap');
    return {
      replay: shown('#replay-section'),
      controls: [...document.querySelectorAll('.controls')].some((c) => getComputedStyle(c).display !== 'none'),
      design: shown('#design-section'),
      timelineCut: wrap.scrollHeight - wrap.clientHeight,
      // a drawing's inner shapes are clipped to their svg's box (overflow hidden), which is checked itself
      wide: [...document.querySelectorAll('main *')]
        .filter((e) => !(e.ownerSVGElement && getComputedStyle(e.ownerSVGElement).overflow !== 'visible'))
        .filter((e) => e.getBoundingClientRect().right > document.documentElement.clientWidth + 1)
        .map((e) => e.tagName + (e.id ? `#${e.id}` : ''))
        .slice(0, 5),
    };
  });
  check('printed: no replay and no controls', !printed.replay && !printed.controls, JSON.stringify(printed));
  check('printed: the design table shows', printed.design);
  check('printed: every timeline row', printed.timelineCut <= 1, `${printed.timelineCut} px cut`);
  check('printed: nothing wider than the page', printed.wide.length === 0, printed.wide.join(' '));
  const pdf = await page.pdf({ format: 'A4', printBackground: true });
  const pages = (pdf.toString('latin1').match(/\/Type\s*\/Page\b/g) || []).length;
  check('printed: a PDF of a few pages', pdf.subarray(0, 5).toString() === '%PDF-' && pages >= 2 && pages <= 30, `${pdf.length} bytes, ${pages} pages`);
  writeFileSync(join(out, 'report-print.pdf'), pdf);
  await page.emulateMedia({ media: 'screen' });
  await page.evaluate(() => document.body.classList.remove('print-all'));
  await page.setViewportSize({ width: 1400, height: 1000 });

  // A roadside run's data sheet row for MASH's exit box, beside summary.json's exit_box: the run's
  // cablesim run --report in out/name, its exit status checked
  async function exitBoxRow(name, runArgs) {
    const dir = join(out, name);
    rmSync(dir, { recursive: true, force: true });
    const r = spawnSync(args.cablesim, ['run', ...runArgs, '-o', dir, '--report'], { encoding: 'utf8' });
    check(`${name}: cablesim run --report exits 0`, r.status === 0, `${r.status} ${r.stderr}`);
    const box = JSON.parse(readFileSync(join(dir, 'summary.json'), 'utf8')).roadside_criteria.exit_box;
    await page.goto(pathToFileURL(join(dir, 'report.html')).href, { waitUntil: 'load' });
    await page.waitForFunction(() => window.csReport && window.csReport.ready, null, { timeout: 60000 });
    const cell = await page.evaluate(() => {
      const th = [...document.querySelectorAll('table.sheet-block th')].find((e) => e.textContent === 'exit box (MASH)');
      return th ? th.nextElementSibling.textContent : '';
    });
    return { box, cell };
  }

  if (!args.report) {
    // APS1's anchor posts are tubes filled with 3,000-psi concrete: the data sheet names the fill and gives
    // the plastic moment the engine takes, the steel's and the fill's (15.00 kN m: docs/theory.md, "A tube
    // filled with concrete"), not the hollow tube's Zx Fy (13.67)
    const dir = join(out, 'aps1');
    rmSync(dir, { recursive: true, force: true });
    const r = spawnSync(args.cablesim, ['run', 'examples/aps1.yaml', '--t-end', '2 ms', '-o', dir, '--report'], { encoding: 'utf8' });
    check('aps1: cablesim run --report exits 0', r.status === 0, `${r.status} ${r.stderr}`);
    await page.goto(pathToFileURL(join(dir, 'report.html')).href, { waitUntil: 'load' });
    await page.waitForFunction(() => window.csReport && window.csReport.ready, null, { timeout: 60000 });
    const fill = await page.evaluate(() => {
      const cell = (id) => { const tr = document.querySelector(`#design-table tr[data-design="${id}"]`); return tr ? tr.children[1].textContent : ''; };
      return { fill: cell('post-kind-0-fill'), mp: cell('post-kind-0-mp'), line: cell('post-kind-1-fill') }; // post 0 is an anchor post
    });
    check('APS1: the anchor posts\' fill and plastic moment', fill.fill === '20.7 MPa' && fill.mp === '15.0 kN·m' && fill.line === '', JSON.stringify(fill));
    // the design's pickup at 20 deg is redirected and its wheels cross the exit box's far side only on the
    // path extrapolated from the run's end (summary.json's exit_box.crossed_in_run false): the data sheet,
    // whose next row says how far the path after the loss of contact is simulated, says so as the criteria do
    let { box, cell } = await exitBoxRow('far', ['examples/roadside/design.yaml', '--set', 'scenario.angle=20 deg']);
    check('20 deg: the data sheet says its exit box crossing is on the extrapolated path', box.crossed_in_run === false && cell === `crossed ${box.cross_along_m.toFixed(1)} m along on the path extrapolated from the run's end (B = ${box.b_m.toFixed(1)} m)`, `${cell} (crossed_in_run ${box.crossed_in_run})`);
    // the design's pickup at 8 deg, its tyres gripping at a friction of 1.0, leaves the ropes and, a
    // vehicle's length on, moves back toward the barrier with no wheel past the box's far side: the data
    // sheet says its box is not judged, as the criteria do
    ({ box, cell } = await exitBoxRow('back', ['examples/roadside/design.yaml', '--set', 'scenario.angle=8 deg', '--set', 'vehicle.tyre_friction=1.0']));
    check('moving back: the data sheet says its exit box is not judged', box.heading_back === true && cell.startsWith('not judged: no wheel crossed in the run'), `${cell} (heading_back ${box.heading_back})`);
  }

  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
  check('no network requests', requests.length === 0, requests.join(' '));
} catch (e) {
  check('the browser session', false, e.stack || String(e));
} finally {
  await context.close();
  rmSync(context.profile, { recursive: true, force: true });
}
console.log(`screenshots: ${out}/{report-top,report-full,replay-start,replay-end,section-*}.png`);
finish();
