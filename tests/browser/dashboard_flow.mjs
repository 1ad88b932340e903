// An instructor's view of a class in `frustum serve`, in Debian's chromium driven headless by
// playwright-core: opens their link, watches the class at a glance while STUDENTS students sign
// in and submit over plain HTTP (the page updates itself through server-sent events, never
// reloaded), reads the counts and the most frequent mistake, opens one student's submissions,
// then fixes the key in the set file, runs a regrade's dry run and applies it. A student is
// refused the instructor's pages. Screenshots go to OUT_DIR.
//   node dashboard_flow.mjs FRUSTUM_BINARY WORK_DIR OUT_DIR [STUDENTS]
import fs from 'node:fs';
import path from 'node:path';
import {check, checks, kPlaneMethodSet, run, startCourse} from './course_server.mjs';

const [frustum, work, out, studentsArg] = process.argv.slice(2);
const kStudents = Number(studentsArg ?? 200);
// What the class writes: every third student right, every third the named mistake (the plane's
// constant on the wrong side), every third an unreadable z.
const kAnswers = [
  {'a.normal': '(1, 1, -1)', 'a.plane': 'x + y - z = -6', 'a.z': '8'},
  {'a.normal': '(1, 1, -1)', 'a.plane': 'x + y - z = 6', 'a.z': '-4'},
  {'a.z': '8++'},
];

async function signIn(link) {
  const start = await fetch(link, {redirect: 'manual'});
  return start.headers.get('set-cookie').split(';')[0];
}

// One student: their link, their set page (for the CSRF token), one submission.
async function studentSubmits(link, base, answers) {
  const cookie = await signIn(link);
  const page = await (await fetch(base + '/set/week1', {headers: {cookie}})).text();
  const csrf = page.match(/name="csrf" content="([0-9a-f]+)"/)[1];
  const body = new URLSearchParams({csrf, problem: 'zbuf', ...answers});
  for (let tries = 0; tries < 20; ++tries) {
    const r = await fetch(base + '/set/week1/submit', {method: 'POST', body, headers: {cookie, accept: 'application/json'}});
    if (r.status === 202) return;
    await new Promise((res) => setTimeout(res, 200));  // 429 or 503: again
  }
  throw new Error('a submission was not accepted');
}

// The counts table's row for the problem: [submitted, right, partly, wrong, unreadable].
async function problemCounts(page) {
  const cells = await page.locator('table.counts tr.problem td').allInnerTexts();
  return cells.slice(2, 7).map(Number);
}

