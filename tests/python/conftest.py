# Shared by the Python module's tests (tests/python): where the repository and the dda
# executable are (ctest passes them in DDA_SOURCE_DIR and DDA_EXE; run by hand, the
# release build's), and the repository's scenes as dicts.
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("DDA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DDA_EXE = os.environ.get("DDA_EXE", str(SOURCE_DIR / "build" / "release" / "dda"))


def scene_dict(name):
    """scenes/NAME.json as a dict."""
    with open(SOURCE_DIR / "scenes" / f"{name}.json") as f:
        return json.load(f)


def run_cli(*args):
    """The dda executable with these arguments: (exit code, stderr)."""
    done = subprocess.run([DDA_EXE, *map(str, args)], capture_output=True, text=True, timeout=300)
    return done.returncode, done.stderr


@pytest.fixture
def source_dir():
    return SOURCE_DIR
