// SPDX-License-Identifier: MIT
// One run, one truth, in the designer too (tests/cli_one_truth.sh checks the terminal, summary.json, the
// CSVs, report.html and compare): designer.html of examples/aps3.yaml in headless chromium, as the file has
// it and then with the post spacing and the speed changed in its form, against `cablesim run --report` of
// the same values. The numbers the page shows (its summary table, cards, story and designation as run, as
// the page draws them) are report.html's, row for row and word for word; the peak 50-ms deceleration and
// its time are the terminal's; and each number agrees with summary.json to the digits shown, the
// penetration to 1 cm, as in tests/one_truth.mjs. The model file is named as the command was given it. Cables are
// counted from 0 in the form, the table and summary.json alike, and the posts failed are summary.json's.
// Exit 77 (skipped) when the command's maths are glibc's: the page's are musl's, and their numbers then
// differ in the last digits (report/test/designer.mjs compares those within 2%).
//
//   node report/test/designer_truth.mjs --cablesim BUILD/cablesim --modules BUILD/report/node_modules --out DIR
//                                       [--math glibc|musl]
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, chromiumPath, finish, launch, pageTestArgs, runCablesim, watchedPage } from './harness.mjs';

const { args, out } = pageTestArgs('report/test/designer_truth.mjs');
if (args.math !== 'musl') {
  console.log('skipped: the command computes with glibc\'s maths and the page with musl\'s, so their numbers differ in the last digits (report/test/designer.mjs compares them within 2%)');
  process.exit(77);
}
if (!existsSync(chromiumPath)) {
  console.log(`skipped: no browser at ${chromiumPath} (bash scripts/install-deps.sh installs Debian's chromium)`);
  process.exit(77);
}

// What a page shows: its summary table's rows (each as its cells' texts), cards, story and designation.
async function shown(page) {
  return page.evaluate(() => {
    const text = (id) => document.getElementById(id).innerText.trim();
    const rows = [...document.querySelectorAll('#table tbody tr')].map((tr) => [...tr.children].map((c) => c.textContent));
    const cards = [...document.querySelectorAll('#cards .card')].map((c) => [...c.children].map((x) => x.textContent));
    return { rows, cards, story: text('story'), designation: text('designation') };
  });
}

// Does the text give the value to the digits it shows? "12.3" stands for 12.25 to 12.35.
function toDigits(text, value) {
  const m = String(text).match(/-?[0-9]+(?:\.([0-9]+))?/);
  if (!m) return false;
  const half = 0.5 * 10 ** -(m[1] ? m[1].length : 0);
  return Math.abs(Number(m[0]) - value) <= half * (1 + 1e-9);
}

const seeAll = (rows) => Object.fromEntries(rows.map((r) => [r[0], r.slice(1)]));

