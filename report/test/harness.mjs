// What the browser tests share: their command line (--name value pairs), counted checks, and a headless
// Debian chromium driven by playwright-core from the report's packages.
import { createRequire } from 'node:module';
import { mkdtempSync } from 'node:fs';
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
