// Launching Debian's chromium headless through playwright-core, and building a
// report page from the template (shared by render.mjs and check_report.mjs).
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const here = path.dirname(fileURLToPath(import.meta.url));
export const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';

export async function launch() {
  if (!fs.existsSync(executablePath)) throw new Error(`chromium not found at ${executablePath} (apt-get install chromium)`);
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'denoising-chromium-'));
  // WebGL without a GPU: SwiftShader through ANGLE. Chromium 156 falls back to
  // it by itself too, but newer ones refuse the fallback unless
  // --enable-unsafe-swiftshader is given, so both are explicit.
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath,
    headless: true,
    viewport: { width: 1280, height: 1000 },
    deviceScaleFactor: 1,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-dev-shm-usage'],
  });
  const close = async () => {
    await context.close();
    fs.rmSync(userDataDir, { recursive: true, force: true });
  };
  return { context, close };
}

// substitutes the three placeholders of report_template.html
export function buildPage(data) {
  const template = fs.readFileSync(path.join(here, 'report_template.html'), 'utf8');
  const three = fs.readFileSync(path.join(here, 'node_modules/three/build/three.module.min.js'), 'utf8');
  const viewer = fs.readFileSync(path.join(here, 'viewer.js'), 'utf8');
  const parts = { '@REPORT_DATA@': JSON.stringify(data).replace(/</g, '\\u003c'), '@THREE_MODULE@': three, '@VIEWER_JS@': viewer };
  return template.replace(/@REPORT_DATA@|@THREE_MODULE@|@VIEWER_JS@/g, (m) => parts[m]);
}

// opens a page, waits for the viewer; returns the console errors seen
export async function openReport(context, file, hash) {
  const page = await context.newPage();
  const errors = [];
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(msg.text()); });
  page.on('pageerror', (err) => errors.push(String(err)));
  await page.goto('file://' + path.resolve(file) + (hash ? '#' + hash : ''));
  await page.waitForFunction(() => window.denoisingViewer && window.denoisingViewer.ready, null, { timeout: 60000 })
    .catch((e) => errors.push('viewer did not start: ' + e.message.split('\n')[0]));
  return { page, errors };
}
