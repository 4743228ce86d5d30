# dda.Simulation against closed forms and against what `dda run` writes for the same scene.
import csv
import json
import math

import numpy as np
import pytest

import dda
from conftest import run_cli, scene_dict


def test_block_slides_down_the_incline_as_the_closed_form_says():
    # scenes/incline.json: a block on a 30 degree plane, joint friction 20 degrees, dt 2 ms.
    scene = scene_dict("incline")
    scene["control"]["end_time"] = 1.0
    sim = dda.Simulation(scene)
    start = sim.blocks()["centroid"][1].copy()
    sim.run()
    assert sim.finished and sim.time == pytest.approx(1.0, abs=1e-12)
    alpha, phi, g = math.radians(30), math.radians(20), 9.81
    expected = 0.5 * g * (math.sin(alpha) - math.cos(alpha) * math.tan(phi)) * 1.0**2
    down = np.array([-math.cos(alpha), -math.sin(alpha)])
    slid = float((sim.blocks()["centroid"][1] - start) @ down)
    # The block leaves late by a lag of at most dt while its contact springs load up
    # (tests/contact/test_contact_physics.cpp measures 0.52 dt): a relative error of at most
    # 2 dt / t = 0.4 % at 1 s.
    assert slid == pytest.approx(expected, rel=2 * 0.002 / 1.0)
    # The translation is the centroid's motion, and the block does not turn on the plane
    # (a rotation of a few micro-radians from the springs' loading at most).
    b = sim.blocks()
    assert np.allclose(b["translation"][1], b["centroid"][1] - start, atol=1e-12)
    assert abs(b["rotation"][1]) < 1e-4
    # It slides: the contacts under it are in mode 1 (slide) and carry its weight
    # m g cos(alpha) = 2700 x 0.5 x 9.81 x cos 30 N/m between them.
    c = sim.contacts()
    under = c["vertex_block"] == 1
    assert set(c["mode"][under]) == {1}
    assert c["normal_force"][under].sum() == pytest.approx(2700 * 0.5 * g * math.cos(alpha), rel=1e-3)


def history_rows(path, step):
    with open(path) as f:
        return [r for r in csv.DictReader(f) if int(r["step"]) == step]


def test_the_arrays_equal_what_dda_run_writes(tmp_path):
    # The default scene (a pinned bar swinging, an octagon thrown onto a floor: contacts
    # opening and closing) for 120 steps, by the command line and by the module stepping 7
    # at a time: the module keeps the step loop's workspace between calls, so its steps are
    # the command line's, and the numbers are the same to the last bit (history.csv writes
    # the shortest text that reads back as the same double).
    scene = scene_dict("default")
    scene["control"].pop("end_time", None)
    scene["control"]["steps"] = 120
    scene["control"]["output_every"] = 40
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    code, err = run_cli("run", path, "--out", tmp_path / "cli", "--no-picture")
    assert code == 0, err
    sim = dda.Simulation(path)
    while not sim.finished:
        sim.step(7)
    assert sim.step_count == 120
    rows = history_rows(tmp_path / "cli" / "history.csv", 120)
    b, e = sim.blocks(), sim.energy()
    assert len(rows) == len(b["area"]) == sim.block_count
    for i, r in enumerate(rows):
        assert float(r["time"]) == sim.time
        assert [float(r["xc"]), float(r["yc"])] == b["centroid"][i].tolist()
        assert float(r["rotation"]) == b["rotation"][i]
        assert float(r["area"]) == b["area"][i]
        assert [float(r[k]) for k in ("exx", "eyy", "gxy")] == b["strain"][i].tolist()
        assert [float(r[k]) for k in ("sxx", "syy", "sxy")] == b["stress"][i].tolist()
        assert [float(r[k]) for k in ("vx", "vy", "omega")] == b["velocity"][i][:3].tolist()
        for column, term in [("kinetic", "kinetic"), ("potential", "potential"),
                             ("strain_energy", "strain_energy"), ("contact_energy", "contact_energy"),
                             ("load_work", "load_work"), ("friction_dissipation", "friction_dissipation"),
                             ("damping_dissipation", "damping_dissipation"),
                             ("energy_remainder", "remainder")]:
            assert float(r[column]) == e[term], column
    with open(tmp_path / "cli" / "summary.json") as f:
        summary = json.load(f)
    assert summary["steps"] == sim.stats()["steps"] == 120


