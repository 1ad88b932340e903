// A student's visit to `frustum serve`, in Debian's chromium driven headless by playwright-core:
// opens their link, types a wrong answer and sees how it is read, submits, sees the named
// mistake and the carried credit, reloads and finds the draft and the result kept, and is
// refused another student's submission. Screenshots go to OUT_DIR.
//   node serve_flow.mjs FRUSTUM_BINARY WORK_DIR OUT_DIR
import path from 'node:path';
import {check, checks, kPlaneMethodSet, run, startCourse} from './course_server.mjs';

const [frustum, work, out] = process.argv.slice(2);
const kSet = kPlaneMethodSet + `  - id: sort
    kind: depth_sort
    text: "Two polygons that cross each other."
    given:
      polygons:
        - [[-2, -1, -6], [2, -1, -6], [2, 1, -6], [-2, 1, -6]]
        - [[-1, -2, -8], [1, -2, -8], [1, 2, -4], [-1, 2, -4]]
      eye: [0, 0, 0]
`;

// Bob submits through plain HTTP (his own session), so that Alice has his submission's URL.
async function bobSubmits(link, base) {
  const start = await fetch(link, {redirect: 'manual'});
  const cookie = start.headers.get('set-cookie').split(';')[0];
  const page = await (await fetch(base + '/set/week1', {headers: {cookie}})).text();
  const csrf = page.match(/name="csrf" content="([0-9a-f]+)"/)[1];
  const body = new URLSearchParams({csrf, problem: 'zbuf', 'a.z': '8'});
  const r = await fetch(base + '/set/week1/submit', {method: 'POST', body, headers: {cookie, accept: 'application/json'}});
  return (await r.json()).id;
}

async function untilGraded(page, problem = '#p-zbuf') {
  for (let i = 0; i < 60; ++i) {
    if (await page.locator(problem + ' .submission[data-state="graded"]').count()) return;
    await new Promise((r) => setTimeout(r, 500));
    await page.reload();
  }
  throw new Error('the submission was not graded');
}

async function main() {
  const {base, link, page, problems, close} = await startCourse({
    frustum, work, out, sets: {week1: kSet}, roster: ['alice', 'bob'],
    viewport: {width: 1000, height: 1400}});
  try {
    // The link: a session cookie, and the token gone from the address.
    await page.goto(link.alice);
    check(page.url() === base + '/', 'the token is removed from the URL: ' + page.url());
    await page.click('a[href="/set/week1"]');
    await page.waitForSelector('body[data-ready="yes"]');
    check(await page.locator('#p-zbuf dl.given [data-typeset="yes"] .katex').count() === 3, 'the givens are typeset');
    check(await page.locator('#p-sort figure img').count() === 0, 'no figure before feedback (it shows the answers)');
    await page.screenshot({path: path.join(out, '1-set.png'), fullPage: true});

    // Typing: how each answer is read, never whether it is right.
    const form = page.locator('form[data-problem="zbuf"]');
    await form.locator('input[name="a.normal"]').fill('(1, 1, -1)');
    await form.locator('input[name="a.plane"]').fill('x + y - z = 6');
    await form.locator('input[name="a.z"]').fill('8++');
    const plane = form.locator('output[data-for="plane"]');
    await page.waitForSelector('output[data-for="plane"][data-state="read"] .katex');
    check((await plane.innerText()).includes('Read as'), 'the plane is read: ' + await plane.innerText());
    await page.waitForSelector('output[data-for="z"][data-state="error"]');
    const zError = await form.locator('output[data-for="z"]').innerText();
    check(zError.includes('8++') && zError.includes('Cannot be read'), 'the parse error is shown: ' + zError);
    check(!/correct|incorrect|wrong/i.test(await plane.innerText()), 'the preview never judges');
    await page.screenshot({path: path.join(out, '2-preview.png'), fullPage: true});
    const drafted = page.waitForResponse((r) => r.url().endsWith('/api/draft') && r.request().postData().includes('text=-4'));
    await form.locator('input[name="a.z"]').fill('-4');
    await drafted;

    // Submitting: the named mistake and the credit carried from the student's own plane.
    await Promise.all([page.waitForNavigation(), form.locator('button[type="submit"]').click()]);
    check(page.url() === base + '/set/week1#p-zbuf', 'back on the set after submitting: ' + page.url() + ' ' + (await page.innerText('body')).slice(0, 200));
    await untilGraded(page);
    const result = await page.locator('#p-zbuf .submission').innerText();
    check(result.includes('constant on the wrong side'), 'the named mistake: ' + result);
    check(result.includes('Where it goes wrong'), 'the step where it happens');
    check(result.includes('Credit carried from your earlier answers') && result.includes('x + y - z = 6'), 'carried credit with the plane it used');
    check(result.includes('1.5 / 3'), 'the score');
    await page.locator('details.derivation').first().evaluate((d) => { d.open = true; });
    // The depth-sort problem's figure comes with its feedback.
    const sort = page.locator('form[data-problem="sort"]');
    await sort.locator('input[name="a.order"]').fill('1, 0');
    await Promise.all([page.waitForNavigation(), sort.locator('button[type="submit"]').click()]);
    await untilGraded(page, '#p-sort');
    const figure = page.locator('#p-sort figure img');
    await figure.scrollIntoViewIfNeeded();
    check(await figure.evaluate((i) => i.complete && i.naturalWidth > 0), 'the figure is shown with the feedback');
    await page.screenshot({path: path.join(out, '3-result.png'), fullPage: true});

    // A draft typed after submitting, and a reload: both kept.
    const saved = page.waitForResponse((r) => r.url().endsWith('/api/draft'));
    await page.locator('form[data-problem="zbuf"] input[name="a.normal"]').fill('(2, 2, -2)');
    await saved;
    await page.reload();
    check(await page.locator('input[name="a.normal"]').inputValue() === '(2, 2, -2)', 'the draft is kept');
    check(await page.locator('input[name="a.z"]').inputValue() === '-4', 'the submitted answer is kept');
    check((await page.locator('#p-zbuf .submission').innerText()).includes('constant on the wrong side'), 'the result is kept');
    await page.screenshot({path: path.join(out, '4-reloaded.png'), fullPage: true});

    // Another student's submission: refused.
    const bobs = await bobSubmits(link.bob, base);
    const refused = await page.goto(`${base}/set/week1/submission/${bobs}`);
    check(refused.status() === 404, 'another student\'s submission is refused: ' + refused.status());
    check((await page.innerText('body')).includes('Not found'), 'the refusal page says so');
    const own = await page.goto(`${base}/set/week1/submission/1`);
    check(own.status() === 200, 'the student\'s own submission opens');
    await page.goto(`${base}/set/week1/submission/${bobs}`);
    await page.screenshot({path: path.join(out, '5-refused.png'), fullPage: true});
    check(problems.filter((p) => !p.includes('404')).length === 0, 'no script errors or CSP violations: ' + problems.join('; '));
    console.log(`serve browser test: ${checks.count} checks passed`);
  } finally {
    await close();
  }
}

run(main);
