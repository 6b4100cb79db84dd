// SPDX-License-Identifier: MIT
// The other pages cablesim writes, in a real browser (Debian's headless chromium, playwright-core):
// compare.html (`cablesim compare` of two short runs and a synthetic "measured" trace made from the first)
// and a study's report.html (`cablesim sweep` of tests/sweep/mc.yaml). Each opens from file:// with no
// console error and no network request; its tables have their rows; every figure is drawn (an SVG with a
// size on the page, its texts <text> elements) and every id an SVG refers to (clip paths) is its own and
// once in the page, so no figure borrows another's. Then a run's report.html whose clips slip (tests/good/base.yaml, the
// lower rope's at 10 kip): its timeline and design table say so. Screenshots go to OUT.
//
//   node report/test/pages.mjs --cablesim BUILD/cablesim --modules BUILD/report/node_modules --out DIR
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, chromiumPath, finish, launch, pageTestArgs, runCablesim, watchedPage } from './harness.mjs';

const { args, out } = pageTestArgs('report/test/pages.mjs');
const cablesim = (...argv) => runCablesim(args.cablesim, ...argv);

// the inputs: two runs, a synthetic trace from the first (time in ms, speed in mph), a small study
cablesim('run', 'examples/aps3.yaml', '--t-end', '0.2 s', '-o', join(out, 'a'));
cablesim('run', 'examples/aps3.yaml', '--t-end', '0.2 s', '--set', 'scenario.speed=35 mph', '-o', join(out, 'b'));
const rows = readFileSync(join(out, 'a', 'timeseries.csv'), 'utf8').trim().split('\n');
const head = rows[0].split(',');
const [it, iv] = [head.indexOf('t [s]'), head.indexOf('forward_speed [m/s]')];
const trace = ['time [ms],speed [mph]', ...rows.slice(1).map((r) => { const c = r.split(','); return `${c[it] * 1000},${c[iv] / 0.44704}`; })];
writeFileSync(join(out, 'measured.csv'), `${trace.join('\n')}\n`);
cablesim('compare', join(out, 'a'), join(out, 'b'), '--measured', join(out, 'measured.csv'), '-o', join(out, 'compare'));
cablesim('sweep', '--allow-path', 'examples', 'tests/sweep/mc.yaml', '--quiet', '-o', join(out, 'study'));
// a run whose lower rope's clips slip at 10 kip and run out after 6 in (tests/cli_run.sh runs it too)
cablesim('run', 'tests/good/base.yaml', '--set', 'barrier.cables[0].slip_load=10 kip', '--set', 'barrier.cables[0].slip_travel=6 in', '--report', '-o', join(out, 'slip'));

