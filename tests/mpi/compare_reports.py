#!/usr/bin/python3
"""Compares two dda fos report.json files key by key, to the last digit: the report of a run
over MPI ranks against the one-process run's (tests/mpi/run.sh).

Left out: wall times, which no two runs share, and the counts of trials the one-process
search started ahead of a verdict and dropped ("discarded_trials": the ranks' search starts
none). Exit 1, naming the first difference, when anything else differs."""
import json
import sys

SKIPPED = {"wall_time_s", "discarded_trials"}


def differences(a, b, where):
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key in SKIPPED:
                continue
            if key not in a or key not in b:
                yield f"{where}/{key}: only in {'the second' if key not in a else 'the first'}"
                continue
            yield from differences(a[key], b[key], f"{where}/{key}")
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            yield f"{where}: {len(a)} items against {len(b)}"
            return
        for k, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{where}/{k}")
    elif type(a) is not type(b) or a != b:
        yield f"{where}: {a!r} against {b!r}"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare_reports.py SERIAL/report.json RANKS/report.json")
    with open(sys.argv[1]) as f:
        first = json.load(f)
    with open(sys.argv[2]) as f:
        second = json.load(f)
    found = list(differences(first, second, ""))
    for line in found[:20]:
        print("differs:", line)
    if found:
        sys.exit(1)
    print("reports equal (wall times and discarded trials aside)")


if __name__ == "__main__":
    main()
