# dda.fos, dda.fos_samples and dda.cut against closed forms and the command line.
import json
import math

import numpy as np
import pytest

import dda
from conftest import run_cli, scene_dict


def plane_scene(phi):
    """scenes/random_plane.json (a block on a 30 degree plane) with friction phi, no draws."""
    scene = scene_dict("random_plane")
    del scene["random_strengths"]
    scene["joint_materials"]["default"]["friction_angle"] = phi
    return scene


def budget(factor, settings):
    # The search's budget (tests/studies/test_probabilistic_fos.cpp): half the bracket plus
    # the verdict's resolution, F x 2 x detect_acceleration (0.002) / sin(alpha).
    return 0.5 * settings["tolerance"] + factor * 2 * 0.002 / math.sin(math.radians(30))


def test_the_factor_of_a_block_on_a_plane_is_tan_phi_over_tan_alpha():
    r = dda.fos(plane_scene(35.0), tolerance=0.02)
    exact = math.tan(math.radians(35)) / math.tan(math.radians(30))
    assert r["found"], r["message"]
    assert abs(r["factor"] - exact) <= budget(exact, r["settings"])
    low, high = r["bracket"]
    assert low <= r["factor"] <= high and high - low <= 0.02
    # Every trial's verdict agrees with its factor against the bracket.
    for t in r["trials"]:
        assert t["stable"] == (t["factor"] <= low), t
        assert t["verdict"]
    assert r["consolidation"]["steps"] > 0


def test_samples_fail_where_phi_is_below_alpha():
    # random_plane: phi ~ N(32, 4) degrees on a 30 degree plane; one trial per sample at
    # F = 1 fails exactly when phi < 30 (a band of 0.15 degree around it is the verdict's
    # resolution: tests/studies/test_probabilistic_fos.cpp).
    r = dda.fos_samples(scene_dict("random_plane"), samples=12, seed=3, at_factor=1.0)
    assert r["judged"] == 12 and r["variables"] == ["default.friction_angle"]
    phi = r["values"][:, 0]
    clear = np.abs(phi - 30.0) >= 0.15
    assert clear.sum() >= 10
    assert (r["sample_failing"][clear] == (phi[clear] < 30.0)).all()
    assert r["failing"] == int(r["sample_failing"].sum())
    assert r["probability_of_failure"] == pytest.approx(r["failing"] / 12)
    low, high = r["interval"]
    assert low <= r["probability_of_failure"] <= high


def test_the_cut_is_the_command_lines(tmp_path, source_dir):
    model = source_dir / "models" / "small-slope.json"
    scene = dda.cut(model)
    code, err = run_cli("cut", model, "--out", tmp_path / "scene.json")
    assert code == 0, err
    with open(tmp_path / "scene.json") as f:
        cli = json.load(f)
    assert len(scene["blocks"]) == len(cli["blocks"]) == 40
    assert scene["blocks"] == cli["blocks"]
    # The cut's scene runs: a dict straight into a Simulation.
    sim = dda.Simulation(scene)
    assert sim.block_count == 40


def test_a_bad_model_names_the_place():
    with open(__import__("conftest").SOURCE_DIR / "models" / "small-slope.json") as f:
        model = json.load(f)
    model["joint_sets"][0]["spacing"] = -2
    with pytest.raises(dda.InputError, match=r"^model dict: joint_sets\[0\]\.spacing"):
        dda.cut(model)
