// Browser test of `epviz serve`: the page shows frames, Play makes the
// picture move, a drag in the 3D view turns it, the wheel zooms it, and runs
// added from the panel are compared (legend and |delta gamma| chart), with a
// screenshot of the three runs saved for a person to look at.
//
//   node tests/e2e/serve_e2e.mjs path/to/epviz [job arguments...]
//
// The screenshot goes to $EPVIZ_E2E_SCREENSHOT, else e2e_serve_compare.png
// beside the epviz binary.
//
// Exit 0: passed; 1: failed (the reason and the server's last lines are
// printed); 77: skipped (no Chromium or no node_modules: see the SKIP line).
import path from 'node:path';
import {
  run, log, fail, sleep, canvasHash, frameRectToCss, epvizState, waitFor,
} from './harness.mjs';

const [binary, ...serverArgs] = process.argv.slice(2);

function inside(r, x, y, margin = 0) {
  return x >= r[0] - margin && y >= r[1] - margin && x < r[0] + r[2] + margin && y < r[1] + r[3] + margin;
}

// A point (frame pixels) in view3d that no other control covers, near the
// middle when possible.
function freePoint(controls) {
  const v = controls.view3d;
  const others = Object.entries(controls).filter(([k, r]) => k !== 'view3d' && Array.isArray(r)).map(([, r]) => r);
  const candidates = [];
  for (let fy = 0.5; fy > 0.05; fy -= 0.1) {
    for (let fx = 0.5; fx > 0.05; fx -= 0.1) {
      for (const [ax, ay] of [[fx, fy], [1 - fx, fy], [fx, 1 - fy], [1 - fx, 1 - fy]]) {
        candidates.push([v[0] + ax * v[2], v[1] + ay * v[3]]);
      }
    }
  }
  return candidates.find(([x, y]) => !others.some((r) => inside(r, x, y, 12)));
}

// Waits until the region's hash differs from `before`.
async function waitChange(page, rect, before, timeoutMs) {
  const end = Date.now() + timeoutMs;
  while (Date.now() < end) {
    await sleep(100);
    const h = await canvasHash(page, rect);
    if (h !== before) return h;
  }
  return null;
}

// Waits until the region stays the same for `quietMs`.
async function waitStill(page, rect, quietMs, timeoutMs) {
  const end = Date.now() + timeoutMs;
  let last = await canvasHash(page, rect);
  let since = Date.now();
  while (Date.now() < end) {
    await sleep(100);
    const h = await canvasHash(page, rect);
    if (h !== last) { last = h; since = Date.now(); }
    if (Date.now() - since >= quietMs) return last;
  }
  return null;
}

