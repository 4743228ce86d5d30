#!/usr/bin/python3
"""Compares two directories written by scripts/same-results.sh, file by file.

   /usr/bin/python3 scripts/compare_results.py OUT_A OUT_B

Every text file must be the same but for what changes from one run to the next: lines or
JSON keys that hold times (wall, cpu, elapsed, seconds, date), table columns headed by a
time, and paths (the two directories' own names and the repositories they ran from, which
same-results.sh writes to repository.txt). PNG pictures are not compared (each is drawn
from numbers that are). VTK frames (.vtp) are compared by their decoded points, cells and
arrays (verification/vtk_frames.py), so that a binary frame equals an ASCII one of the same
numbers: a baseline written before the frames became binary still compares. Prints each difference (the first five lines of a file) and exits 1
if there is one, 0 if the two runs are the same.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verification"))
import vtk_frames  # noqa: E402  (the repository's reader of both VTK encodings)

TIMING = re.compile(r"(wall|cpu|elapsed|seconds|_s\b|time_s|date|took|ms a|per_step_ms|duration|ns_per|ns per)", re.I)
SECONDS = re.compile(r"\b\d+(\.\d+)?(e-?\d+)? ?(s|ms|min)\b")
SKIP_EXT = {".png"}


def strip_json(value):
    if isinstance(value, dict):
        return {k: strip_json(v) for k, v in value.items() if not TIMING.search(k)}
    if isinstance(value, list):
        return [strip_json(v) for v in value]
    return value


def vtp_lines(path):
    """A frame as text: its points, cells and arrays, numbers with repr (exact)."""
    frame = vtk_frames.read_vtp(path)
    lines = ["points " + " ".join(repr(c) for p in frame["points"] for c in p)]
    for kind in ("verts", "lines", "polys"):
        if frame[kind] is not None:
            connectivity, offsets = frame[kind]
            lines.append("%s %s | %s" % (kind, " ".join(map(str, connectivity)), " ".join(map(str, offsets))))
    for section in ("point_data", "cell_data"):
        for name, (components, values) in frame[section].items():
            lines.append("%s %s %d %s" % (section, name, components, " ".join(repr(float(v)) for v in values)))
    return lines


def text_lines(path, roots, repositories):
    if path.endswith(".vtp"):
        return vtp_lines(path)
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    for r in sorted(roots, key=len, reverse=True):
        text = text.replace(r, "<OUT>")
    for r in sorted(repositories, key=len, reverse=True):
        text = text.replace(r, "<REPOSITORY>")
    text = SECONDS.sub("<t> s", text)
    if path.endswith(".json"):
        try:
            return json.dumps(strip_json(json.loads(text)), indent=1, sort_keys=True).splitlines()
        except ValueError:
            pass
    lines = text.splitlines()
    if path.endswith(".csv") and lines:
        header = lines[0].split(",")
        drop = {i for i, h in enumerate(header) if TIMING.search(h)}
        return [",".join(c for i, c in enumerate(line.split(",")) if i not in drop) for line in lines]
    if path.endswith(".md"):
        return markdown_without_times(lines)
    return [l for l in lines if not TIMING.search(l)]


def markdown_without_times(lines):
    """A table's cells under a header that names a time are left out."""
    kept, drop = [], set()
    for i, line in enumerate(lines):
        if not line.startswith("|"):
            drop = set()
            kept.append(line)
            continue
        cells = line.split("|")
        if i + 1 < len(lines) and lines[i + 1].startswith("|-"):
            drop = {j for j, c in enumerate(cells) if TIMING.search(c) or re.search(r"cpu|time|\(s\)", c, re.I)}
        kept.append("|".join(c for j, c in enumerate(cells) if j not in drop))
    return kept


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    a, b = (os.path.abspath(p) for p in sys.argv[1:])
    roots = [a, b]
    # The repositories the two runs read their scenes from (a worktree's differs from main's).
    repositories = []
    for out in (a, b):
        path = os.path.join(out, "repository.txt")
        if os.path.exists(path):
            repositories.append(open(path).read().strip())
    files = set()
    for root in (a, b):
        for d, _, names in os.walk(root):
            for n in names:
                files.add(os.path.relpath(os.path.join(d, n), root))
    differ = 0
    for rel in sorted(files):
        if os.path.splitext(rel)[1] in SKIP_EXT or rel == "repository.txt":
            continue
        pa, pb = os.path.join(a, rel), os.path.join(b, rel)
        if not (os.path.exists(pa) and os.path.exists(pb)):
            print(f"only in {'A' if os.path.exists(pa) else 'B'}: {rel}")
            differ += 1
            continue
        la, lb = text_lines(pa, roots, repositories), text_lines(pb, roots, repositories)
        if la != lb:
            differ += 1
            shown = 0
            print(f"differs: {rel}")
            for i in range(max(len(la), len(lb))):
                x = la[i] if i < len(la) else "<none>"
                y = lb[i] if i < len(lb) else "<none>"
                if x != y:
                    print(f"  line {i + 1}:\n    A {x[:200]}\n    B {y[:200]}")
                    shown += 1
                    if shown == 5:
                        break
    print(f"{len(files)} files, {differ} differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
