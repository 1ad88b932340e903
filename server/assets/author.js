// The authoring page, better with JavaScript (it works without: a textarea and a save button):
// CodeMirror's YAML editor, and as the author types, check's errors marked at their line and
// column, the sample answers graded otherwise than expected, and each problem as students read
// it — statement in each language, givens, answer key and derivation typeset, figure.
import {debounce, typeset} from './page.js';

const csrf = document.querySelector('meta[name="csrf"]')?.content ?? '';
const main = document.querySelector('main.author');
const form = document.getElementById('author-form');
const textarea = document.getElementById('yaml');
const status = document.getElementById('status');
const words = JSON.parse(main.dataset.words ?? '{}');
const say = (key) => words[key] ?? key;

let editor = null;
if (typeof CodeMirror !== 'undefined') {
  editor = CodeMirror.fromTextArea(textarea, {mode: 'yaml', lineNumbers: true, indentUnit: 2,
                                              viewportMargin: Infinity});
}
const text = () => (editor ? editor.getValue() : textarea.value);

function typesetAll(root) {
  for (const element of root.querySelectorAll('[data-tex]')) {
    if (typeset(element, element.dataset.tex, element.classList.contains('display'))) {
      element.dataset.typeset = 'yes';
    }
  }
}

function element(tag, attributes = {}, ...children) {
  const e = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
  e.append(...children);
  return e;
}

let marks = [];
// Each item {line, column, message} marked in the editor: its line's background (`lineClass`)
// and its text from the column on.
function markLines(items) {
  if (!editor) return;
  for (const clear of marks) clear();
  marks = [];
  for (const item of items) {
    if (!(item.line > 0) || item.line > editor.lineCount()) continue;
    const line = item.line - 1;
    const handle = editor.addLineClass(line, 'background', item.lineClass);
    const length = editor.getLine(line).length;
    const from = Math.min(Math.max(0, (item.column || 1) - 1), length);
    const mark = editor.markText({line, ch: from}, {line, ch: length},
                                 {className: 'error-mark', attributes: {title: item.message}});
    marks.push(() => {
      editor.removeLineClass(handle, 'background', item.lineClass);
      mark.clear();
    });
  }
}

function located(item) {
  return element('li', {'data-line': String(item.line ?? 0), class: 'located'},
                 `${say('line')} ${item.line ?? '?'}:${item.column ?? ''} `,
                 element('code', {}, item.field ?? ''), `: ${item.message ?? ''}`);
}

function showCheck(result) {
  const check = document.getElementById('check');
  check.replaceChildren(element('h2', {}, say('errors')));
  const errors = result.errors ?? [];
  if (errors.length === 0) check.append(element('p', {class: 'no-errors'}, say('noErrors')));
  else check.append(element('ul', {class: 'errors'}, ...errors.map(located)));
  if ((result.warnings ?? []).length > 0) {
    check.append(element('h2', {}, say('warnings')),
                 element('ul', {class: 'warnings'}, ...result.warnings.map(located)));
  }
  const samples = document.getElementById('samples');
  samples.replaceChildren();
  if ((result.samples ?? []).length > 0) {
    samples.append(element('h2', {}, say('samples')));
    const list = element('ul');
    for (const s of result.samples) {
      const item = element('li', {class: s.ok ? 'as-expected' : 'mismatch', 'data-line': String(s.line)},
                           `${say('line')} ${s.line}: `, element('code', {}, s.field),
                           ` — ${say('expected')} ${s.expected}, ${say('graded')} ${s.verdict}`);
      if (!s.ok) item.append(element('div', {}, s.message));
      list.append(item);
    }
    samples.append(list);
  }
  markLines([...errors.map((e) => ({...e, lineClass: 'error-line'})),
             ...(result.samples ?? []).filter((s) => !s.ok)
                 .map((s) => ({...s, column: 1, lineClass: 'sample-line'}))]);
}

