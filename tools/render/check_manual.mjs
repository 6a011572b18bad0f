#!/usr/bin/env node
// Browser test of the Doxygen manual: opens each page given in headless
// chromium, lets MathJax typeset it, and checks that the text shown holds no
// LaTeX source (no "\[", "\(" nor "\frac") and that formulas were typeset.
// Exit status 0 if every page passes, 1 otherwise (one line per failure on
// stderr).
//
// Usage: node check_manual.mjs PAGE.html...
import path from 'node:path';
import { launch } from './browser.mjs';

const pages = process.argv.slice(2);
if (pages.length === 0) {
  console.error('usage: node check_manual.mjs PAGE.html...');
  process.exit(2);
}
const failures = [];
const { context, close } = await launch();
try {
  for (const file of pages) {
    const name = path.basename(file);
    const page = await context.newPage();
    await page.goto('file://' + path.resolve(file));
    // MathJax 2: done when its queue is empty after the start-up typesetting
    const typeset = await page.waitForFunction(() => window.MathJax && window.MathJax.isReady &&
        window.MathJax.Hub.queue.pending === 0 && window.MathJax.Hub.queue.running === 0, null, { timeout: 30000 })
      .then(() => true, () => false);
    if (!typeset) failures.push(`${name}: MathJax did not load or did not finish`);
    const { text, rendered } = await page.evaluate(() => ({
      text: document.body.innerText,
      rendered: document.querySelectorAll('.MathJax, .MathJax_Display').length,
    }));
    for (const raw of ['\\[', '\\(', '\\frac']) {
      const at = text.indexOf(raw);
      if (at >= 0) failures.push(`${name}: LaTeX source shown: "${text.slice(at, at + 40).replace(/\s+/g, ' ')}"`);
    }
    if (rendered === 0) failures.push(`${name}: no typeset formula`);
    else console.log(`${name}: ${rendered} formulas typeset, no LaTeX source shown`);
    await page.close();
  }
} finally {
  await close();
}
for (const f of failures) console.error('check_manual: ' + f);
process.exit(failures.length ? 1 : 0);
