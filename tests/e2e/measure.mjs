// Measures `epviz serve` as a browser sees it, at 1280x720: frames per second
// drawn while playing, and input-to-frame latency (from the page sending an
// input event to drawing the first frame whose header says it was applied).
//
//   node tests/e2e/measure.mjs path/to/epviz [out.json|-] [job arguments...]
//
// Prints one JSON object {width, height, fps, latency_median_ms,
// latency_p90_ms, samples, ..., stages} and writes it to out.json when given;
// `stages` holds the median of each stage of a frame while playing (the
// server's from the frame headers, the page's decode and paint) and
// `server_stats` what the server's /stats said at the end.
// tests/e2e/measure.sh runs it three times and prints a table.
// Exit codes as serve_e2e.mjs (77: skipped).
import fs from 'node:fs';
import { run, log, fail, sleep, frameRectToCss, epvizState } from './harness.mjs';

const [binary, outArg, ...serverArgs] = process.argv.slice(2);
const outPath = outArg && outArg !== '-' ? outArg : null;

const MEASURE_MS = 8000;
const MOVES = 40;
const MOVE_SPACING_MS = 150;
const PAUSED_MOVES = 20;

function percentile(sorted, q) {
  if (!sorted.length) return null;
  const i = Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1));
  return sorted[i];
}

const STAGES = ['simulate_ms', 'draw_ms', 'read_back_ms', 'encode_ms', 'queue_ms', 'send_ms', 'decode_ms', 'paint_ms', 'bytes'];

// The median of each stage over the frames drawn in [a, b] (page clock).
function stageMedians(frames, a, b) {
  const inside = frames.filter((f) => f.at >= a && f.at <= b);
  const out = {};
  for (const k of STAGES) {
    const v = inside.map((f) => f[k]).filter((x) => typeof x === 'number').sort((x, y) => x - y);
    out[k] = round(percentile(v, 0.5), k === 'bytes' ? 0 : 2);
  }
  return out;
}

// The frame size drawn most often in [a, b] (adaptive resolution's choice while playing).
function commonestSize(frames, a, b) {
  const counts = new Map();
  for (const f of frames) {
    if (f.at < a || f.at > b) continue;
    const k = `${f.width}x${f.height}`;
    counts.set(k, (counts.get(k) || 0) + 1);
  }
  let best = null;
  for (const [k, n] of counts) if (!best || n > counts.get(best)) best = k;
  return best;
}

function round(v, digits = 1) {
  return v === null ? null : Math.round(v * 10 ** digits) / 10 ** digits;
}

// Hovers back and forth inside the 3D view, one pointer move each spacing;
// returns the latencies the page recorded for them.
async function moveSamples(page, point, count) {
  await page.evaluate(() => { window.epviz.latencies.length = 0; });
  for (let i = 0; i < count; ++i) {
    const dx = (i % 2 === 0 ? 1 : -1) * 20;
    await page.mouse.move(point.x + dx, point.y + (i % 4 < 2 ? 0 : 10));
    await sleep(MOVE_SPACING_MS);
  }
  await sleep(500);   // the last moves' frames
  return page.evaluate(() => window.epviz.latencies.slice());
}

