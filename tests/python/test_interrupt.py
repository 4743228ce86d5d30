# Ctrl-C during a long call: the call releases the GIL and polls for signals, so SIGINT
# raises KeyboardInterrupt within a fraction of a second, with the state complete.
import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from conftest import SOURCE_DIR

# Long enough that no call ends by itself before the signal: the incline run for 1000 s of
# simulated time (500 000 steps, minutes), a factor whose trials last 1000 s each.
CALLS = {
    "run": "sim = dda.Simulation(scene); before = time.monotonic(); sim.run()",
    "fos": "before = time.monotonic(); dda.fos(plane, trial_time=1000.0)",
}

SCRIPT = """
import json, sys, time
import dda
scene = json.load(open(sys.argv[1]))
scene["control"]["end_time"] = 1000.0
plane = json.load(open(sys.argv[2]))
del plane["random_strengths"]
sim = None
print("ready", flush=True)
try:
    {call}
except KeyboardInterrupt:
    took = time.monotonic() - before
    state = "" if sim is None else f" step {{sim.step_count}} finished {{sim.finished}}"
    print(f"interrupted after {{took:.3f}} s{{state}}", flush=True)
    if sim is not None:
        sim.step(3)  # the state is whole: the run goes on from where it stopped
        print(f"stepped to {{sim.step_count}}", flush=True)
    sys.exit(42)
print("ended by itself", flush=True)
"""


@pytest.mark.parametrize("call", sorted(CALLS))
def test_ctrl_c_raises_keyboard_interrupt_at_once(call):
    env = dict(os.environ)
    proc = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(SCRIPT.format(call=CALLS[call])),
         str(SOURCE_DIR / "scenes" / "incline.json"), str(SOURCE_DIR / "scenes" / "random_plane.json")],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        assert proc.stdout.readline().strip() == "ready"
        time.sleep(1.0)  # well inside the call
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=10)
        answered = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 42, (out, err)
    assert out.startswith("interrupted after "), out
    # The signal is seen within the poll interval (50 ms) plus the step or trial step that
    # runs when it comes (milliseconds here) and the interpreter's exit; 3 s is the bound a
    # person waiting on Ctrl-C would call prompt, far below the calls' own length.
    assert answered < 3.0, answered
    if call == "run":
        words = out.split()
        step = int(words[words.index("step") + 1])
        assert step > 0 and "finished False" in out
        assert f"stepped to {step + 3}" in out


def test_a_run_releases_the_gil_and_refuses_a_second_caller():
    # A block at rest on the incline (friction 40 degrees > 30) for 20 000 steps, about
    # half a second, in a thread: the main thread runs meanwhile (the GIL is released), and
    # reading the simulation while it steps is refused rather than left to race.
    import json
    import threading
    import dda
    scene = json.load(open(SOURCE_DIR / "scenes" / "incline.json"))
    scene["joint_materials"]["default"]["friction_angle"] = 40.0
    scene["control"]["end_time"] = 40.0
    sim = dda.Simulation(scene)
    worker = threading.Thread(target=sim.run)
    worker.start()
    refused = False
    while worker.is_alive() and not refused:
        try:
            sim.blocks()
        except RuntimeError as e:
            refused = "another thread" in str(e)
        time.sleep(0.01)
    worker.join()
    assert refused
    assert sim.finished and sim.step_count == 20000
    # At rest on the plane: it has not moved beyond its contact springs' compliance
    # (m g / p = 2700 x 0.5 x 9.81 / 5e10 = 2.6e-7 m).
    assert abs(sim.blocks()["translation"][1]).max() < 1e-5
