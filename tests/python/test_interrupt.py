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
