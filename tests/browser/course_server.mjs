// What each browser flow starts with: a course directory, its links, `frustum serve` on a free
// port, and Debian's chromium driven headless by playwright-core, its script errors collected.
import {spawn, execFileSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {freePort, launch, waitForServer} from './flow.mjs';

// check(ok, what) throws with `what` when !ok; checks() counts the ones that passed.
export function checker() {
  let passed = 0;
  const check = (ok, what) => {
    if (!ok) throw new Error('failed: ' + what);
    ++passed;
  };
  return {check, checks: () => passed};
}

// sets: {name: yaml}; roster: students' ids; instructors: instructors' ids (instructors.csv).
// Returns {course, base, link (id → url), page, problems (script errors and CSP violations),
// close()}.
export async function startCourse({frustum, work, out, sets, roster, instructors = [], viewport, serveArgs = []}) {
  fs.rmSync(work, {recursive: true, force: true});
  fs.mkdirSync(work, {recursive: true});
  fs.mkdirSync(out, {recursive: true});
  const course = path.join(work, 'course');
  fs.mkdirSync(course);
  for (const [name, text] of Object.entries(sets)) fs.writeFileSync(path.join(course, name + '.yaml'), text);
  fs.writeFileSync(path.join(course, 'roster.csv'), 'student\n' + roster.join('\n') + '\n');
  if (instructors.length)
    fs.writeFileSync(path.join(course, 'instructors.csv'), 'instructor\n' + instructors.join('\n') + '\n');
  const port = await freePort();
  const base = `http://127.0.0.1:${port}`;
  const links = path.join(work, 'links.csv');
  execFileSync(frustum, ['serve', course, '--issue-links', links, '--public-url', base]);
  const link = Object.fromEntries(fs.readFileSync(links, 'utf8').trim().split('\n').slice(1).map((l) => l.split(',')));
  const server = spawn(frustum, ['serve', course, '--listen', `127.0.0.1:${port}`, ...serveArgs],
                       {stdio: ['ignore', 'inherit', 'inherit']});
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'frustum-serve-chromium-'));
  let context;
  const close = async () => {
    if (context) await context.close();
    server.kill('SIGTERM');
    fs.rmSync(profile, {recursive: true, force: true});
  };
  try {
    await waitForServer(base);
    context = await launch(profile, viewport);
  } catch (e) {
    await close();
    throw e;
  }
  const page = context.pages()[0] ?? await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.on('pageerror', (e) => problems.push(e.message));
  return {course, base, link, page, context, problems, close};
}

export {run} from './flow.mjs';
