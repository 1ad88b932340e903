// What each browser flow starts with: a course directory, its links, `frustum serve` on a free
// port, and Debian's chromium driven headless by playwright-core, its script errors collected.
import {spawn, execFileSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {freePort, launch, waitForServer} from './flow.mjs';

// The plane method on one triangle, the set the student's and the instructor's flows serve.
export const kPlaneMethodSet = `title: "Depth by the plane method"
problems:
  - id: zbuf
    kind: depth_at_pixel
    text: "Find the plane of triangle ABC and the depth z at the pixel."
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [normal, plane, z]
`;

// sets: {name: yaml}; roster: students' ids; instructors: instructors' ids (instructors.csv).
// Returns {course, base, link (id → url), role (id → student or instructor, from the links
// file), page, problems (script errors and CSP violations), close()}.
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
  const rows = fs.readFileSync(links, 'utf8').trim().split('\n');
  if (rows[0] !== 'student,url,role') throw new Error('the links file has no role column: ' + rows[0]);
  const link = {}, role = {};
  for (const row of rows.slice(1)) {
    const [id, url, r] = row.split(',');
    link[id] = url;
    role[id] = r;
  }
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
  return {course, base, link, role, page, context, problems, close};
}

export {check, checks, run} from './flow.mjs';
