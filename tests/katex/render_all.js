// Renders every LaTeX string of a JSON array with KaTeX in strict mode (Debian's libjs-katex):
// any parse error, and any strict-mode warning (unknown Unicode, LaTeX-incompatible input), is
// a failure. Usage: node render_all.js KATEX_JS STRINGS_JSON. Prints one line per failure and
// exits 1 when there is any.
'use strict';
const fs = require('fs');
const katex = require(process.argv[2]);
const strings = JSON.parse(fs.readFileSync(process.argv[3], 'utf8'));
let failed = 0;
for (const tex of strings) {
  try {
    katex.renderToString(tex, {
      displayMode: true,
      throwOnError: true,
      strict: (code, message) => { throw new Error('strict: ' + code + ': ' + message); },
    });
  } catch (e) {
    ++failed;
    console.log(JSON.stringify({latex: tex, error: String(e.message || e)}));
  }
}
console.log(`${strings.length} formulas, ${failed} failed`);
process.exit(failed ? 1 : 0);
