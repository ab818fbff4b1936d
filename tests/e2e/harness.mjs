// Shared start-up for the browser tests of `epviz serve`: checks what is
// needed (else SKIP, exit 77), starts the server on a free port, launches
// Debian's Chromium through playwright-core, and always cleans both up.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const SKIP = 77;
const HERE = path.dirname(fileURLToPath(import.meta.url));
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

export function log(line) {
  process.stdout.write(line + '\n');
}

class Failure extends Error {}

// Fails the current run with a message (caught by run()).
export function fail(message) {
  throw new Failure(message);
}

export function sleep(ms) {
  return new Promise((resolve) => setTimeout(resolve, ms));
}

function skip(reason) {
  log(`SKIP: ${reason}`);
  process.exit(SKIP);
}

// Everything the test needs, or SKIP with the reason.
async function loadPlaywright() {
  const major = Number(process.versions.node.split('.')[0]);
  if (major < 20) skip(`Node.js ${process.versions.node} is too old for playwright-core (needs 20 or newer)`);
  if (!fs.existsSync(CHROMIUM)) skip(`${CHROMIUM} not found (install Debian's chromium: scripts/setup.sh)`);
  if (!fs.existsSync(path.join(HERE, 'node_modules', 'playwright-core'))) {
    skip(`${path.join(HERE, 'node_modules', 'playwright-core')} missing (run: cd tests/e2e && npm ci)`);
  }
  try {
    return await import('playwright-core');
  } catch (e) {
    skip(`playwright-core does not load: ${e.message}`);
  }
  return null;
}

// The epviz server (one process). It stays in this script's process group,
// so a runner that kills the group (CTest on its timeout, Ctrl+C) ends it too.
class ServerProcess {
  constructor(binary, args) {
    this.binary = binary;
    this.args = args;
    this.output = [];          // the last lines it printed (shown on failure)
    this.exited = null;
    this.child = null;
  }

  remember(prefix, chunk) {
    for (const line of chunk.toString().split('\n')) {
      if (!line) continue;
      this.output.push(prefix + line);
      if (this.output.length > 60) this.output.shift();
    }
  }

