"""A run read step by step from Python: the block sliding down scenes/incline.json.

Steps the simulation, keeps the sliding block's distance and the energy account's terms at
every output step, and draws the blocks at the end, the distance against the closed form
d = g (sin a - cos a tan phi) t^2 / 2, and the energies.
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import dda

here = os.path.dirname(os.path.abspath(__file__))
sim = dda.Simulation(os.path.join(here, "..", "scenes", "incline.json"))
end = 0.2 if os.environ.get("DDA_EXAMPLES_QUICK") else 2.0
start = sim.blocks()["centroid"][1].copy()
down = np.array([-math.cos(math.radians(30)), -math.sin(math.radians(30))])
times, slid, energies = [], [], []
while sim.time < end - 1e-9 and not sim.finished:
    sim.step(25)
    times.append(sim.time)
    slid.append((sim.blocks()["centroid"][1] - start) @ down)
    energies.append(sim.energy())
t = np.array(times)
closed_form = 0.5 * 9.81 * (math.sin(math.radians(30)) - math.cos(math.radians(30)) * math.tan(math.radians(20))) * t**2
print(f"{sim.step_count} steps to t = {sim.time:.3f} s; slid {slid[-1]:.4f} m, closed form {closed_form[-1]:.4f} m")

fig, (blocks, distance, energy) = plt.subplots(1, 3, figsize=(15, 4.5))
for i in range(sim.block_count):
    v = sim.block_vertices(i)
    blocks.fill(v[:, 0], v[:, 1], alpha=0.6, edgecolor="black",
                color="lightgrey" if sim.blocks()["fixed"][i] else "tab:orange")
c = sim.blocks()["centroid"][1]
blocks.set_xlim(c[0] - 2, c[0] + 2), blocks.set_ylim(c[1] - 2, c[1] + 2), blocks.set_aspect("equal")
blocks.set_title(f"blocks at t = {sim.time:.2f} s")
distance.plot(t, slid, "o", markersize=3, label="dda")
distance.plot(t, closed_form, "-", label="g (sin a - cos a tan phi) t^2 / 2")
distance.set_xlabel("t (s)"), distance.set_ylabel("distance slid (m)"), distance.legend()
for term in ("kinetic", "potential", "friction_dissipation", "remainder"):
    energy.plot(t, [e[term] for e in energies], label=term)
energy.set_xlabel("t (s)"), energy.set_ylabel("J/m"), energy.legend()
out = sys.argv[1] if len(sys.argv) > 1 else "plot_run.png"
fig.tight_layout()
fig.savefig(out, dpi=110)
print("picture in", out)
