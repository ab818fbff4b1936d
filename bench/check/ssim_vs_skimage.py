#!/usr/bin/env python3
"""epviz's SSIM against scikit-image's, the comparison alone, on the same
1280x720 image pairs and in one run, so that machine load affects both alike.

It writes the pairs as PNG files, times skimage.metrics.structural_similarity
on them (already read and made grey: scikit-image's best case), then runs
epviz_ssim_bench --pairs on the same files, alternating the two a few times.

    bench/check/ssim_vs_skimage.py [--bench build/bench/epviz_ssim_bench] [--rounds 3]

scikit-image is not a dependency of epviz: without it the script says so and
exits 0 without measuring (install python3-skimage to measure).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WIDTH, HEIGHT, PAIRS = 1280, 720, 4


def frame_pairs(np):
    """A frame-like picture (gradient, disc, thin lines) against the same one
    with its disc and lines a pixel to the right and a little noise."""
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH]

    def picture(shift):
        im = np.empty((HEIGHT, WIDTH, 4), np.uint8)
        im[..., 0] = 20 + 40 * y // HEIGHT
        im[..., 1] = 25 + 40 * y // HEIGHT
        im[..., 2] = 60 + 60 * y // HEIGHT
        im[..., 3] = 255
        line = ((x + shift) % 97 == 0) | ((x + 2 * y + shift) % 151 == 0)
        im[line, :3] = 250
        disc = (x - WIDTH // 2 - shift) ** 2 + (y - HEIGHT // 2) ** 2 < (HEIGHT // 4) ** 2
        im[disc, :3] = (230, 120, 40)
        return im

    rng = np.random.default_rng(1)
    for _ in range(PAIRS):
        b = picture(1).astype(np.int16)
        b[..., :3] += rng.integers(-3, 4, size=(HEIGHT, WIDTH, 3), dtype=np.int16)
        yield picture(0), np.clip(b, 0, 255).astype(np.uint8)


def skimage_seconds_per_pair(ssim, greys):
    """Wall-clock and CPU seconds a pair (the lower of three passes over the pairs)."""
    best = None
    for _ in range(3):
        wall, cpu = time.perf_counter(), time.process_time()
        for a, b in greys:
            ssim(a, b, data_range=255)
        took = ((time.perf_counter() - wall) / len(greys), (time.process_time() - cpu) / len(greys))
        best = took if best is None or took[0] < best[0] else best
    return best


def epviz_seconds_per_pair(bench, pairs_dir):
    out = subprocess.run(
        [bench, "--pairs", pairs_dir, "--benchmark_filter=BM_SsimReusedWorkspace",
         "--benchmark_format=json", "--benchmark_min_time=1"],
        check=True, capture_output=True, text=True).stdout
    run = json.loads(out)["benchmarks"][0]
    assert run["time_unit"] == "ms", run["time_unit"]
    return (run["real_time"] / 1e3, run["cpu_time"] / 1e3), run["mean_ssim"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bench", default=os.path.join(ROOT, "build/bench/epviz_ssim_bench"))
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    try:
        import numpy as np
        import skimage
        from skimage.io import imsave
        from skimage.metrics import structural_similarity
    except ImportError as e:
        print(f"ssim_vs_skimage: skipped, scikit-image is not installed ({e}); "
              "install python3-skimage to measure")
        return 0
    if not os.access(args.bench, os.X_OK):
        print(f"ssim_vs_skimage: --bench: no executable {args.bench} "
              "(build the epviz_ssim_bench target)", file=sys.stderr)
        return 2

    with tempfile.TemporaryDirectory() as pairs_dir:
        greys = []
        weights = np.array([0.299, 0.587, 0.114])
        for k, (a, b) in enumerate(frame_pairs(np)):
            imsave(os.path.join(pairs_dir, f"{k}_a.png"), a, check_contrast=False)
            imsave(os.path.join(pairs_dir, f"{k}_b.png"), b, check_contrast=False)
            greys.append((a[..., :3] @ weights, b[..., :3] @ weights))
        sk, ep = [], []
        for _ in range(args.rounds):
            sk.append(skimage_seconds_per_pair(structural_similarity, greys))
            seconds, mean_ssim = epviz_seconds_per_pair(args.bench, pairs_dir)
            ep.append(seconds)
        sk_mean = statistics.mean(structural_similarity(a, b, data_range=255) for a, b in greys)

    def median(runs, which):
        return statistics.median(r[which] for r in runs)

    sk_wall, sk_cpu, ep_wall, ep_cpu = median(sk, 0), median(sk, 1), median(ep, 0), median(ep, 1)
    print(f"pairs:                {PAIRS} of {WIDTH}x{HEIGHT}, {args.rounds} rounds (medians)")
    print("                       wall ms   CPU ms  a pair")
    print(f"scikit-image {skimage.__version__:<8} {sk_wall * 1e3:8.2f} {sk_cpu * 1e3:8.2f}"
          f"   mean SSIM {sk_mean:.5f} (7x7 windows)")
    print(f"epviz                 {ep_wall * 1e3:8.2f} {ep_cpu * 1e3:8.2f}"
          f"   mean SSIM {mean_ssim:.5f} (8x8 windows)")
    print(f"epviz / scikit-image  {sk_wall / ep_wall:7.2f}x {sk_cpu / ep_cpu:7.2f}x as fast")
    print(f"load average         {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