// The designer's page against the command's run of the same values: its report.html, terminal and
// summary.json.
async function compare(what, context, designer, sets) {
  const dir = join(out, what.replace(/\W+/g, '-'));
  const r = runCablesim(args.cablesim, 'run', 'examples/aps3.yaml', ...sets.flatMap((s) => ['--set', s]), '-o', dir, '--report');
  const term = r.stdout;
  const summary = JSON.parse(readFileSync(join(dir, 'summary.json'), 'utf8'));
  const { page: reportPage } = await watchedPage(context);
  await reportPage.goto(pathToFileURL(join(dir, 'report.html')).href, { waitUntil: 'load' });
  await reportPage.waitForFunction(() => document.querySelectorAll('#table tbody tr').length > 0, null, { timeout: 60000 });
  const report = await shown(reportPage);
  await reportPage.close();
  const page = await shown(designer);

  // the page's words are report.html's: every row of the summary table, every card, the story
  const want = seeAll(report.rows);
  const got = seeAll(page.rows);
  const differ = Object.keys(want).filter((k) => JSON.stringify(want[k]) !== JSON.stringify(got[k]));
  check(`${what}: the designer's summary table is report.html's, row for row (${report.rows.length} rows)`, page.rows.length === report.rows.length && differ.length === 0, differ.map((k) => `${k}: report ${JSON.stringify(want[k])}, designer ${JSON.stringify(got[k])}`).join('; '));
  check(`${what}: the designer's cards are report.html's`, JSON.stringify(page.cards) === JSON.stringify(report.cards) && page.cards.length >= 6, JSON.stringify([page.cards, report.cards]));
  check(`${what}: the designer's story is report.html's`, page.story === report.story && page.story.length > 100, JSON.stringify([page.story, report.story]));

  // the designation as run: summary.json's words
  const designations = summary.designations_as_run.map((d) => d.text).join('; ');
  check(`${what}: the designation as run is summary.json's`, page.designation === `Designation as run: ${designations}.` && got['Designation as run'][0] === designations && summary.designations_as_run.length === 2, `${page.designation} vs ${designations}`);
  // the peak 50-ms deceleration and its time: the terminal's, and summary.json's to the digits shown
  const termG = (term.match(/max 50-ms deceleration ([0-9.]+) g/) || [])[1];
  const termT = (term.match(/max 50-ms deceleration [0-9.]+ g at t = ([0-9.]+) s/) || [])[1];
  const decel = got['Max 50-ms deceleration'] || [];
  check(`${what}: the peak 50-ms deceleration is the terminal's, at its time`, termG !== undefined && decel[0] === `${termG} g` && decel[1] === `at t = ${termT} s`, `${JSON.stringify(decel)} vs ${termG} g at ${termT} s`);
  check(`${what}: the peak 50-ms deceleration and its time are summary.json's to the digits shown`, toDigits(decel[0], summary.max_50ms_decel_g) && toDigits(decel[1], summary.t_max_50ms_decel_s), `${JSON.stringify(decel)} vs ${summary.max_50ms_decel_g} g at ${summary.t_max_50ms_decel_s} s`);
  // the penetration: a number where the vehicle stopped, "beyond" where it got through (1 cm)
  const through = summary.max_dynamic_penetration_m === null;
  const pen = through ? summary.penetration_beyond_m : summary.max_dynamic_penetration_m;
  const penRow = got['Max dynamic penetration (front face)'] || [];
  check(`${what}: the penetration is summary.json's (1 cm)`, penRow[0] === `${through ? 'beyond ' : ''}${pen.toFixed(2)} m`, `${penRow[0]} vs ${pen}`);
  // the cables, counted from 0, each with summary.json's peak tension and its time to the digits shown
  summary.cables.forEach((c, i) => {
    const row = got[`Cable ${i}: peak tension`] || [];
    const m = (row[0] || '').match(/^([0-9.]+) kN at t = ([0-9.]+) s$/);
    check(`${what}: cable ${i}: the designer's cable ${i} is summary.json's (its peak and time to the digits shown)`, c.index === i && m && toDigits(m[1], c.peak_tension_n / 1e3) && toDigits(m[2], c.peak_tension_time_s), `${row[0]} vs ${c.peak_tension_n} N at ${c.peak_tension_time_s} s`);
  });
  check(`${what}: the table has a row per cable of summary.json, and no other`, page.rows.filter((row) => /^Cable \d+: peak tension$/.test(row[0])).length === summary.cables.length);
  // the posts failed and the cables broken: summary.json's counts
  const failed = summary.posts_failed_left + summary.posts_failed_right;
  const posts = summary.inputs.barrier.posts.length;
  const termPosts = term.match(/posts failed +(\d+) left, (\d+) right \(of (\d+)\)/) || [];
  check(`${what}: the posts failed are summary.json's and the terminal's, of its posts`, (got['Posts failed'] || [])[0] === `${failed} of ${posts}` && `${Number(termPosts[1]) + Number(termPosts[2])} of ${termPosts[3]}` === `${failed} of ${posts}`, `${(got['Posts failed'] || [])[0]} vs ${failed} of ${posts}, the terminal ${termPosts[0]}`);
  check(`${what}: the cables broken are summary.json's`, (got['Cables broken'] || [])[0] === `${summary.cables_broken} of ${summary.cables.length}`, (got['Cables broken'] || [])[0]);
  return summary;
}

