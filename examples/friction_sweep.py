"""F against the bedding's friction angle of the example slope (models/small-slope.json)."""
import os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import dda

here = os.path.dirname(os.path.abspath(__file__))
scene = dda.cut(os.path.join(here, "..", "models", "small-slope.json"))  # 40 blocks
quick = os.environ.get("DDA_EXAMPLES_QUICK")  # the test suite's smoke run: one coarse point
angles, tolerance = ([30], 0.1) if quick else (list(range(26, 42, 2)), 0.01)
factors = []
for phi in angles:
    scene["joint_materials"]["bedding"]["friction_angle"] = phi
    factors.append(dda.fos(scene, tolerance=tolerance)["factor"])
    print(f"bedding friction {phi} deg: F = {factors[-1]:.3f}")
plt.plot(angles, factors, "o-", label="dda.fos")
plt.plot(angles, np.tan(np.radians(angles)) / np.tan(np.radians(25)), "--", label="tan(phi) / tan(25 deg)")
plt.xlabel("bedding friction angle phi (deg)"), plt.ylabel("factor of safety F"), plt.legend()
out = sys.argv[1] if len(sys.argv) > 1 else "friction_sweep.png"
plt.savefig(out, dpi=120)
print("picture in", out)