  // Starts it and resolves with the URL it prints.
  start(timeoutMs) {
    return new Promise((resolve, reject) => {
      let stdoutText = '';
      let done = false;
      const finish = (err, url) => {
        if (done) return;
        done = true;
        clearTimeout(timer);
        if (err) reject(err); else resolve(url);
      };
      const timer = setTimeout(() => finish(new Failure(`the server printed no URL within ${timeoutMs / 1000} s`)), timeoutMs);
      try {
        this.child = spawn(this.binary, this.args, { stdio: ['ignore', 'pipe', 'pipe'] });
      } catch (e) {
        finish(new Failure(`cannot start ${this.binary}: ${e.message}`));
        return;
      }
      this.child.on('error', (e) => finish(new Failure(`cannot start ${this.binary}: ${e.message}`)));
      this.child.on('exit', (code, signal) => {
        this.exited = { code, signal };
        finish(new Failure(`the server exited (${signal || 'code ' + code}) before printing a URL`));
      });
      this.child.stderr.on('data', (d) => this.remember('[server stderr] ', d));
      this.child.stdout.on('data', (d) => {
        this.remember('[server] ', d);
        if (done) return;
        stdoutText += d.toString();
        const m = stdoutText.match(/http:\/\/(?:127\.0\.0\.1|localhost|\[::1\]):\d+\//);
        if (m) finish(null, m[0]);
      });
    });
  }

  alive() {
    return this.child && this.child.pid && this.exited === null;
  }

  async stop() {
    if (!this.alive()) return;
    const signal = (sig) => {
      try { this.child.kill(sig); } catch (_) { /* already gone */ }
    };
    signal('SIGTERM');
    for (let i = 0; i < 30 && this.alive(); ++i) await sleep(100);
    if (this.alive()) {
      log('note: the server ignored SIGTERM for 3 s; killing it');
      signal('SIGKILL');
      for (let i = 0; i < 20 && this.alive(); ++i) await sleep(100);
    }
  }
}

// In the page: frame pixels -> CSS pixels, and a hash of the canvas (or of a
// rectangle of it in frame pixels) to tell whether the picture changed.
// A rectangle from a frame header's controls (epvizState tags each with its
// frame's size) is scaled by that frame's size, not by the canvas's: with
// adaptive resolution another frame of another size may be shown by now,
// and the page stretches every frame to the same CSS box.
export async function frameRectToCss(page, rect) {
  const frame = rect.frameSize || null;
  return page.evaluate(([[x, y, w, h], size]) => {
    const c = document.getElementById('view');
    const r = c.getBoundingClientRect();
    const [fw, fh] = size || [c.width, c.height];
    const sx = r.width / fw;
    const sy = r.height / fh;
    return { x: r.left + x * sx, y: r.top + y * sy, w: w * sx, h: h * sy };
  }, [Array.from(rect).slice(0, 4), frame]);
}

export async function canvasHash(page, rect) {
  return page.evaluate((rc) => {
    const c = document.getElementById('view');
    const g = c.getContext('2d');
    let [x, y, w, h] = rc || [0, 0, c.width, c.height];
    x = Math.max(0, Math.floor(x));
    y = Math.max(0, Math.floor(y));
    w = Math.min(c.width - x, Math.ceil(w));
    h = Math.min(c.height - y, Math.ceil(h));
    if (w <= 0 || h <= 0) return 'empty';
    const px = new Uint32Array(g.getImageData(x, y, w, h).data.buffer);
    let a = 0x811c9dc5;
    let b = 0;
    for (let i = 0; i < px.length; ++i) {
      a = Math.imul(a ^ px[i], 0x01000193);
      b = (b + px[i] * (i + 1)) >>> 0;
    }
    return (a >>> 0).toString(16) + ':' + b.toString(16);
  }, rect || null);
}

export async function epvizState(page) {
  const state = await page.evaluate(() => {
    const e = window.epviz;
    return e ? { framesShown: e.framesShown, connected: e.connected, header: e.lastHeader } : null;
  });
  const h = state && state.header;
  if (h && h.controls && typeof h.controls === 'object') {
    for (const rect of Object.values(h.controls)) {
      if (Array.isArray(rect)) rect.frameSize = [h.width, h.height];
    }
  }
  return state;
}

export async function waitFor(what, timeoutMs, check, intervalMs = 100) {
  const end = Date.now() + timeoutMs;
  for (;;) {
    const v = await check();
    if (v) return v;
    if (Date.now() > end) fail(`timed out after ${timeoutMs / 1000} s waiting for ${what}`);
    await sleep(intervalMs);
  }
}

// The page's state once it has drawn its first frame.
function firstFrame(page) {
  return waitFor('the first frame', 20000, async () => {
    const s = await epvizState(page);
    return s && s.framesShown > 0 ? s : null;
  });
}

// Runs body({ page, url, server, pageErrors, first }) with the server and a
// browser started and the page showing its first frame (`first`, the page's
// state then), within an overall time limit; exits 0 when body returns, 1 on
// a failure, and always stops the browser and the server first.
export async function run({ name, binary, serverArgs, timeoutMs = 90000, body }) {
  if (!binary) {
    log(`usage: node ${name} path/to/epviz [job arguments...]`);
    process.exit(2);
  }
  const playwright = await loadPlaywright();
  const server = new ServerProcess(path.resolve(binary), ['serve', '--port', '0', ...serverArgs]);
  let browser = null;
  let cleaning = null;
  const cleanup = () => {
    if (!cleaning) {
      cleaning = (async () => {
        if (browser) {
          await Promise.race([browser.close().catch(() => {}), sleep(5000)]);
        }
        await server.stop();
      })();
    }
    return cleaning;
  };
  const abort = async (message) => {
    log(`FAIL: ${message}`);
    for (const line of server.output.slice(-30)) log(line);
    await Promise.race([cleanup(), sleep(10000)]);
    process.exit(1);
  };
  const watchdog = setTimeout(() => abort(`overall time limit (${timeoutMs / 1000} s) reached`), timeoutMs);
  for (const sig of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.on(sig, () => abort(`interrupted (${sig})`));

  try {
    const url = await server.start(30000);
    log(`server: ${url}`);
    browser = await playwright.chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, timeout: 30000 });
    const context = await browser.newContext({ viewport: { width: 1280, height: 720 }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(String(e)));
    page.on('console', (m) => { if (m.type() === 'error') pageErrors.push('console: ' + m.text()); });
    await page.goto(url, { waitUntil: 'load', timeout: 15000 });
    const first = await firstFrame(page);
    await body({ page, url, server, pageErrors, first });
    const errs = pageErrors.filter((e) => !/favicon/.test(e));
    if (errs.length) fail(`the page reported errors:\n  ${errs.join('\n  ')}`);
    if (server.exited) fail(`the server exited during the test (${server.exited.signal || 'code ' + server.exited.code})`);
  } catch (e) {
    clearTimeout(watchdog);
    await abort(e instanceof Failure ? e.message : (e && e.stack) || String(e));
  }
  clearTimeout(watchdog);
  await cleanup();
  process.exit(0);
}