def test_run_with_out_writes_what_dda_run_writes(tmp_path):
    # dda.run(scene, out) records through the command line's writer: the same history.
    scene = scene_dict("bolted_block")
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    code, err = run_cli("run", path, "--out", tmp_path / "cli", "--no-picture")
    assert code == 0, err
    sim = dda.run(path, out=tmp_path / "py")
    assert sim.finished
    for name in ("history.csv", "bolts.csv"):
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text(), name
    # The bolts' arrays are the last rows of bolts.csv.
    with open(tmp_path / "cli" / "bolts.csv") as f:
        last = [r for r in csv.DictReader(f) if int(r["step"]) == sim.step_count]
    bolts = sim.bolts()
    assert [r["bolt"] for r in last] == bolts["name"]
    assert [float(r["force"]) for r in last] == bolts["force"].tolist()


def test_monitors_equal_monitors_csv(tmp_path):
    # A monitor on the incline's block: the arrays equal monitors.csv's last row, and the
    # displacement is the block's translation (a block that does not turn carries its points
    # with its centroid; 1e-4 rad of rotation moves a point 0.5 m away by 5e-5 m at most).
    scene = scene_dict("incline")
    scene["control"]["end_time"] = 0.2
    scene["monitors"] = [{"name": "corner", "point": [0.0, 0.25]}]
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    code, err = run_cli("run", path, "--out", tmp_path / "cli", "--no-picture")
    assert code == 0, err
    sim = dda.run(scene)
    m = sim.monitors()
    assert m["name"] == ["corner"]
    with open(tmp_path / "cli" / "monitors.csv") as f:
        last = [r for r in csv.DictReader(f)][-1]
    assert int(last["step"]) == sim.step_count
    assert [float(last["x"]), float(last["y"])] == m["position"][0].tolist()
    assert [float(last["ux"]), float(last["uy"])] == m["displacement"][0].tolist()
    assert [float(last["vx"]), float(last["vy"])] == m["velocity"][0].tolist()
    assert np.allclose(m["displacement"][0], sim.blocks()["translation"][1], atol=5e-5)


def test_block_vertices_and_index_errors():
    sim = dda.Simulation(scene_dict("incline"))
    v = sim.block_vertices(1)
    assert v.shape == (4, 2)
    # The polygon's centroid by the shoelace formula is the block's.
    x, y = v[:, 0], v[:, 1]
    cross = x * np.roll(y, -1) - np.roll(x, -1) * y
    area = cross.sum() / 2
    cx = ((x + np.roll(x, -1)) * cross).sum() / (6 * area)
    assert area == pytest.approx(0.5, rel=1e-12)
    assert cx == pytest.approx(sim.blocks()["centroid"][1][0], abs=1e-12)
    with pytest.raises(IndexError):
        sim.block_vertices(2)


def test_run_until_stops_at_the_first_step_past_it_and_goes_on_as_one_run():
    scene = scene_dict("incline")
    scene["control"]["end_time"] = 0.5
    sim = dda.Simulation(scene)
    assert sim.run(until=0.2001) == 101  # dt 2 ms: step 101 ends at 0.202 s, the first past
    assert 0.2001 <= sim.time < 0.2001 + 0.002 and not sim.finished
    assert sim.run(until=0.1) == 0  # already past it
    sim.run()
    whole = dda.run(scene)
    assert sim.step_count == whole.step_count == 250
    # The same steps whether stopped on the way or not, to the last bit.
    for key in ("centroid", "velocity", "stress"):
        assert (sim.blocks()[key] == whole.blocks()[key]).all(), key
    assert sim.energy() == whole.energy()
