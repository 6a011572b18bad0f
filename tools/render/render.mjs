#!/usr/bin/env node
// Renders denoising results to PNG with three.js in headless chromium.
//
//   node render.mjs REPORT.html --out FILE.png [--tile 300] [--cols 3] [--heat]
//       a contact sheet of every mesh of a comparison report (written by
//       comparison_report.h), each tile flat shaded from the report's camera
//   node render.mjs --mesh MESH.off [--errors ERRORS.txt] --out FILE.png [--tile 400] [--heat] [--heat-max DEG]
//       one mesh (OFF; polygons are fanned into triangles); ERRORS.txt: one
//       per-face error (degrees) a line, drawn full red from DEG (default 15)
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launch, buildPage, openReport } from './browser.mjs';

function usage(msg) {
  if (msg) console.error('render.mjs: ' + msg);
  console.error('usage: node render.mjs REPORT.html --out FILE.png [--tile N] [--cols N] [--heat]\n' +
                '       node render.mjs --mesh MESH.off [--errors FILE] --out FILE.png [--tile N] [--heat] [--heat-max DEG]');
  process.exit(2);
}

const opt = { tile: 300, cols: 0, heat: false, heatMax: 15 };
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  if (a === '--out') opt.out = args[++i];
  else if (a === '--tile') opt.tile = parseInt(args[++i], 10);
  else if (a === '--cols') opt.cols = parseInt(args[++i], 10);
  else if (a === '--heat') opt.heat = true;
  else if (a === '--heat-max') opt.heatMax = Number(args[++i]);
  else if (a === '--mesh') opt.mesh = args[++i];
  else if (a === '--errors') opt.errors = args[++i];
  else if (a.startsWith('--')) usage('unknown option ' + a);
  else opt.report = a;
}
if (!opt.out || (!opt.report === !opt.mesh)) usage();
if (!(opt.tile > 0) || !(opt.heatMax > 0)) usage('--tile and --heat-max must be positive');

function readOff(file) {
  const tokens = fs.readFileSync(file, 'utf8').replace(/#[^\n]*/g, ' ').split(/\s+/).filter((s) => s);
  if (!/^C?N?OFF$/.test(tokens[0])) throw new Error(file + ': not an OFF file');
  const nv = +tokens[1], nf = +tokens[2];
  let k = 4;
  const pos = new Float32Array(3 * nv);
  for (let i = 0; i < 3 * nv; ++i) pos[i] = +tokens[k++];
  const tri = [];
  for (let f = 0; f < nf; ++f) {
    const n = +tokens[k++];
    const face = tokens.slice(k, k + n).map(Number);
    k += n;
    for (let j = 1; j + 1 < n; ++j) tri.push(face[0], face[j], face[j + 1]);
  }
  return { pos, tri: Uint32Array.from(tri) };
}
const b64 = (typed) => Buffer.from(typed.buffer, typed.byteOffset, typed.byteLength).toString('base64');

let file = opt.report;
let tmp = null;
if (opt.mesh) {
  const { pos, tri } = readOff(opt.mesh);
  let errors = null;
  if (opt.errors) {
    errors = Uint16Array.from(fs.readFileSync(opt.errors, 'utf8').split(/\s+/).filter((s) => s).map((x) => Math.min(65535, Math.round(Number(x) * 100))));
    if (errors.length !== tri.length / 3) throw new Error(`${opt.errors}: ${errors.length} values for ${tri.length / 3} faces`);
  }
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'denoising-render-'));
  file = path.join(tmp, 'mesh.html');
  fs.writeFileSync(file, buildPage({
    title: path.basename(opt.mesh), heatMax: opt.heatMax, faceLists: [b64(tri)],
    meshes: [{ label: '', positions: b64(pos), faces: 0, errors: errors ? b64(errors) : null }], table: [],
  }));
  opt.cols = 1;
}

const { context, close } = await launch();
try {
  const hash = `tile=${opt.tile}&static=1` + (opt.cols ? `&cols=${opt.cols}` : '') + (opt.heat ? '&heat=1' : '');
  const { page, errors } = await openReport(context, file, hash);
  if (errors.length) throw new Error('page errors: ' + errors.join(' | '));
  await page.locator('#grid').screenshot({ path: opt.out });
  console.log('wrote ' + opt.out);
} finally {
  await close();
  if (tmp) fs.rmSync(tmp, { recursive: true, force: true });
}