function problemPreview(p) {
  const section = element('section', {class: 'problem-preview', 'data-problem': p.id},
                          element('h3', {}, `${p.id} (${p.kind})`));
  if (p.error) {
    section.append(element('p', {class: 'error'}, p.error));
    return section;
  }
  section.append(element('h4', {}, say('statement')));
  for (const t of p.texts ?? []) {
    section.append(element('p', {class: 'statement', lang: t.lang, 'data-lang': t.lang},
                           element('span', {class: 'lang'}, t.lang), t.text));
  }
  if ((p.given ?? []).length > 0) {
    section.append(element('h4', {}, say('given')));
    const list = element('dl', {class: 'given'});
    for (const g of p.given) {
      list.append(element('dt', {}, g.name),
                  element('dd', {}, element('span', {class: 'tex', 'data-tex': g.tex}, g.plain)));
    }
    section.append(list);
  }
  const key = element('dl', {class: 'key'});
  // The key's and the derivation's HTML are made by the server, every text escaped there.
  for (const k of p.key ?? []) {
    const value = element('dd');
    value.innerHTML = k.html;
    key.append(element('dt', {}, element('code', {}, k.name)), value);
  }
  section.append(element('h4', {}, say('key')), key);
  const derivation = element('div', {class: 'derivation'});
  derivation.innerHTML = p.derivation_html ?? '';
  section.append(element('h4', {}, say('derivation')), derivation);
  if (p.figure_svg) {
    section.append(element('figure', {}, element('img', {
      alt: say('figure'), src: 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(p.figure_svg)})));
  }
  if (p.figure_png) {  // the render kind's image, as `frustum render` draws it
    section.append(element('figure', {}, element('img', {alt: say('figure'), src: p.figure_png})));
  }
  typesetAll(section);
  return section;
}

function showPreview(result) {
  const preview = document.getElementById('preview');
  const parts = [];
  if (result.student_error) parts.push(element('p', {class: 'error'}, `${result.student}: ${result.student_error}`));
  for (const p of result.problems ?? []) parts.push(problemPreview(p));
  preview.replaceChildren(...parts);
}

function setStatus(message, state) {
  status.textContent = message;
  status.dataset.state = state;
}

async function post(action, fields) {
  const body = new URLSearchParams({csrf, ...fields});
  const response = await fetch(`/instructor/author/${encodeURIComponent(main.dataset.set)}/${action}`, {
    method: 'POST', body, credentials: 'same-origin', headers: {Accept: 'application/json'}});
  let json = null;
  try {
    json = await response.json();
  } catch {
    json = null;
  }
  return {status: response.status, json};
}

let asked = 0;
async function preview() {
  const mine = ++asked;
  setStatus(say('checking'), 'checking');
  const student = document.getElementById('student').value.trim();
  let reply;
  try {
    reply = await post('preview', {yaml: text(), student});
  } catch {
    reply = {status: 0, json: null};
  }
  if (mine !== asked) return;  // a newer text is on its way
  if (reply.status !== 200 || !reply.json) {
    setStatus(reply.json?.message ?? say('previewFailed'), 'error');
    return;
  }
  showCheck(reply.json);
  showPreview(reply.json);
  setStatus('', reply.json.ok ? 'ok' : 'error');
  main.dataset.previews = String(Number(main.dataset.previews ?? '0') + 1);
}

const later = debounce(preview, 400);
if (editor) editor.on('change', later);
else textarea.addEventListener('input', later);
document.getElementById('student').addEventListener('change', later);

form.addEventListener('submit', async (event) => {
  event.preventDefault();
  const force = event.submitter?.value === '1' ? '1' : '0';
  const base = form.elements.base.value;
  const reply = await post('save', {yaml: text(), base, force});
  if (reply.status === 200 && reply.json?.saved) {
    form.elements.base.value = reply.json.version;
    setStatus(reply.json.message, 'saved');
    main.dataset.saved = reply.json.version;
  } else {
    setStatus(reply.json?.message ?? say('previewFailed'), 'error');
    if (reply.json?.check) showCheck(reply.json.check);
  }
});

preview();
