// Browser test of the HTML report of `epviz check --report`: a small job is
// checked against goldens of a changed colour, and the report must show the
// golden, actual and diff images of each failing frame in headless Chromium.
//
//   node tests/e2e/check_report.mjs path/to/epviz path/to/source [screenshot.png]
//
// Exit 0: passed; 1: failed (the reason is printed); 77: skipped (no Chromium
// or no node_modules: see the SKIP line).
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const SKIP = 77;
const HERE = path.dirname(fileURLToPath(import.meta.url));
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

const [binary, source, screenshotPath] = process.argv.slice(2);
if (!binary || !source) {
  console.log('usage: node check_report.mjs path/to/epviz path/to/source [screenshot.png]');
  process.exit(2);
}

function skip(reason) {
  console.log(`SKIP: ${reason}`);
  process.exit(SKIP);
}
function fail(message) {
  console.log(`FAIL: ${message}`);
  process.exitCode = 1;
  throw new Error(message);
}

if (Number(process.versions.node.split('.')[0]) < 20) skip(`Node.js ${process.versions.node} is too old for playwright-core`);
if (!fs.existsSync(CHROMIUM)) skip(`${CHROMIUM} not found (install Debian's chromium: scripts/setup.sh)`);
if (!fs.existsSync(path.join(HERE, 'node_modules', 'playwright-core'))) {
  skip(`${path.join(HERE, 'node_modules', 'playwright-core')} missing (run: cd tests/e2e && npm ci)`);
}
let playwright;
try {
  playwright = await import('playwright-core');
} catch (e) {
  skip(`playwright-core does not load: ${e.message}`);
}

// A report with failing frames: goldens of the Kovalevskaya job at 160x120,
// then the body's colour changed.
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'epviz-check-report-'));
function epviz(args, expect) {
  const r = spawnSync(path.resolve(binary), args, { encoding: 'utf8', timeout: 120000 });
  if (r.status !== expect) fail(`epviz ${args.join(' ')} exited ${r.status} (expected ${expect}):\n${r.stdout}${r.stderr}`);
  return r.stdout;
}

let browser = null;
try {
  const job = JSON.parse(fs.readFileSync(path.join(source, 'render_jobs', 'kovalevskaya.json'), 'utf8'));
  Object.assign(job, { width: 160, height: 120 });
  const jobFile = path.join(work, 'kov.json');
  fs.writeFileSync(jobFile, JSON.stringify(job));
  epviz(['check', jobFile, '--frames', '0,134', '--update'], 0);
  job.colours = { body: '#5c9ecc' };
  fs.writeFileSync(jobFile, JSON.stringify(job));
  const report = path.join(work, 'report');
  const out = epviz(['check', jobFile, '--frames', '0,134', '--report', report], 1);
  console.log(out.trim());

  browser = await playwright.chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, timeout: 30000 });
  const page = await browser.newPage({ viewport: { width: 1200, height: 900 }, deviceScaleFactor: 1 });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push('console: ' + m.text()); });
  await page.goto(pathToFileURL(path.join(report, 'index.html')).href, { waitUntil: 'load', timeout: 15000 });

  // Every failing frame shows three images, each loaded.
  const sections = await page.evaluate(() => [...document.querySelectorAll('section.failure')].map((s) => ({
    title: s.querySelector('h2').textContent,
    images: [...s.querySelectorAll('img')].map((i) => ({ alt: i.alt, w: i.naturalWidth, h: i.naturalHeight, done: i.complete })),
  })));
  if (sections.length !== 2) fail(`expected 2 failing frames in the report, found ${sections.length}`);
  for (const s of sections) {
    const kinds = s.images.map((i) => i.alt).join(',');
    if (kinds !== 'golden,actual,diff') fail(`${s.title}: images ${kinds}, expected golden,actual,diff`);
    for (const i of s.images) {
      if (!i.done || i.w !== 160 || i.h !== 120) fail(`${s.title}: ${i.alt} image not loaded (naturalWidth ${i.w})`);
    }
    console.log(`ok: ${s.title}: golden, actual and diff loaded (160x120)`);
  }

  // The screenshot is not blank: many distinct colours, the diff's red among them.
  const shot = await page.screenshot({ fullPage: true });
  if (screenshotPath) fs.writeFileSync(screenshotPath, shot);
  const stats = await page.evaluate(async (dataUrl) => {
    const img = new Image();
    img.src = dataUrl;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    let red = 0;
    for (let i = 0; i < px.length; i += 4) {
      colours.add((px[i] << 16) | (px[i + 1] << 8) | px[i + 2]);
      if (px[i] >= 128 && px[i + 1] < 30 && px[i + 2] < 30) ++red;
    }
    return { colours: colours.size, red, w: c.width, h: c.height };
  }, 'data:image/png;base64,' + shot.toString('base64'));
  if (stats.colours < 50) fail(`the screenshot looks blank: ${stats.colours} distinct colours`);
  if (stats.red < 20) fail(`the screenshot shows no red diff pixels (${stats.red})`);
  console.log(`ok: screenshot ${stats.w}x${stats.h}, ${stats.colours} colours, ${stats.red} red diff pixels`);
  if (errors.length) fail(`the page reported errors:\n  ${errors.join('\n  ')}`);
  console.log('PASS');
} catch (e) {
  if (!process.exitCode) {
    console.log(`FAIL: ${e.stack || e}`);
    process.exitCode = 1;
  }
} finally {
  if (browser) await browser.close().catch(() => {});
  fs.rmSync(work, { recursive: true, force: true });
}
