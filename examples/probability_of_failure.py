"""The probability of failure of a block on a plane whose friction angle is random.

scenes/random_plane.json: a block on a 30 degree plane, the joint's friction angle drawn
from N(32, 4) degrees. One strength-reduction trial per sample at F = 1 says whether that
sample fails; the closed form is P(F < 1) = P(phi < 30) = Phi(-0.5) = 0.309.
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import dda

here = os.path.dirname(os.path.abspath(__file__))
samples = 8 if os.environ.get("DDA_EXAMPLES_QUICK") else 200
r = dda.fos_samples(os.path.join(here, "..", "scenes", "random_plane.json"),
                    samples=samples, seed=1, at_factor=1.0)
closed_form = 0.5 * (1 + math.erf((30 - 32) / (4 * math.sqrt(2))))
low, high = r["interval"]
print(f"P(F < 1) = {r['probability_of_failure']:.3f} (95 % interval {low:.3f} to {high:.3f}) "
      f"over {r['judged']} samples; closed form {closed_form:.3f}")

phi = r["values"][:, 0]
failing = r["sample_failing"]
bins = [20 + k for k in range(25)]
plt.hist([phi[~failing], phi[failing]], bins=bins, stacked=True, label=["stable", "failing"],
         color=["tab:blue", "tab:red"])
plt.axvline(30, color="black", linestyle="--", label="plane's dip, 30 deg")
plt.xlabel("sampled friction angle (deg)")
plt.ylabel("samples")
plt.title(f"P(F < 1) = {r['probability_of_failure']:.3f} [{low:.3f}, {high:.3f}], closed form {closed_form:.3f}")
plt.legend()
out = sys.argv[1] if len(sys.argv) > 1 else "probability_of_failure.png"
plt.savefig(out, dpi=120)
print("picture in", out)