await run({
  name: 'measure.mjs',
  binary,
  serverArgs,
  async body({ page, url }) {
    await sleep(300);   // the layout of the latest frame (the first frames may precede it)
    const latest = (await epvizState(page)).header;
    const controls = latest.controls || {};
    if (!Array.isArray(controls.play) || !Array.isArray(controls.view3d)) {
      fail(`the frame header names no play/view3d controls: ${JSON.stringify(controls)}`);
    }
    const play = await frameRectToCss(page, controls.play);
    const view = await frameRectToCss(page, controls.view3d);
    // Hover point: the middle of the 3D view, nudged down when another control covers it.
    const others = Object.entries(controls).filter(([k, r]) => k !== 'view3d' && Array.isArray(r));
    let point = { x: view.x + view.w / 2, y: view.y + view.h / 2 };
    for (let f = 0.5; f < 0.95; f += 0.05) {
      const p = { x: view.x + view.w / 2, y: view.y + view.h * f };
      const frameP = [p.x * latest.width / 1280, p.y * latest.height / 720];
      if (!others.some(([, r]) => frameP[0] >= r[0] - 30 && frameP[0] < r[0] + r[2] + 30 && frameP[1] >= r[1] - 20 && frameP[1] < r[1] + r[3] + 20)) { point = p; break; }
    }

    await page.mouse.click(play.x + play.w / 2, play.y + play.h / 2);
    log('measure: playing; warming up 1 s');
    await sleep(1000);

    log(`measure: ${MEASURE_MS / 1000} s of frames, ${MOVES} pointer moves ${MOVE_SPACING_MS} ms apart`);
    const t0 = await page.evaluate(() => performance.now());
    const playing = await moveSamples(page, point, MOVES);
    const elapsed = (await page.evaluate(() => performance.now())) - t0;
    if (elapsed < MEASURE_MS) await sleep(MEASURE_MS - elapsed);
    const t1 = await page.evaluate(() => performance.now());
    const times = await page.evaluate(([a, b]) => window.epviz.frameTimes.filter((t) => t >= a && t <= b), [t0, t1]);
    const state = await epvizState(page);
    const fps = times.length / ((t1 - t0) / 1000);

    // The same while paused: frames are rendered only for the input.
    const playNow = await frameRectToCss(page, state.header.controls.play);
    await page.mouse.click(playNow.x + playNow.w / 2, playNow.y + playNow.h / 2);
    await sleep(1000);
    log(`measure: paused; ${PAUSED_MOVES} pointer moves`);
    const paused = await moveSamples(page, point, PAUSED_MOVES);

    // The last frame (the sharp one drawn at rest) decoded again with
    // nothing else running: the decoder's own cost on this machine, against
    // the decode stage above, which is measured while the server draws.
    const alone = await page.evaluate(async () => {
      const f = window.epviz.lastFrame;
      const times = [];
      let size = null;
      for (let i = 0; i < 15; ++i) {
        const start = performance.now();
        const bmp = await createImageBitmap(new Blob([f.bytes], { type: f.mime }));
        times.push(performance.now() - start);
        size = `${bmp.width}x${bmp.height}`;
        bmp.close();
      }
      times.sort((a, b) => a - b);
      return { ms: times[times.length >> 1], size, bytes: f.bytes.byteLength };
    });

    const frames = await page.evaluate(() => window.epviz.stages.slice());
    const stats = await page.evaluate(async (u) => (await fetch(u + 'stats')).json(), url);

    const sorted = playing.slice().sort((a, b) => a - b);
    const sortedPaused = paused.slice().sort((a, b) => a - b);
    const h = state.header;
    const viewSize = await page.evaluate(() => [innerWidth * devicePixelRatio, innerHeight * devicePixelRatio]);
    const result = {
      width: viewSize[0],
      height: viewSize[1],
      last_frame: `${h.width}x${h.height}`,  // smaller than the view while adaptive resolution holds it down
      fps: round(fps),
      latency_median_ms: round(percentile(sorted, 0.5)),
      latency_p90_ms: round(percentile(sorted, 0.9)),
      samples: sorted.length,
      paused_latency_median_ms: round(percentile(sortedPaused, 0.5)),
      paused_latency_p90_ms: round(percentile(sortedPaused, 0.9)),
      paused_samples: sortedPaused.length,
      mime: h.mime,
      measure_s: round((t1 - t0) / 1000, 2),
      stages: stageMedians(frames, t0, t1),
      playing_size: commonestSize(frames, t0, t1),
      decode_alone: { ms: round(alone.ms, 2), size: alone.size, kB: Math.round(alone.bytes / 1000) },
      server_stats: stats,
    };
    if (sorted.length < MOVES / 2) fail(`only ${sorted.length} of ${MOVES} pointer moves got a latency: ${JSON.stringify(result)}`);
    const text = JSON.stringify(result);
    log(text);
    if (outPath) fs.writeFileSync(outPath, JSON.stringify(result, null, 2) + '\n');
  },
});
