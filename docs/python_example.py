"""Two methods' energy drift, a Poincare section, a rendered frame and a
cloud of nearby states, from Python (docs/python.md). Run from the source tree, after the full build:

    PYTHONPATH=build/python python3 docs/python_example.py OUT_DIR
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed; a notebook shows the figure inline
import matplotlib.pyplot as plt
import numpy as np

import epviz

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
fig, (drift_ax, section_ax, frame_ax, cloud_ax) = plt.subplots(1, 4, figsize=(21, 4.8))

# 1. The Kovalevskaya top with an adaptive and a fixed-step method: the
#    relative drift of the energy C1 along each run.
for method, setting in (("dop853", {"tol": 1e-10}), ("rk4", {"step": 0.01})):
    run = epviz.simulate(case="kovalevskaya", method=method, t_end=100, samples=2000, **setting)
    energy = run["energy"]
    drift = np.abs(energy - energy[0]) / abs(energy[0])
    steps = run.report["steps"]
    drift_ax.semilogy(run["t"][1:], np.maximum(drift[1:], 1e-17), label=f"{method}, {steps} steps")
drift_ax.set(xlabel="t", ylabel="relative drift of C1", title="Energy drift")
drift_ax.legend()

# 2. A Poincare section: the crossings of gamma3 = 0, coloured by orbit.
section = epviz.section("render_jobs/kovalevskaya.section.json")
section_ax.scatter(section["gamma1"], section["omega3"], s=0.5, c=section["orbit"], cmap="viridis")
section_ax.set(xlabel="gamma1", ylabel="omega3", title=f"{section.report['crossings']} crossings")

# 3. The first frame of the shipped Kovalevskaya job, as `epviz render` draws it.
frame = epviz.render_frame("kovalevskaya", frame=0, width=640, height=360)
frame_ax.imshow(frame)
frame_ax.set_axis_off()

# 4. The cloud of the shipped generic job: 10,000 states launched in a small
#    disc of gamma, each member's gamma over time a row of the arrays
#    (the same numbers as `epviz render cloud_generic --h5`'s group "cloud").
cloud = epviz.cloud("cloud_generic")
for frame_index, colour in ((0, "crimson"), (-1, "steelblue")):
    cloud_ax.scatter(cloud["gamma1"][:, frame_index], cloud["gamma2"][:, frame_index], s=0.2,
                     color=colour, label=f"t = {cloud['t'][frame_index]:g}")
cloud_ax.set(xlabel="gamma1", ylabel="gamma2", aspect="equal",
             title=f"{cloud.report['members']} members, {cloud.report['failed_members']} failed")
cloud_ax.legend(markerscale=20)

fig.tight_layout()
fig.savefig(out / "python_example.png", dpi=80)
print(f"wrote {out / 'python_example.png'}")
