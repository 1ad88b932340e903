// The student's page, better with JavaScript (it works without): formulas typeset by KaTeX —
// only LaTeX the server produced, in strict mode with trust off — each answer's reading shown
// as it is typed (the grader's own parser, run by the server; never whether it is right), and
// drafts saved as the student types.
const csrf = document.querySelector('meta[name="csrf"]')?.content ?? '';

export function typeset(element, tex, display) {
  if (typeof katex === 'undefined') return false;
  try {
    katex.render(tex, element, {displayMode: display, throwOnError: true, strict: 'error', trust: false});
    return true;
  } catch {
    return false;
  }
}

export function debounce(run, ms) {
  let timer = 0;
  return () => {
    clearTimeout(timer);
    timer = setTimeout(run, ms);
  };
}

async function post(url, fields) {
  const body = new URLSearchParams({csrf, ...fields});
  try {
    const response = await fetch(url, {method: 'POST', body, credentials: 'same-origin'});
    if (!response.ok) return null;
    return await response.json();
  } catch {
    return null;
  }
}

function showReading(output, result) {
  output.textContent = '';
  delete output.dataset.state;
  if (!result || result.empty) return;
  const label = document.createElement('span');
  label.className = 'label';
  label.textContent = result.label + ': ';
  const value = document.createElement('span');
  if (result.ok) {
    value.className = 'reading';
    if (!typeset(value, result.tex, false)) value.textContent = result.text;
  } else {
    value.className = 'error';
    value.textContent = result.error;
  }
  output.append(label, value);
  output.dataset.state = result.ok ? 'read' : 'error';
}

function watchInput(form, input) {
  const fields = () => ({set: form.dataset.set, problem: form.dataset.problem,
                         answer: input.dataset.answer, text: input.value});
  const output = form.querySelector(`output[data-for="${CSS.escape(input.dataset.answer)}"]`);
  const preview = debounce(async () => showReading(output, await post('/api/preview', fields())), 200);
  const draft = debounce(async () => {
    const saved = await post('/api/draft', fields());
    if (saved?.ok) input.dataset.saved = input.value;
  }, 600);
  input.addEventListener('input', () => {
    preview();
    draft();
  });
  if (input.value) preview();
}

for (const element of document.querySelectorAll('[data-tex]')) {
  if (typeset(element, element.dataset.tex, element.classList.contains('display'))) {
    element.dataset.typeset = 'yes';
  }
}
for (const form of document.querySelectorAll('form.answers')) {
  for (const input of form.querySelectorAll('input[data-answer]')) watchInput(form, input);
}
document.body.dataset.ready = 'yes';
