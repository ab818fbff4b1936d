// Records the replay test's input in a real browser: starts `epviz serve
// --record FILE JOB`, then clicks the case combo, picks Kovalevskaya, drags
// the I3 slider and presses Play. tests/live/replay_test.cpp replays FILE.
//
//   node tests/e2e/record.mjs path/to/epviz tests/live/recordings/pick_case_drag_play.jsonl render_jobs/hess.json
import { run, log, fail, sleep, waitFor, frameRectToCss, epvizState } from './harness.mjs';

const [binary, recording, job] = process.argv.slice(2);
if (!recording || !job) {
  log('usage: node record.mjs path/to/epviz RECORDING.jsonl JOB.json');
  process.exit(2);
}

async function control(page, name) {
  const s = await waitFor(`control ${name}`, 5000, async () => {
    const st = await epvizState(page);
    return st && st.header && st.header.controls && st.header.controls[name] ? st : null;
  });
  return frameRectToCss(page, s.header.controls[name]);
}

async function click(page, name) {
  const r = await control(page, name);
  await page.mouse.click(r.x + r.w / 2, r.y + r.h / 2);
  await sleep(400);
  log(`clicked ${name}`);
}

await run({
  name: 'record.mjs',
  binary,
  serverArgs: ['--record', recording, job],
  timeoutMs: 60000,
  async body({ page }) {
    await click(page, 'case');
    await click(page, 'case:kovalevskaya');
    const i3 = await control(page, 'I3');
    const y = i3.y + i3.h / 2;
    await page.mouse.move(i3.x + i3.w / 2, y);
    await page.mouse.down();
    await page.mouse.move(i3.x + i3.w / 2 + 50, y, { steps: 10 });
    await page.mouse.up();
    await sleep(400);
    log('dragged I3 by 50 px');
    await click(page, 'play');
    await sleep(1000);
    const s = await epvizState(page);
    if (!s.connected) fail('disconnected');
    log(`recorded ${recording} (${s.framesShown} frames shown)`);
  },
});
