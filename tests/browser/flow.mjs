// What the browser flows share: counted checks, a free port, waiting for `frustum serve` to
// answer, and Debian's chromium started headless by playwright-core.
import {chromium} from 'playwright-core';
import fs from 'node:fs';
import net from 'node:net';

export const checks = {count: 0};
export function check(ok, what) {
  if (!ok) throw new Error('failed: ' + what);
  ++checks.count;
}

export function freePort() {
  return new Promise((resolve) => {
    const s = net.createServer();
    s.listen(0, '127.0.0.1', () => {
      const {port} = s.address();
      s.close(() => resolve(port));
    });
  });
}

export async function waitForServer(base) {
  for (let i = 0; i < 100; ++i) {
    try {
      await fetch(base + '/');
      return;
    } catch {
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  throw new Error('the server did not start');
}

export function launch(profile, viewport) {
  return chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    viewport,
  });
}

// Runs a flow's main: on failure, its error and exit status 1.
export function run(main) {
  main().catch((e) => {
    console.error(e.stack || String(e));
    process.exit(1);
  });
}
