// Browser test of the live mode's section panel: the panel's "Poincaré
// section" part shows it, the run's crossings fill it as it plays, and a
// click on it starts an orbit whose crossings are then drawn (the frame's
// controls count each list's dots), with a screenshot saved for a person to
// look at.
//
//   node tests/e2e/serve_section_e2e.mjs path/to/epviz [job arguments...]
//
// The screenshot goes to $EPVIZ_E2E_SECTION_SCREENSHOT, else
// e2e_serve_section.png beside the epviz binary.
//
// Exit 0: passed; 1: failed; 77: skipped (no Chromium or no node_modules).
import path from 'node:path';
import {
  run, log, fail, canvasHash, frameRectToCss, epvizState, waitFor,
} from './harness.mjs';

const [binary, ...serverArgs] = process.argv.slice(2);

await run({
  name: 'serve_section_e2e.mjs',
  binary,
  serverArgs,
  timeoutMs: 150000,
  async body({ page }) {
    const controlsNow = async () => {
      const s = await epvizState(page);
      return (s && s.header && s.header.controls) || {};
    };
    const clickFrame = async (rect) => {
      const r = await frameRectToCss(page, rect);
      const shown = (await epvizState(page)).framesShown;
      await page.mouse.click(r.x + r.w / 2, r.y + r.h / 2);
      // Two frames later the panel has laid out what the click did.
      await waitFor('frames after a click', 5000,
                    async () => (await epvizState(page)).framesShown >= shown + 2);
    };
    const clickControl = async (name) => {
      const c = await waitFor(`the control '${name}'`, 5000, async () => {
        const controls = await controlsNow();
        return Array.isArray(controls[name]) ? controls : null;
      });
      await clickFrame(c[name]);
    };
    // Clicks `name` once and waits until `done(controls)` holds: a click
    // lands where the page shows the control whatever size the server draws
    // the frame at (tests/live/view_scale_test.cpp), so one must do.
    const clickUntil = async (name, what, done) => {
      await clickControl(name);
      await waitFor(what, 5000, async () => done(await controlsNow()));
    };
    await waitFor('a frame of the view\'s size, 1280x720', 10000, async () => {
      const s = await epvizState(page);
      return s.header.width === 1280 && s.header.height === 720;
    });

    // 1. Shown from the panel: the frame names the section's plot.
    await clickUntil('header:section', 'the section part open', (c) => Array.isArray(c.section));
    await clickUntil('section', 'the section panel', (c) => c.section && Array.isArray(c.section.plot));
    const shown = (await controlsNow()).section;
    log(`ok: the section panel is shown at ${JSON.stringify(shown.plot)}`);

    // 2. The run's crossings fill it as it plays.
    await clickControl('play');
    // (Drawn or counted: the panel draws one sheet, γ₂ > 0 unless chosen.)
    await waitFor('three crossings of the run', 60000, async () => {
      const c = await controlsNow();
      return c.section && c.section.dots[0] + c.section.hidden >= 3;
    });
    await clickControl('play');
    // A run that crosses on the other sheet only (the Kovalevskaya preset
    // does): that sheet's button draws them.
    if ((await controlsNow()).section.dots[0] === 0) {
      await clickUntil('sheet:-', 'the run\'s crossings on γ₂ < 0 drawn',
        (c) => c.section && c.section.dots[0] > 0);
      log('ok: the run crosses on γ₂ < 0 only; that sheet drawn');
    }
    const before = await controlsNow();
    log(`ok: the run crossed the surface ${before.section.dots[0]} times on the sheet drawn ` +
      `(${before.section.hidden} on the other), paused`);

    // 3. A click on the plot starts an orbit there: points from the middle
    // outwards until one lies on the run's level (a point with no state is
    // refused with a notice, and leaves the panel as it was).
    const plot = before.section.plot;
    const plotHash = await canvasHash(page, plot);
    let started = null;
    for (const [fx, fy] of [[0.5, 0.5], [0.4, 0.55], [0.6, 0.45], [0.3, 0.5], [0.7, 0.5],
      [0.5, 0.35], [0.5, 0.65], [0.2, 0.5], [0.8, 0.5], [0.5, 0.5], [0.45, 0.5], [0.55, 0.5]]) {
      // The plot's place in the latest frame, whatever its size (adaptive
      // resolution), and that size, by which the page's picture is stretched.
      const latest = (await epvizState(page)).header;
      const p = latest.controls.section.plot;
      const at = [p[0] + fx * p[2], p[1] + fy * p[3], 1, 1];
      at.frameSize = [latest.width, latest.height];
      await clickFrame(at);
      const c = await controlsNow();
      if (c.section && c.section.dots.length === 2) {
        started = [fx, fy];
        break;
      }
    }
    if (!started) fail('no click on the section panel started an orbit');
    log(`ok: a click at ${started} of the plot started an orbit`);

    // 4. Paused, the orbit catches up to the scene's time: its crossings are drawn.
    const filled = await waitFor('three crossings of the clicked orbit', 30000, async () => {
      const c = await controlsNow();
      return c.section && c.section.dots.length === 2 && c.section.dots[1] >= 3 ? c.section : null;
    });
    await waitFor('the plot to show the orbit\'s crossings', 5000,
                  async () => (await canvasHash(page, plot)) !== plotHash);
    log(`ok: the orbit's crossings are drawn (${filled.dots[1]} dots, the run's ${filled.dots[0]})`);

    const shot = process.env.EPVIZ_E2E_SECTION_SCREENSHOT ||
      path.join(path.dirname(path.resolve(binary)), 'e2e_serve_section.png');
    await page.screenshot({ path: shot });
    log(`PASS: screenshot ${shot}`);
  },
});
