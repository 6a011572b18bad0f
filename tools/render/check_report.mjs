#!/usr/bin/env node
// Browser test of a comparison report (comparison_report.h): opens it in
// headless chromium and checks that
//   - it loads with no console error,
//   - every mesh canvas shows the mesh (enough non-background pixels),
//   - dragging one canvas turns every camera (linked cameras),
//   - the heat-map toggle recolours the meshes that have errors,
//   - the table shown and the JSON embedded in the page hold the numbers of
//     the CSV the writer put next to the page (FILE.csv for FILE.html),
//   - the mean of each mesh's per-face errors (the heat map) is its E_n.
// Exit status 0 if all hold, 1 otherwise (one line per failure on stderr).
//
// Usage: node check_report.mjs REPORT.html [--csv FILE.csv] [--min-pixels N]
import fs from 'node:fs';
import { launch, openReport } from './browser.mjs';

const args = process.argv.slice(2);
let html = null, csv = null, minPixels = 400;
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--csv') csv = args[++i];
  else if (args[i] === '--min-pixels') minPixels = parseInt(args[++i], 10);
  else html = args[i];
}
if (!html) {
  console.error('usage: node check_report.mjs REPORT.html [--csv FILE.csv] [--min-pixels N]');
  process.exit(2);
}
csv = csv || html.replace(/\.[^./]*$/, '') + '.csv';

const failures = [];
const fail = (msg) => failures.push(msg);

// the CSV the writer wrote: label,E_n,E_v,seconds
const rows = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((line) => {
  const [label, En, Ev, seconds] = line.split(',');
  const num = (s) => (s === '' ? null : Number(s));
  return { label, E_n: num(En), E_v: num(Ev), seconds: num(seconds) };
});
const shown = (x, kind) => (x === null ? '' : kind === 'E_v' ? x.toExponential(3) : kind === 'seconds' ? x.toFixed(2) : x.toFixed(3));

// per canvas: number of pixels that differ from the white background, and a checksum
const canvasStats = (page) => page.evaluate(() => [...document.querySelectorAll('#grid canvas')].map((c) => {
  const copy = document.createElement('canvas');
  copy.width = c.width;
  copy.height = c.height;
  const g = copy.getContext('2d');
  g.drawImage(c, 0, 0);
  const px = g.getImageData(0, 0, c.width, c.height).data;
  let count = 0, sum = 0;
  for (let i = 0; i < px.length; i += 4) {
    if (px[i] < 250 || px[i + 1] < 250 || px[i + 2] < 250) ++count;
    sum = (sum * 31 + px[i] + 3 * px[i + 1] + 7 * px[i + 2]) % 1000000007;
  }
  return { label: c.dataset.label, count, sum };
}));

const { context, close } = await launch();
let data = { meshes: [] };
try {
  const { page, errors } = await openReport(context, html);
  for (const e of errors) fail('console error: ' + e);

  const before = await canvasStats(page);
  if (before.length !== rows.length) fail(`${before.length} mesh canvases, ${rows.length} rows in ${csv}`);
  for (const s of before)
    if (s.count < minPixels) fail(`canvas "${s.label}" is blank (${s.count} non-background pixels < ${minPixels})`);

  // linked cameras: drag the first canvas, every canvas must change
  const first = await page.locator('#grid canvas').first().boundingBox();
  if (first) {
    await page.mouse.move(first.x + first.width / 2, first.y + first.height / 2);
    await page.mouse.down();
    await page.mouse.move(first.x + first.width / 2 + 60, first.y + first.height / 2 + 20, { steps: 5 });
    await page.mouse.up();
    const after = await canvasStats(page);
    after.forEach((s, i) => {
      if (before[i] && s.count >= minPixels && s.sum === before[i].sum) fail(`canvas "${s.label}" did not follow the camera`);
    });
  }

  // heat map: meshes with errors change colour
  data = await page.evaluate(() => JSON.parse(document.getElementById('report-data').textContent));
  const noHeat = await canvasStats(page);
  await page.locator('#heat').check().catch(() => {});
  const heat = await canvasStats(page);
  data.meshes.forEach((m, i) => {
    if (m.errors && heat[i] && heat[i].count >= minPixels && heat[i].sum === noHeat[i].sum)
      fail(`canvas "${m.label}": the heat map toggle changed nothing`);
  });

  // the heat map's per-face errors average to the table's E_n (eq. 12;
  // stored in hundredths of a degree, so within 0.01)
  const means = await page.evaluate(() => JSON.parse(document.getElementById('report-data').textContent).meshes.map((m) => {
    if (!m.errors) return null;
    const e = DenoisingViewer.decode(m.errors, Uint16Array);
    let sum = 0;
    for (const c of e) sum += c / 100;
    return e.length ? sum / e.length : null;
  }));
  means.forEach((mean, i) => {
    const En = rows[i] ? rows[i].E_n : null;
    if (mean !== null && En !== null && Math.abs(mean - En) > 0.01)
      fail(`mesh "${rows[i].label}": mean per-face error ${mean.toFixed(4)} degrees, E_n ${En}`);
  });

  // the table shown and the JSON embedded match the CSV
  const table = await page.evaluate(() => [...document.querySelectorAll('#error-table tbody tr')].map(
    (tr) => [...tr.cells].map((td) => td.textContent)));
  if (table.length !== rows.length) fail(`table shows ${table.length} rows, ${csv} has ${rows.length}`);
  rows.forEach((r, i) => {
    const cells = table[i] || [];
    if (cells[0] !== r.label) fail(`row ${i + 1}: label "${cells[0]}", expected "${r.label}"`);
    ['E_n', 'E_v', 'seconds'].forEach((kind, k) => {
      if (cells[k + 1] !== shown(r[kind], kind))
        fail(`row ${i + 1} (${r.label}) ${kind}: shown "${cells[k + 1]}", ${csv} says ${r[kind]}`);
      const j = data.table[i] ? data.table[i][kind] : undefined;
      if (j !== r[kind]) fail(`row ${i + 1} (${r.label}) ${kind}: embedded JSON ${j}, ${csv} says ${r[kind]}`);
    });
  });
} finally {
  await close();
}
if (failures.length) {
  for (const f of failures) console.error('check_report: ' + f);
  process.exit(1);
}
const withErrors = data.meshes.filter((m) => m.errors).length;
console.log(`check_report: ${html}: ${rows.length} meshes drawn, cameras linked, heat map recolours ${withErrors} ` +
            `mesh(es) with errors, table matches ${csv}`);
