"""Writes a variant of a cut scene: its own settings ("scene"), another time step
("dt0.002", "dt0.05") or the penalty a tenth or ten times "auto" (50 x the largest Young's
modulus): "penalty_div10", "penalty_x10".

    /usr/bin/python3 variant.py SCENE.json VARIANT OUT.json
"""
import json
import sys

scene_path, variant, out_path = sys.argv[1:4]
with open(scene_path) as f:
    scene = json.load(f)
control = scene.setdefault("control", {})
auto_penalty = 50.0 * max(m["young"] for m in scene["materials"].values())
if variant == "scene":
    pass
elif variant.startswith("dt"):
    control["time_step"] = float(variant[2:])
elif variant == "penalty_div10":
    control["penalty"] = auto_penalty / 10.0
elif variant == "penalty_x10":
    control["penalty"] = auto_penalty * 10.0
else:
    sys.exit(f"variant.py: unknown variant {variant}")
with open(out_path, "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