runCablesim(args.cablesim, 'designer', 'examples/aps3.yaml', '-o', join(out, 'page'));
const context = await launch(args.modules, out, { width: 1300, height: 1000 });
const { page, errors } = await watchedPage(context);
try {
  await page.goto(pathToFileURL(join(out, 'page', 'designer.html')).href, { waitUntil: 'load' });
  await page.waitForFunction(() => window.csDesigner && (window.csDesigner.ready || window.csDesigner.errors.length), null, { timeout: 120000 });
  const first = await page.evaluate(() => window.csDesigner.last);
  check('the page ran the model as the file has it', first && first.ok, JSON.stringify(first && first.errors));
  const summary = await compare('APS3 as the file has it', context, page, []);

  // the form's cables, counted from 0 as summary.json's: "cable i: ..." edits barrier.cables[i]
  const labels = await page.evaluate(() => [...document.querySelectorAll('.field')].map((f) => [f.dataset.path, f.querySelector('label').textContent]));
  const cableFields = labels.filter(([p]) => p.startsWith('barrier.cables['));
  const indices = [...new Set(cableFields.map(([p]) => Number(p.match(/^barrier\.cables\[(\d+)\]/)[1])))];
  check('the form names barrier.cables[i] "cable i", i from 0 as in summary.json', cableFields.length > 0 && cableFields.every(([p, l]) => l.startsWith(`cable ${p.match(/^barrier\.cables\[(\d+)\]/)[1]}: `)) && JSON.stringify(indices) === JSON.stringify(summary.cables.map((c) => c.index)), JSON.stringify(cableFields));
  // its groups of posts by the names the model file gives them (barrier.posts[i] is group i, not post i:
  // the posts themselves are counted from 0 along the barrier, as the terminal's "post 7")
  const model = readFileSync('examples/aps3.yaml', 'utf8');
  const groups = [...model.slice(model.indexOf('\n  posts:')).matchAll(/^ {4}- name: ([^#\n]*?) *(?:#.*)?$/gm)].map((m) => m[1]);
  const postFields = labels.filter(([p]) => /^barrier\.posts\[\d+\]\./.test(p));
  check('the form names each group of posts by its name in the model file', groups.length === 2 && postFields.length > 0 && postFields.every(([p, l]) => l.startsWith(`${groups[Number(p.match(/\[(\d+)\]/)[1])]}: `)), JSON.stringify([groups, postFields]));

  // the form's values changed: the page's run is the command's with the same --set
  const field = (path) => page.locator(`.field[data-path="${path}"] input`);
  for (const [path, value] of [['barrier.posts[0].spacing', '6 ft'], ['scenario.speed', '35 mph']]) {
    const runs = await page.evaluate(() => window.csDesigner.runs);
    await field(path).fill(value);
    await field(path).dispatchEvent('change');
    await page.waitForFunction((n) => window.csDesigner.runs > n, runs, { timeout: 60000 });
  }
  const changed = await page.evaluate(() => window.csDesigner.last);
  check('the page ran the changed model', changed.ok, JSON.stringify(changed.errors));
  const other = await compare('APS3 with 6-ft spacing at 35 mph', context, page, changed.sets);
  check('the changed run is another run', other.max_50ms_decel_g !== summary.max_50ms_decel_g && other.inputs.scenario.speed !== summary.inputs.scenario.speed);
  check('no console error', errors.length === 0, errors.join(' | '));
} finally {
  await context.close();
}
finish();
