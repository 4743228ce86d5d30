# Errors from the module: bad input raises dda.InputError (a ValueError) with the message
# the command line prints, naming the place; a failed run raises dda.DivergedError.
import json

import pytest

import dda
from conftest import run_cli, scene_dict


def cli_message(tmp_path, scene):
    """What `dda run` says of this scene (after "dda: error: "), its file named FILE."""
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(scene))
    code, err = run_cli("run", path, "--out", tmp_path / "out")
    assert code == 2, err
    line = err.strip().splitlines()[-1]
    assert line.startswith("dda: error: " + str(path) + ": ")
    return line[len("dda: error: " + str(path) + ": "):]


@pytest.mark.parametrize("spoil", [
    lambda s: s["blocks"][1].__setitem__("vertices", [[0, 0], [1, 0]]),
    lambda s: s["materials"]["rock"].__setitem__("poisson", 0.7),
    lambda s: s["joint_materials"]["default"].__setitem__("friction_angle", "steep"),
    lambda s: s["control"].__setitem__("time_step", -1),
    lambda s: s.__setitem__("gravity", [0, -9.81, 0]),
])
def test_a_bad_dict_raises_the_command_lines_message(tmp_path, spoil):
    scene = scene_dict("incline")
    spoil(scene)
    expected = cli_message(tmp_path, scene)
    with pytest.raises(dda.InputError) as raised:
        dda.Simulation(scene)
    assert isinstance(raised.value, ValueError)
    assert str(raised.value) == "scene dict: " + expected
    # A file gives the same message, the file named.
    with pytest.raises(dda.InputError) as raised:
        dda.Simulation(tmp_path / "bad.json")
    assert str(raised.value) == str(tmp_path / "bad.json") + ": " + expected


def test_a_missing_file_and_a_wrong_type_are_input_errors(tmp_path):
    with pytest.raises(dda.InputError, match="nothing.json"):
        dda.Simulation(tmp_path / "nothing.json")
    with pytest.raises(dda.InputError, match="a path to a scene file or a dict"):
        dda.Simulation(42)
    with pytest.raises(dda.InputError, match="cannot be written as JSON"):
        dda.Simulation({"blocks": object()})


def test_numpy_values_in_a_dict_are_read_as_numbers():
    import numpy as np
    scene = scene_dict("incline")
    scene["blocks"][1]["vertices"] = np.array(scene["blocks"][1]["vertices"])
    scene["control"]["end_time"] = np.float64(0.01)
    scene["control"]["output_every"] = np.int64(5)
    sim = dda.Simulation(scene)
    assert sim.run() == 5


def test_bad_fos_settings_name_the_setting():
    with pytest.raises(dda.InputError, match="fos: tolerance"):
        dda.fos(scene_dict("random_plane"), tolerance=2.0)
    with pytest.raises(dda.InputError, match="fos: max_factor"):
        dda.fos(scene_dict("random_plane"), max_factor=float("nan"))
    with pytest.raises(TypeError, match="toleranse"):
        dda.fos(scene_dict("random_plane"), toleranse=0.1)
    with pytest.raises(dda.InputError, match="random_strengths"):
        dda.fos_samples(scene_dict("incline"), samples=3)


def test_a_run_that_fails_raises_diverged_error():
    # The block's weight on its contact springs penetrates them about m g / p = 3e-7 m; an
    # allowed penetration of 1e-9 m without augmentation rounds cannot be met by cutting
    # the step, and the run stops as diverged (exit 3 on the command line).
    scene = scene_dict("incline")
    scene["control"].update({"allowed_penetration": 1e-9, "max_augmentations": 0})
    with pytest.raises(dda.DivergedError) as raised:
        dda.run(scene)
    assert isinstance(raised.value, RuntimeError)
    assert str(raised.value).startswith("the run diverged at step ")
    assert "allowed_penetration" in str(raised.value)
    # The simulation keeps its last good step and refuses to go on.
    sim = dda.Simulation(scene)
    with pytest.raises(dda.DivergedError):
        sim.run()
    kept = sim.step_count
    assert kept > 0
    with pytest.raises(dda.DivergedError):
        sim.step()
    assert sim.step_count == kept