// compare's tables: its header, the outcome and 10 parameters (the max dynamic penetration and the
// penetration beyond, each a row); the validation metrics against the measured trace, a header and a row
// for each run
const pages = [
  { name: 'compare', file: join(out, 'compare', 'compare.html'), figures: 5, tables: [12, 3] },
  { name: 'study', file: join(out, 'study', 'report.html'), figures: 16, tables: [3, 10, 8] },
];
if (!existsSync(chromiumPath)) {
  check(`a browser at ${chromiumPath}`, false, 'install Debian chromium (bash scripts/install-deps.sh)');
  finish();
}
const context = await launch(args.modules, out, { width: 1100, height: 900 });
try {
  for (const p of pages) {
    check(`${p.name}: the page exists`, existsSync(p.file));
    if (!existsSync(p.file)) continue;
    const { page, errors, requests } = await watchedPage(context);
    await page.goto(pathToFileURL(p.file).href, { waitUntil: 'load' });
    const seen = await page.evaluate(() => {
      const svgs = [...document.querySelectorAll('svg')];
      const drawn = svgs.filter((s) => { const b = s.getBoundingClientRect(); return b.width > 300 && b.height > 150; }).length;
      // every reference inside an SVG (xlink:href="#id", clip-path="url(#id)") must name an element of that SVG
      let refs = 0;
      let foreign = 0;
      for (const s of svgs) {
        const own = new Set([...s.querySelectorAll('[id]')].map((e) => e.id));
        for (const e of s.querySelectorAll('*')) {
          for (const a of e.getAttributeNames()) {
            const v = e.getAttribute(a);
            const m = /^#(.+)$/.exec(v) || /url\(#([^)]+)\)/.exec(v);
            if (!m || !/href|clip|mask|fill|filter/.test(a)) continue;
            refs++;
            if (!own.has(m[1])) foreign++;
          }
        }
      }
      const ids = [...document.querySelectorAll('[id]')].map((e) => e.id);
      const repeated = ids.length - new Set(ids).size; // a reference resolves to the first of a repeated id
      const tables = [...document.querySelectorAll('table')].map((t) => t.querySelectorAll('tr').length);
      const texts = svgs.filter((s) => s.querySelector('text') && !s.querySelector('[id*="glyph"]')).length;
      return { svgs: svgs.length, drawn, refs, foreign, repeated, tables, texts };
    });
    check(`${p.name}: ${p.figures} figures`, seen.svgs === p.figures, `${seen.svgs}`);
    check(`${p.name}: every figure drawn with a size`, seen.drawn === p.figures, `${seen.drawn}`);
    check(`${p.name}: every figure's texts are <text>, not glyphs`, seen.texts === p.figures, `${seen.texts}`);
    check(`${p.name}: the figures refer to their clips (${seen.refs})`, seen.refs > 0);
    check(`${p.name}: no figure refers to another's ids`, seen.foreign === 0, `${seen.foreign} of ${seen.refs}`);
    check(`${p.name}: every id once in the page`, seen.repeated === 0, `${seen.repeated} repeated`);
    check(`${p.name}: its tables' rows`, JSON.stringify(seen.tables) === JSON.stringify(p.tables), JSON.stringify(seen.tables));
    check(`${p.name}: no console errors`, errors.length === 0, errors.join(' | '));
    check(`${p.name}: no network requests`, requests.length === 0, requests.join(' '));
    await page.screenshot({ path: join(out, `${p.name}.png`), fullPage: true });
    await page.close();
  }
  // the run report of the clips that slip: its timeline says where a rope starts to slip and runs out, its
  // design table the slip load and turn-back of both ends of the lower rope, in one row
  const { page, errors } = await watchedPage(context);
  await page.goto(pathToFileURL(join(out, 'slip', 'report.html')).href, { waitUntil: 'load' });
  await page.waitForSelector('table.timeline tbody tr');
  const slip = await page.evaluate(() => ({
    rows: [...document.querySelectorAll('table.timeline tbody tr')].map((r) => r.textContent),
    design: [...document.querySelectorAll('table.design tr')].map((r) => r.textContent),
  }));
  for (const end of ['start', 'end'])
    check(`slipping clips: the timeline says cable 0 starts slipping at its ${end} anchor`, slip.rows.some((r) => r.includes(`starts slipping through the end fitting on the ${end} anchor`) && /44\.\d kN/.test(r)), slip.rows.filter((r) => r.includes('slip')).join(' | '));
  check('slipping clips: the timeline says where it runs out', slip.rows.some((r) => /Cable 0 .*breaks at the end fitting/.test(r)));
  check('slipping clips: the design table gives the slip load and turn-back, one row for both ends', slip.design.filter((r) => r.includes('slips at 44.5 kN (10.0 kip), runs out after 0.15 m (0.5 ft)')).length === 1, slip.design.filter((r) => r.includes('fitting')).join(' | '));
  check('slipping clips: no console errors', errors.length === 0, errors.join(' | '));
  await page.close();
} finally {
  await context.close();
}
console.log(`screenshots: ${out}/{compare,study}.png`);
finish();
