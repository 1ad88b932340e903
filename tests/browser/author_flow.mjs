// An author at work in `frustum serve`'s authoring page, in Debian's chromium driven headless by
// playwright-core: opens a set in the editor, types a field the kind does not read and sees
// the error marked at its line, fixes it and moves the pixel, sees the key and the derivation
// follow, and saves (the file on disk is the text in the editor, the previous one kept).
// Screenshots go to OUT_DIR.
//   node author_flow.mjs FRUSTUM_BINARY WORK_DIR OUT_DIR
import fs from 'node:fs';
import path from 'node:path';
import {check, checks, run, startCourse} from './course_server.mjs';

const [frustum, work, out] = process.argv.slice(2);
const kSet = `title: {en: "Depth", ja: "奥行き", ru: "Глубина"}
problems:
  - id: zbuf
    kind: depth_at_pixel
    text:
      en: "Find the depth z at the pixel {pixel}."
      ja: "画素 {pixel} の奥行き z を求めよ。"
      ru: "Найдите глубину z в пикселе {pixel}."
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
      cross: [AC, AB]
    ask: [plane, z]
    samples:
      - {answers: {z: 8}, expect: right}
`;
const kPixelLine = 11;  // 1-based, "      pixel: [1, 1]"

// Waits for the preview after `count` previews have been shown.
async function previewAfter(page, count) {
  await page.waitForFunction((n) => Number(document.querySelector('main.author').dataset.previews ?? '0') > n,
                             count, {timeout: 30000});
  return Number(await page.locator('main.author').getAttribute('data-previews'));
}

async function main() {
  const {course, base, link, page, context, problems, close} = await startCourse({
    frustum, work, out, sets: {week1: kSet}, roster: ['alice'], instructors: ['carol'],
    viewport: {width: 1100, height: 1600}, serveArgs: ['--workers', '1']});
  const file = path.join(course, 'week1.yaml');
  try {
    // A student is refused the page.
    await page.goto(link.alice);
    const refused = await page.goto(`${base}/instructor/author/week1`);
    check(refused.status() === 403, 'a student is refused the authoring page: ' + refused.status());
    await context.clearCookies();

    // The instructor's page: the editor, and the first preview.
    await page.goto(link.carol);
    await page.goto(`${base}/instructor/author/week1`);
    await page.waitForSelector('.CodeMirror');
    let seen = await previewAfter(page, 0);
    const zbuf = page.locator('#preview [data-problem="zbuf"]');
    check((await zbuf.locator('.statement[data-lang="ja"]').innerText()).includes('画素 (1, 1) の奥行き z を求めよ。'),
          'the Japanese statement, filled: ' + await zbuf.locator('.statement[data-lang="ja"]').innerText());
    check(await zbuf.locator('.derivation .katex').count() > 3, 'the derivation is typeset');
    check(await zbuf.locator('dl.key [data-tex="8"]').count() === 1, 'the key says z = 8');
    check(await page.locator('#samples li.as-expected').count() === 1, 'the sample is graded as expected');
    check(await page.locator('#check .no-errors').count() === 1, 'no errors');

    // An error: a field depth_at_pixel does not read, typed at the end of the pixel's line.
    await page.evaluate((line) => {
      const cm = document.querySelector('.CodeMirror').CodeMirror;
      cm.focus();
      cm.setCursor({line: line - 1, ch: cm.getLine(line - 1).length});
    }, kPixelLine + 1);
    await page.keyboard.press('Enter');
    await page.keyboard.type('colour: red');
    seen = await previewAfter(page, seen);
    await page.waitForSelector(`#check ul.errors li[data-line="${kPixelLine + 2}"]`);
    const error = await page.locator('#check ul.errors li').first().innerText();
    check(error.includes('problems[0].given.colour'), 'the error names the field: ' + error);
    const marked = await page.evaluate(() => {
      const cm = document.querySelector('.CodeMirror').CodeMirror;
      const lines = [];
      cm.eachLine((h) => { if ((h.bgClass ?? '').includes('error-line')) lines.push(cm.getLineNumber(h) + 1); });
      return lines;
    });
    check(JSON.stringify(marked) === JSON.stringify([kPixelLine + 2]), 'the error is marked at its line: ' + JSON.stringify(marked));
    check(await page.locator('.CodeMirror .error-mark').count() >= 1, 'and at its column');
    await page.screenshot({path: path.join(out, '1-error.png'), fullPage: true});

    // The fix: the line removed, and the pixel moved to (1, 2): z is now 9.
    await page.keyboard.press('Control+D');  // CodeMirror: delete the line
    await page.evaluate((line) => {
      const cm = document.querySelector('.CodeMirror').CodeMirror;
      const text = cm.getLine(line - 1);
      cm.setCursor({line: line - 1, ch: text.indexOf('1]') + 1});
    }, kPixelLine);
    await page.keyboard.press('Backspace');
    await page.keyboard.type('2');
    await page.waitForFunction(() => document.querySelectorAll('#preview dl.key [data-tex="9"]').length === 1,
                               null, {timeout: 30000});
    check(await page.locator('#check .no-errors').count() === 1, 'the error is gone');
    check(await page.locator('.CodeMirror .error-line').count() === 0, 'and its mark');
    check((await zbuf.locator('.derivation').innerText()).includes('9'), 'the derivation follows the new pixel');
    check(await page.locator('#samples li.mismatch').count() === 1, 'the sample z = 8 is now graded wrong');
    check(await page.locator('.CodeMirror .sample-line').count() === 1, 'and marked at its line');
    await page.screenshot({path: path.join(out, '2-fixed.png'), fullPage: true});

    // Saving: with a sample graded otherwise, only "save with errors" writes the file.
    const edited = await page.evaluate(() => document.querySelector('.CodeMirror').CodeMirror.getValue());
    const notSaved = page.waitForResponse((r) => r.url().endsWith('/save'));
    await page.click('#save');
    check((await notSaved).status() === 422, 'refused while a sample disagrees');
    await page.waitForSelector('#status[data-state="error"]');
    check(fs.readFileSync(file, 'utf8') === kSet, 'not saved while a sample disagrees');
    const saved = page.waitForResponse((r) => r.url().endsWith('/save'));
    await page.click('#save-anyway');
    check((await saved).status() === 200, 'saved with errors when asked to');
    await page.waitForSelector('#status[data-state="saved"]');
    check(fs.readFileSync(file, 'utf8') === edited, 'the file on disk is the text in the editor');
    const kept = fs.readdirSync(path.join(course, '.frustum', 'history', 'week1'));
    check(kept.length === 1 && fs.readFileSync(path.join(course, '.frustum', 'history', 'week1', kept[0]), 'utf8') === kSet,
          'the previous version is kept');
    await page.screenshot({path: path.join(out, '3-saved.png'), fullPage: true});
    // The statuses the flow asked for (the student refused, the save refused) and the browser's
    // own favicon request are no script errors.
    const unexpected = problems.filter((p) => !/^Failed to load resource: .* status of (403|404|422) /.test(p));
    check(unexpected.length === 0, 'no script errors or CSP violations: ' + unexpected.join('; '));
    console.log(`author browser test: ${checks.count} checks passed`);
  } finally {
    await close();
  }
}

run(main);
