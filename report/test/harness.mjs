// SPDX-License-Identifier: MIT
// What the browser tests share: their command line (--name value pairs), counted checks, and a headless
// Debian chromium driven by playwright-core from the report's packages.
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';

export const chromiumPath = process.env.CS_CHROMIUM || '/usr/bin/chromium';

export function parseArgs() {
  const args = {};
  for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
  return args;
}

let passed = 0;
let failed = 0;
export function check(what, ok, detail = '') {
  if (ok) passed++;
  else {
    failed++;
    console.log(`FAIL: ${what}${detail ? `: ${detail}` : ''}`);
  }
}
export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

// A persistent context of headless chromium with a fresh profile under out (its folder: context.profile),
// offline-minded flags.
export async function launch(modules, out, viewport) {
  const require = createRequire(join(resolve(modules), 'noop.js'));
  const { chromium } = require('playwright-core');
  const profile = mkdtempSync(join(out, 'profile-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    viewport,
    deviceScaleFactor: 1,
  });
  context.profile = profile;
  return context;
}

// The command line of a test of pages cablesim writes (--cablesim CABLESIM --modules NODE_MODULES --out
// DIR; usage names the test's script) with DIR made anew: {args, out}.
export function pageTestArgs(script) {
  const args = parseArgs();
  if (!args.modules || !args.out || !args.cablesim) {
    console.error(`usage: node ${script} --cablesim CABLESIM --modules NODE_MODULES --out DIR`);
    process.exit(2);
  }
  const out = resolve(args.out);
  rmSync(out, { recursive: true, force: true });
  mkdirSync(out, { recursive: true });
  return { args, out };
}

// Run the cablesim command, checking that it exits 0; its result (spawnSync's).
export function runCablesim(cablesim, ...argv) {
  const r = spawnSync(cablesim, argv, { encoding: 'utf8' });
  check(`cablesim ${argv.join(' ')} exits 0`, r.status === 0, `${r.status} ${r.stderr}`);
  return r;
}

// A new page of context whose console errors and requests off the disk are collected: {page, errors,
// requests}.
export async function watchedPage(context) {
  const page = await context.newPage();
  const errors = [];
  const requests = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  page.on('request', (r) => { if (!/^(file|data|blob):/.test(r.url())) requests.push(r.url()); });
  return { page, errors, requests };
}