async function main() {
  const students = Array.from({length: kStudents}, (_, i) => `s${String(i + 1).padStart(3, '0')}`);
  const {course, base, link, role, page, problems, close} = await startCourse({
    frustum, work, out, sets: {week1: kPlaneMethodSet}, roster: students, instructors: ['prof'],
    viewport: {width: 1200, height: 1400}, serveArgs: ['--workers', '2', '--submit-rate', '50']});
  try {
    check(role.prof === 'instructor' && role.s001 === 'student', 'roles in the links file');
    // A student is refused the instructor's pages.
    const studentCookie = await signIn(link.s001);
    const refused = await fetch(base + '/instructor/set/week1', {headers: {cookie: studentCookie}});
    check(refused.status === 403, 'a student is refused /instructor/: ' + refused.status);

    page.on('response', (r) => { if (r.status() >= 400) problems.push(r.status() + ' ' + r.url()); });

    await page.goto(link.prof);
    check(page.url() === base + '/instructor/', 'the instructor lands on /instructor/: ' + page.url());
    await page.click('a[href="/instructor/set/week1"]');
    await page.waitForSelector('main[data-events]');
    check((await problemCounts(page))[0] === 0, 'nobody has submitted yet');
    await page.screenshot({path: path.join(out, '1-empty.png'), fullPage: true});

    // The class submits, twenty at a time; the page is never reloaded.
    const navigations = [];
    page.on('framenavigated', (f) => { if (f === page.mainFrame()) navigations.push(f.url()); });
    for (let i = 0; i < students.length; i += 20)
      await Promise.all(students.slice(i, i + 20).map((s, j) => studentSubmits(link[s], base, kAnswers[(i + j) % 3])));
    const third = (k) => students.filter((_, i) => i % 3 === k).length;
    let counts = [];
    for (let i = 0; i < 240; ++i) {
      counts = await problemCounts(page);
      if (counts[0] === kStudents && counts[1] + counts[2] + counts[3] + counts[4] === kStudents) break;
      await new Promise((r) => setTimeout(r, 500));
    }
    check(counts[0] === kStudents, `the live page counts every submission: ${counts}`);
    check(counts[1] === third(0), `right: ${counts[1]} of ${third(0)}`);
    check(counts[2] === third(1), `partly right: ${counts[2]} of ${third(1)}`);
    check(counts[4] === third(2), `unreadable: ${counts[4]} of ${third(2)}`);
    check(navigations.length === 0, 'updated without a reload: ' + navigations.join(' '));
    check(Number(await page.locator('main').getAttribute('data-updated')) > 0, 'the module swapped the page in');
    const mistake = await page.locator('table.mistakes tbody tr').first().innerText();
    check(mistake.includes('constant on the wrong side') && mistake.includes(String(third(1))),
          'the most frequent mistake with its students: ' + mistake);
    await page.screenshot({path: path.join(out, '2-class.png'), fullPage: true});

    // Sorted by score, highest first: a right student on top.
    await page.goto(base + '/instructor/set/week1?sort=score&desc=1');
    check((await page.locator('table.gradebook tbody tr').first().innerText()).includes('3 / 3'), 'sorted by score');

    // One student's submission: the answers as written, the feedback they saw, the history.
    await page.goto(base + '/instructor/set/week1/student/s002');
    const drill = await page.innerText('main');
    check(drill.includes('x + y - z = 6') && drill.includes('constant on the wrong side'), 'the drill-down: ' + drill.slice(0, 300));
    await page.screenshot({path: path.join(out, '3-student.png'), fullPage: true});

    // The key changes (the pixel moves: z is 7 now); the dry run lists who changes, then apply.
    fs.writeFileSync(path.join(course, 'week1.yaml'), kPlaneMethodSet.replace('pixel: [1, 1]', 'pixel: [1, 0]'));
    await page.goto(base + '/instructor/set/week1');
    await Promise.all([page.waitForNavigation(), page.click('#regrade button[type="submit"]')]);
    const changes = await page.locator('table.changes tbody tr').count();
    check(changes === third(0) + third(1), `the dry run lists ${changes} students (right ones lose z, mistaken ones' carried z)`);
    const why = await page.locator('table.changes tbody tr[data-student="s001"]').innerText();
    check(why.includes('z: Correct → Incorrect') && why.includes('3') && why.includes('2'), 'why: z is no longer right: ' + why);
    const carried = await page.locator('table.changes tbody tr[data-student="s002"]').innerText();
    check(carried.includes('z: Partly correct → Incorrect'), 'why: z no longer follows from the plane: ' + carried);
    await page.screenshot({path: path.join(out, '4-dry-run.png'), fullPage: true});
    await Promise.all([page.waitForNavigation(), page.click('main form button[type="submit"]')]);
    const applied = await page.innerText('main');
    check(applied.includes('Regrade applied'), 'applied: ' + applied);
    await page.screenshot({path: path.join(out, '5-applied.png'), fullPage: true});
    await page.goto(base + '/instructor/set/week1/student/s001');
    const history = await page.locator('table.history tbody tr').count();
    check(history === 2, 'the grade keeps its history: ' + history + ' rows');
    check(problems.filter((p) => !p.includes('404')).length === 0, 'no script errors or CSP violations: ' + problems.join('; '));
    console.log(`dashboard browser test: ${checks.count} checks passed`);
  } finally {
    await close();
  }
}

run(main);