await run({
  name: 'serve_e2e.mjs',
  binary,
  serverArgs,
  async body({ page, first }) {
    // 1. The page connects and, once the picture rests, draws a frame of the
    // window's size (on a loaded machine the first ones may be smaller: the
    // server's adaptive resolution, sharpened at rest).
    const f = first.header;
    log(`ok: first frame drawn (${f.width}x${f.height} ${f.mime}, frame ${f.frame})`);
    const h = await waitFor('a frame of the view\'s size, 1280x720, at rest', 10000, async () => {
      const s = await epvizState(page);
      return s.header.width === 1280 && s.header.height === 720 ? s.header : null;
    });
    log(`ok: at rest the frame is the view's size (frame ${h.frame})`);
    const layout = await page.evaluate(() => {
      const c = document.getElementById('view');
      const r = c.getBoundingClientRect();
      const d = document.documentElement;
      return { left: r.left, top: r.top, w: r.width, h: r.height, sw: d.scrollWidth, sh: d.scrollHeight,
        iw: innerWidth, ih: innerHeight, bw: c.width, bh: c.height };
    });
    if (layout.left !== 0 || layout.top !== 0 || layout.w !== layout.iw || layout.h !== layout.ih) {
      fail(`the canvas does not cover the window: ${JSON.stringify(layout)}`);
    }
    if (layout.sw > layout.iw || layout.sh > layout.ih) fail(`the page scrolls: ${JSON.stringify(layout)}`);
    if (layout.bw !== h.width || layout.bh !== h.height) fail(`canvas backing ${layout.bw}x${layout.bh} is not the frame size`);
    log('ok: the canvas fills the window, no scrolling');

    // The layout of the latest frame (the first frames may precede it).
    await sleep(300);
    const currentControls = async () => {
      const c = (await epvizState(page)).header.controls;
      if (!c || !Array.isArray(c.play) || !Array.isArray(c.view3d)) {
        fail(`the frame header names no play/view3d controls: ${JSON.stringify(c)}`);
      }
      return c;
    };
    let controls = await currentControls();
    let view = controls.view3d;

    // 2. Play: frames keep coming and the 3D view moves.
    const play = await frameRectToCss(page, controls.play);
    const playX = play.x + play.w / 2;
    const playY = play.y + play.h / 2;
    await page.mouse.click(playX, playY);
    await sleep(300);
    const framesAtPlay = (await epvizState(page)).framesShown;
    const viewAtPlay = await canvasHash(page, view);
    const moved = await waitChange(page, view, viewAtPlay, 2500);
    await sleep(1000);
    const framesLater = (await epvizState(page)).framesShown;
    if (!moved) fail('after clicking Play the 3D view did not change within 2.5 s');
    if (framesLater - framesAtPlay < 5) fail(`after clicking Play only ${framesLater - framesAtPlay} frames came in over ~1 s`);
    log(`ok: Play at (${playX.toFixed(0)}, ${playY.toFixed(0)}) css px: the view moves, ${framesLater - framesAtPlay} frames in ~1 s`);

    // 3. Pause (the same control again): the view comes to rest.
    const playAgain = await frameRectToCss(page, (await currentControls()).play);
    await page.mouse.click(playAgain.x + playAgain.w / 2, playAgain.y + playAgain.h / 2);
    const still = await waitStill(page, view, 700, 5000);
    if (!still) fail('after clicking Play again (pause) the 3D view kept changing for 5 s');
    log('ok: paused, the view is at rest');

    // 4. Left-drag inside the 3D view (clear of other controls) turns it.
    controls = await currentControls();
    view = controls.view3d;
    const start = freePoint(controls);
    if (!start) fail(`no point of view3d is clear of the other controls: ${JSON.stringify(controls)}`);
    const [sx, sy] = start;
    const ex = Math.min(view[0] + view[2] - 2, Math.max(view[0] + 2, sx + (sx < view[0] + view[2] / 2 ? 1 : -1) * view[2] * 0.2));
    const ey = Math.min(view[1] + view[3] - 2, Math.max(view[1] + 2, sy + (sy < view[1] + view[3] / 2 ? 1 : -1) * view[3] * 0.1));
    const a = await frameRectToCss(page, [sx, sy, 0, 0]);
    const b = await frameRectToCss(page, [ex, ey, 0, 0]);
    await page.mouse.move(a.x, a.y);
    const beforeDrag = await waitStill(page, view, 300, 3000);
    if (!beforeDrag) fail('the 3D view does not come to rest with the pointer over it');
    await page.mouse.down({ button: 'left' });
    await page.mouse.move(b.x, b.y, { steps: 12 });
    await page.mouse.up({ button: 'left' });
    const dragged = await waitChange(page, view, beforeDrag, 3000);
    if (!dragged) fail(`dragging from (${a.x.toFixed(0)}, ${a.y.toFixed(0)}) to (${b.x.toFixed(0)}, ${b.y.toFixed(0)}) css px did not change the 3D view`);
    log(`ok: left-drag (${a.x.toFixed(0)}, ${a.y.toFixed(0)}) -> (${b.x.toFixed(0)}, ${b.y.toFixed(0)}) css px in view3d ${JSON.stringify(view)} turned the view`);

    // 5. Wheel over the view (reported, not required).
    await page.mouse.move(a.x, a.y);
    const beforeWheel = await waitStill(page, view, 300, 3000);
    await page.mouse.wheel(0, -300);
    const wheeled = beforeWheel ? await waitChange(page, view, beforeWheel, 2000) : null;
    log(wheeled ? 'ok: wheel up over the view changed it' : 'note: wheel over the view did not change it (not asserted)');

    // 6. Compare runs: the generic (chaotic) body, then an RK4 run and a
    // nudged one added from the panel's "Compare runs" section.
    const clickControl = async (name) => {
      const c = await waitFor(`the control '${name}'`, 5000, async () => {
        const s = await epvizState(page);
        const controls = s && s.header && s.header.controls;
        return controls && Array.isArray(controls[name]) ? controls : null;
      });
      const r = await frameRectToCss(page, c[name]);
      const shown = (await epvizState(page)).framesShown;
      await page.mouse.click(r.x + r.w / 2, r.y + r.h / 2);
      // Two frames later the panel has laid out what the click opened.
      await waitFor(`frames after clicking '${name}'`, 5000,
                    async () => (await epvizState(page)).framesShown >= shown + 2);
    };
    const runRows = async () => {
      const c = (await epvizState(page)).header.controls || {};
      return Object.keys(c).filter((k) => /^run:\d+$/.test(k)).length;
    };
    await clickControl('case');
    await clickControl('case:generic');
    await clickControl('header:case');  // closed, to make room for the runs
    await clickControl('header:runs');
    await clickControl('new_method');
    await clickControl('new_method:rk4');
    await clickControl('add_run');
    await waitFor('a second run', 5000, async () => (await runRows()) === 2);
    await clickControl('add_nudged');
    await waitFor('a third run', 5000, async () => (await runRows()) === 3);
    log('ok: an RK4 run and a nudged run added from the panel: 3 runs');
    await clickControl('play');
    const playing = (await epvizState(page)).framesShown;
    await waitFor('60 frames of the three runs playing', 20000,
                  async () => (await epvizState(page)).framesShown >= playing + 60);
    await clickControl('play');
    controls = await currentControls();
    await waitStill(page, controls.view3d, 500, 5000);
    if ((await runRows()) !== 3) fail(`after playing the panel lists ${await runRows()} runs, not 3`);
    const shot = process.env.EPVIZ_E2E_SCREENSHOT || path.join(path.dirname(path.resolve(binary)), 'e2e_serve_compare.png');
    await page.screenshot({ path: shot });
    log(`ok: three runs played; screenshot ${shot}`);
    await clickControl('remove:2');
    await waitFor('two runs after removing one', 5000, async () => (await runRows()) === 2);
    log('ok: a run removed from the panel');

    const end = await epvizState(page);
    if (!end.connected) fail('the page is no longer connected');
    log(`PASS: ${end.framesShown} frames shown`);
  },
});
