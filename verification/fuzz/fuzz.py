#!/usr/bin/python3
"""Mutation fuzzing of dda's four commands with faults injected (verification/fuzz/README.md).

Each mutant is a seed input (a scene, a model, a material-point spec, or a scene for dda fos)
changed by one to three mutations, JSON-aware (a number made extreme, a key dropped or renamed,
a list emptied or repeated, a value of the wrong type, a subtree from another seed) or
byte-level (a cut, a flipped byte, a deleted run). Some mutants are also run under a fault: a
file-size limit, SIGTERM or SIGINT at a random moment, /dev/full as an output, an output path
that is a regular file where a directory is wanted, or a timeout.

After every run the checks on faults and hostile inputs are applied:
  crash      exit by a signal not sent, an exit code outside the README's table, or a
             sanitizer report;
  silent     a non-zero exit with nothing on standard error;
  truncated  a file left under its final name that does not read back whole (JSON that does
             not parse, a CSV row with the wrong number of fields or without its newline, a
             VTK file that is not whole XML, a PNG without its end chunk), a leftover *.tmp,
             or nan/inf written;
  memory     peak resident memory above the limit (--memory-mib);
  hang       still running 20 s after SIGTERM.
A mutant that runs past --timeout is stopped with SIGTERM and counted as "long" (not a
finding: a mutated end_time may ask for a long run), but it must then stop, with whole files.

Usage: fuzz.py --dda PATH --root REPO --out DIR [--seeds N] [--mutants M] [--jobs J]
Exit 0 when no finding, 1 otherwise; DIR/report.md and DIR/report.json list everything and
DIR/findings/ keeps each finding's input, command line and standard error.
"""
import argparse
import concurrent.futures
import copy
import json
import math
import os
import random
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET

# The reader of the run's VTK frames, beside this directory (verification/vtk_frames.py).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import vtk_frames  # noqa: E402

ALLOWED_EXITS = {0, 1, 2, 3}
SIGNAL_EXITS = {130, 143}


class Raw:
    """A token written as is (numbers JSON cannot hold, or that Python would round)."""

    def __init__(self, text):
        self.text = text


def dump(value):
    if isinstance(value, Raw):
        return value.text
    if isinstance(value, bool) or value is None:
        return json.dumps(value)
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else "1e999"
    if isinstance(value, (int, str)):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(dump(v) for v in value) + "]"
    return "{" + ", ".join(json.dumps(k) + ": " + dump(v) for k, v in value.items()) + "}"


# ---- mutations ------------------------------------------------------------------------------

def nodes(value, path=()):
    """Every (path, value) in a JSON tree, the root included."""
    yield path, value
    if isinstance(value, dict):
        for k, v in value.items():
            yield from nodes(v, path + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from nodes(v, path + (i,))


def get(tree, path):
    for p in path:
        tree = tree[p]
    return tree


def put(tree, path, value):
    if not path:
        return value
    get(tree, path[:-1])[path[-1]] = value
    return tree


def extreme_number(rng, old):
    choices = [0, -0.0, -1, 1, 0.5, 1e-320, 1e-12, 1e-9, 1e9, 1e12, 1e15, 1e16, 1e18, 1e19,
               1e100, 1e300, -1e300, Raw("1e999"), Raw("-1e999"), Raw("18446744073709551617"),
               Raw("NaN"), Raw("0.4999999999"), Raw("1e-400"), 2 ** 31, -2 ** 31, 64, 65]
    if isinstance(old, (int, float)) and not isinstance(old, bool) and rng.random() < 0.5:
        k = rng.choice([-12, -6, -3, -1, 1, 2, 3, 6, 8, 12])
        return old * 10.0 ** k * rng.choice([1, -1])
    return rng.choice(choices)


def wrong_type(rng, vocab):
    return rng.choice([None, True, False, "", "x" * rng.choice([1, 100, 100000]), {}, [],
                       [[]], [0, 0], {"a": 1}, rng.choice(vocab["strings"]),
                       Raw('"\\ud800"'), Raw('"\\u0000"')])


def mutate_tree(rng, tree, vocab, other_trees):
    where = list(nodes(tree))
    path, value = rng.choice(where)
    op = rng.random()
    if isinstance(value, (int, float)) and not isinstance(value, bool) and op < 0.6:
        return put(tree, path, extreme_number(rng, value))
    if isinstance(value, str) and op < 0.5:
        return put(tree, path, rng.choice(vocab["strings"] + ["", "x" * 100000, "Ω", "default"]))
    if isinstance(value, list) and op < 0.6:
        kind = rng.randrange(6)
        if kind == 0:
            return put(tree, path, [])
        if kind == 1 and value:
            value.pop(rng.randrange(len(value)))
            return tree
        if kind == 2 and value:
            value.insert(rng.randrange(len(value) + 1), copy.deepcopy(rng.choice(value)))
            return tree
        if kind == 3:
            value.reverse()
            return tree
        if kind == 4 and value:
            n = rng.choice([10, 200, 3000])
            return put(tree, path, [copy.deepcopy(value[i % len(value)]) for i in range(n)])
        if kind == 5:
            return put(tree, path, [value])
    if isinstance(value, dict) and op < 0.7:
        kind = rng.randrange(5)
        if kind == 0 and value:
            del value[rng.choice(list(value))]
            return tree
        if kind == 1:
            value[rng.choice(vocab["keys"])] = copy.deepcopy(
                rng.choice(list(nodes(rng.choice(other_trees))))[1])
            return tree
        if kind == 2 and value:
            old = rng.choice(list(value))
            value[rng.choice(vocab["keys"] + ["k" * 100000, "", old.upper()])] = value.pop(old)
            return tree
        if kind == 3:
            value["unknown_" + str(rng.randrange(100))] = 1
            return tree
        if kind == 4 and value:
            k = rng.choice(list(value))
            value[k] = wrong_type(rng, vocab)
            return tree
    if path and op < 0.85:
        return put(tree, path, wrong_type(rng, vocab))
    if path:
        # A subtree of the same key from another seed (a block from a scene into a model ...).
        donor = rng.choice(other_trees)
        same = [v for p, v in nodes(donor) if p and p[-1] == path[-1]]
        if same:
            return put(tree, path, copy.deepcopy(rng.choice(same)))
    return tree


def mutate_bytes(rng, text):
    data = bytearray(text.encode("utf-8"))
    if not data:
        return bytes(data)
    kind = rng.randrange(5)
    i = rng.randrange(len(data))
    if kind == 0:
        return bytes(data[:i])                                   # cut short
    if kind == 1:
        data[i] = rng.randrange(256)                             # a flipped byte
    elif kind == 2:
        del data[i:i + rng.randrange(1, 40)]                      # a deleted run
    elif kind == 3:
        data[i:i] = bytes(rng.choice([b"[" * 200, b"{\"a\":" * 70, b"\x00", b"\xff\xfe",
                                      b",", b"]", b"\"", b"-", b"e", b"9" * 400]))
    else:
        data = data + data                                        # two documents
    return bytes(data)


def mild(rng, tree):
    """A number scaled by 0.5 to 2: mostly still valid, so that the run, and the faults
    injected into it, are exercised and not only the reader."""
    numbers = [p for p, v in nodes(tree)
               if p and isinstance(v, (int, float)) and not isinstance(v, bool)]
    if numbers:
        path = rng.choice(numbers)
        put(tree, path, get(tree, path) * rng.uniform(0.5, 2.0))
    return tree


def make_mutant(rng, seed_tree, vocab, other_trees):
    tree = copy.deepcopy(seed_tree)
    style = rng.random()
    if style < 0.1:
        return dump(tree).encode("utf-8")          # the seed itself, under a fault
    if style < 0.4:
        for _ in range(rng.choice([1, 2, 3])):
            tree = mild(rng, tree)
        return dump(tree).encode("utf-8")
    for _ in range(rng.choice([1, 1, 2, 3])):
        tree = mutate_tree(rng, tree, vocab, other_trees)
    text = dump(tree)
    if rng.random() < 0.15:
        return mutate_bytes(rng, text)
    return text.encode("utf-8")


def vocabulary(trees):
    keys, strings = set(), set()
    for t in trees:
        for p, v in nodes(t):
            if p and isinstance(p[-1], str):
                keys.add(p[-1])
            if isinstance(v, str) and len(v) < 40:
                strings.add(v)
    return {"keys": sorted(keys), "strings": sorted(strings)}


# ---- faults and commands --------------------------------------------------------------------

def command_line(rng, kind, dda, inp, work):
    """The command, its output path, and the fault to inject (name, detail)."""
    fault = rng.choices(["none", "signal", "fsize", "outfile", "devfull"],
                        [55, 15, 15, 7, 8])[0]
    out = os.path.join(work, "out")
    if kind in ("cut", "material-point"):
        out = os.path.join(work, "out.json" if kind == "cut" else "out.csv")
    args = [dda, kind, inp, "--out", out]
    detail = None
    if kind == "fos":
        args += ["--jobs", str(rng.choice([1, 2])), "--tolerance", str(rng.choice([0.05, 0.1, 0.2]))]
        if rng.random() < 0.3:
            args += ["--method", "limit-analysis"]
        if rng.random() < 0.2:
            opt = rng.choice(["--min-factor", "--max-factor", "--trial-time", "--failure-displacement",
                              "--seismic-coefficient", "--consolidation-factor", "--dynamic-coefficient"])
            args += [opt, rng.choice(["0", "-1", "1e-300", "nan", "inf", "0.5", "2", "1e9", "x", ""])]
    if fault == "outfile":
        # A regular file where the output goes: a directory is wanted for run and fos; for cut
        # and material-point it is simply replaced, so point them at a directory instead.
        if kind in ("run", "fos"):
            with open(out, "w") as f:
                f.write("keep me\n")
            detail = "keep me\n"
        else:
            os.makedirs(out)
    elif fault == "devfull":
        if kind in ("cut", "material-point"):
            args[4] = "/dev/full"
        else:
            os.makedirs(out)
            target = rng.choice(["history.csv", "summary.json", "report.json", "report.md"])
            os.symlink("/dev/full", os.path.join(out, target))
            detail = target
    elif fault == "fsize":
        detail = rng.choice([1, 100, 1000, 5000, 20000, 100000, 400000])
    elif fault == "signal":
        detail = (rng.choice([signal.SIGTERM, signal.SIGINT]),
                  rng.choice([rng.uniform(0.0, 0.02), rng.uniform(0.0, 0.3)]))
    return args, out, fault, detail


def handlers_installed(pid, signum, wait_for):
    """Waits until the program catches `signum` (its SigCgt bit in /proc), or has ended.
    A signal before that, while the dynamic loader runs, ends any program by its default
    action, with nothing said: not the program's doing, so not sent."""
    while True:
        try:
            with open("/proc/%d/status" % pid) as f:
                caught = next(int(l.split()[1], 16) for l in f if l.startswith("SigCgt:"))
        except (OSError, StopIteration):
            return False
        if caught >> (signum - 1) & 1:
            return True
        if wait_for(0.001):
            return False


def run_one(args, fault, detail, timeout, memory_mib, sanitized):
    def limits():
        if fault == "fsize":
            resource.setrlimit(resource.RLIMIT_FSIZE, (detail, detail))
        if not sanitized:
            cap = int((memory_mib + 1024) * 1024 * 1024)  # address space: a hard stop past the check
            resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
    env = dict(os.environ)
    env.setdefault("ASAN_OPTIONS", "detect_leaks=0")
    start = time.monotonic()
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            preexec_fn=limits, env=env)
    sent, long_run, hang = None, False, False
    stderr_chunks = []
    reader = threading.Thread(target=lambda: stderr_chunks.append(proc.stderr.read()))
    reader.start()
    status, usage = None, None

    def wait_for(seconds):
        # os.wait4 rather than Popen.wait: it gives this child's own peak memory. Signals go
        # by os.kill, not Popen.send_signal, which polls and could reap the child first.
        nonlocal status, usage
        end = time.monotonic() + seconds
        while True:
            pid, st, ru = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                status, usage = st, ru
                proc.returncode = os.waitstatus_to_exitcode(st)
                return True
            if time.monotonic() >= end:
                return False
            time.sleep(0.002)

    if fault == "signal" and handlers_installed(proc.pid, detail[0], wait_for) and \
            not wait_for(detail[1]):
        os.kill(proc.pid, detail[0])
        sent = detail[0]
    if status is None and not wait_for(timeout):
        long_run = True
        os.kill(proc.pid, signal.SIGTERM)
        sent = signal.SIGTERM
        if not wait_for(20):
            hang = True
            os.kill(proc.pid, signal.SIGKILL)
            wait_for(60)
    reader.join()
    rss = usage.ru_maxrss / 1024 if usage else None
    return proc.returncode, sent, long_run, hang, b"".join(stderr_chunks).decode("utf-8", "replace"), \
        time.monotonic() - start, rss


# ---- checks ---------------------------------------------------------------------------------

def no_special(text):
    return not re.search(r"(?<![A-Za-z_])(nan|-?inf|infinity)(?![A-Za-z_])", text, re.IGNORECASE)


def strict_json(text):
    def refuse(token):
        raise ValueError("non-finite " + token)
    json.loads(text, parse_constant=refuse)


def check_file(path):
    """What is wrong with a file left under its final name, or None."""
    if path.endswith(".tmp"):
        return "leftover temporary file"
    try:
        data = open(path, "rb").read()
    except OSError as e:
        return "unreadable: %s" % e
    name = os.path.basename(path)
    try:
        if name.endswith(".json"):
            strict_json(data.decode("utf-8"))
        elif name.endswith(".csv"):
            text = data.decode("utf-8")
            if text and not text.endswith("\n"):
                return "CSV does not end with a newline"
            rows = text.splitlines()
            if rows:
                width = rows[0].count(",")
                bad = [i for i, r in enumerate(rows) if r.count(",") != width]
                if bad:
                    return "CSV row %d has %d fields, the header %d" % (
                        bad[0] + 1, rows[bad[0]].count(",") + 1, width + 1)
            if not no_special(text):
                return "CSV holds nan or inf"
        elif name.endswith(".vtp"):
            # Either encoding (binary by default): read every array back, then look at the
            # numbers themselves, since a binary file's bytes are no text to search.
            frame = vtk_frames.parse_vtp(data, name)
            numbers = [c for p in frame["points"] for c in p]
            for section in ("point_data", "cell_data"):
                for _, values in frame[section].values():
                    numbers += values
            if not all(math.isfinite(x) for x in numbers):
                return "VTK file holds nan or inf"
        elif name.endswith((".pvd", ".vtu")):
            ET.fromstring(data)
            if not no_special(data.decode("utf-8", "replace")):
                return "VTK file holds nan or inf"
        elif name.endswith(".png"):
            if not data.startswith(b"\x89PNG\r\n\x1a\n") or b"IEND" not in data[-12:]:
                return "PNG not whole"
        elif name.endswith(".md"):
            if data and not data.endswith(b"\n"):
                return "Markdown report does not end with a newline"
    except Exception as e:  # noqa: BLE001 - any failure to read back is the finding
        return "does not read back: %s" % str(e)[:200]
    return None


def check_outputs(out, kind, fault, detail):
    problems = []
    if fault == "outfile" and kind in ("run", "fos"):
        if not os.path.isfile(out) or open(out).read() != detail:
            problems.append("truncated: the regular file at --out was changed")
        return problems
    if fault == "devfull" and not stat.S_ISCHR(os.stat("/dev/full").st_mode):
        problems.append("crash: /dev/full is no longer a device")
    paths = []
    if os.path.isdir(out):
        for d, _, files in os.walk(out):
            paths += [os.path.join(d, f) for f in files]
    elif os.path.isfile(out):
        paths.append(out)
    folder = os.path.dirname(out)
    paths += [os.path.join(folder, f) for f in os.listdir(folder) if f.endswith(".tmp")]
    for p in paths:
        if os.path.islink(p):
            continue
        why = check_file(p)
        if why:
            problems.append("truncated: %s: %s" % (os.path.relpath(p, folder), why))
    return problems


def judge(kind, rc, sent, long_run, hang, stderr, rss, memory_mib, sanitized):
    findings = []
    if hang:
        findings.append("hang: still running 20 s after SIGTERM")
    if rc is None or rc < 0:
        if not (sent is not None and rc == -sent) and not hang:
            findings.append("crash: killed by signal %s" % (-rc if rc is not None else "?"))
    elif rc not in ALLOWED_EXITS and not (sent is not None and rc in SIGNAL_EXITS):
        findings.append("crash: exit code %d" % rc)
    if rc not in (0, None) and not stderr.strip():
        findings.append("silent: exit %s with nothing on standard error" % rc)
    if re.search(r"AddressSanitizer|LeakSanitizer|runtime error:|UndefinedBehaviorSanitizer", stderr):
        findings.append("crash: sanitizer report")
    if re.search(r"terminate called|std::bad_alloc|Assertion", stderr):
        findings.append("crash: %s" % re.search(r"terminate called|std::bad_alloc|Assertion",
                                                stderr).group(0))
    if rss is not None and rss > memory_mib and not sanitized:
        findings.append("memory: peak %.0f MiB" % rss)
    return findings


# ---- campaign -------------------------------------------------------------------------------

def load_seeds(root, work):
    seeds = {"run": [], "cut": [], "material-point": [], "fos": []}
    for f in sorted(os.listdir(os.path.join(root, "scenes"))):
        seeds["run"].append(json.load(open(os.path.join(root, "scenes", f))))
    for f in sorted(os.listdir(os.path.join(root, "models"))):
        seeds["cut"].append(json.load(open(os.path.join(root, "models", f))))
    specs = os.path.join(root, "verification", "constitutive", "specs")
    for f in sorted(os.listdir(specs)):
        seeds["material-point"].append(json.load(open(os.path.join(specs, f))))
    # fos: the incline (one block, a closed form) and the small slope cut into 40 blocks.
    seeds["fos"].append(json.load(open(os.path.join(root, "scenes", "incline.json"))))
    seeds["fos"].append(json.load(open(os.path.join(work, "small-slope-scene.json"))))
    seeds["run"].append(seeds["fos"][-1])
    return seeds


def one_mutant(job):
    (index, kind, campaign_seed, seed_index, text_seed, dda, work_root, timeout, memory_mib,
     sanitized, seeds, vocab) = job
    rng = random.Random("%d/%d" % (campaign_seed, index))
    seed_tree = seeds[kind][seed_index % len(seeds[kind])]
    others = [t for k in seeds for t in seeds[k]]
    data = make_mutant(rng, seed_tree, vocab, others)
    work = os.path.join(work_root, "m%06d" % index)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    inp = os.path.join(work, "input.json")
    with open(inp, "wb") as f:
        f.write(data)
    args, out, fault, detail = command_line(rng, kind, dda, inp, work)
    rc, sent, long_run, hang, stderr, seconds, rss = run_one(args, fault, detail, timeout,
                                                             memory_mib, sanitized)
    findings = judge(kind, rc, sent, long_run, hang, stderr, rss, memory_mib, sanitized)
    findings += check_outputs(out, kind, fault, detail)
    record = {"index": index, "kind": kind, "seed": seed_index % len(seeds[kind]), "fault": fault,
              "fault_detail": str(detail) if not isinstance(detail, tuple)
              else "%s after %.3f s" % (signal.Signals(detail[0]).name, detail[1]),
              "exit": rc, "signal_sent": int(sent) if sent else None, "long": long_run,
              "seconds": round(seconds, 3), "peak_mib": round(rss, 1) if rss else None,
              "first_message": (stderr.strip().splitlines() or [""])[-1][:300],
              "findings": findings}
    if findings:
        keep = os.path.join(work_root, "..", "findings", "m%06d" % index)
        shutil.rmtree(keep, ignore_errors=True)
        os.makedirs(keep)
        shutil.copy(inp, os.path.join(keep, "input.json"))
        with open(os.path.join(keep, "command.txt"), "w") as f:
            f.write(" ".join(args) + "\nfault: %s %s\n" % (fault, record["fault_detail"]))
        with open(os.path.join(keep, "stderr.txt"), "w") as f:
            f.write(stderr)
    shutil.rmtree(work, ignore_errors=True)
    return record


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dda", required=True)
    ap.add_argument("--root", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seeds", type=int, default=13, help="campaign seeds (each makes --mutants)")
    ap.add_argument("--mutants", type=int, default=250, help="mutants per campaign seed")
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=10.0)
    ap.add_argument("--memory-mib", type=float, default=1024.0)
    ap.add_argument("--sanitized", action="store_true", help="the program is an ASan build")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    work_root = os.path.join(out, "work")
    shutil.rmtree(work_root, ignore_errors=True)
    shutil.rmtree(os.path.join(out, "findings"), ignore_errors=True)
    os.makedirs(work_root)
    cut = subprocess.run([a.dda, "cut", os.path.join(a.root, "models", "small-slope.json"),
                          "--out", os.path.join(work_root, "small-slope-scene.json")],
                         capture_output=True, text=True)
    if cut.returncode != 0:
        sys.exit("fuzz.py: the seed scene could not be cut: " + cut.stderr)
    seeds = load_seeds(a.root, work_root)
    vocab = vocabulary([t for k in seeds for t in seeds[k]])
    kinds = ["run", "cut", "material-point", "fos"]
    weights = [40, 25, 15, 20]
    jobs = []
    index = 0
    for s in range(a.first_seed, a.first_seed + a.seeds):
        pick = random.Random(s)
        for _ in range(a.mutants):
            kind = pick.choices(kinds, weights)[0]
            jobs.append((index, kind, s, pick.randrange(1000), 0, a.dda, work_root, a.timeout,
                         a.memory_mib, a.sanitized, seeds, vocab))
            index += 1
    start = time.monotonic()
    records = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for r in pool.map(one_mutant, jobs):
            records.append(r)
            if r["findings"]:
                print("finding m%06d %s: %s" % (r["index"], r["kind"], "; ".join(r["findings"])),
                      flush=True)
    wall = time.monotonic() - start
    write_report(out, records, wall, a)
    shutil.rmtree(work_root, ignore_errors=True)
    sys.exit(1 if any(r["findings"] for r in records) else 0)


def write_report(out, records, wall, a):
    def count(pred):
        return sum(1 for r in records if pred(r))
    table = []
    for kind in ["run", "cut", "material-point", "fos"]:
        rs = [r for r in records if r["kind"] == kind]
        table.append("| %s | %d | %d | %d | %d | %d | %d | %d | %d |" % (
            kind, len(rs), count(lambda r: r in rs and r["exit"] == 0),
            count(lambda r: r in rs and r["exit"] == 1), count(lambda r: r in rs and r["exit"] == 2),
            count(lambda r: r in rs and r["exit"] == 3),
            count(lambda r: r in rs and r["exit"] in SIGNAL_EXITS),
            count(lambda r: r in rs and r["long"]), count(lambda r: r in rs and r["findings"])))
    faults = {}
    for r in records:
        faults[r["fault"]] = faults.get(r["fault"], 0) + 1
    peak = max((r["peak_mib"] or 0) for r in records) if records else 0
    slowest = max(records, key=lambda r: r["seconds"]) if records else None
    found = [r for r in records if r["findings"]]
    lines = ["# Mutation fuzzing of dda run, cut, material-point and fos", "",
             "Program: `%s`%s. Campaign seeds %d to %d, %d mutants each: %d mutants in %.0f s "
             "(%d at once), timeout %.0f s, memory limit %.0f MiB." % (
                 a.dda, " (sanitized build)" if a.sanitized else "", a.first_seed,
                 a.first_seed + a.seeds - 1, a.mutants, len(records), wall, a.jobs, a.timeout,
                 a.memory_mib), "",
             "| command | mutants | exit 0 | exit 1 | exit 2 | exit 3 | 130/143 | long | findings |",
             "|---|---|---|---|---|---|---|---|---|"] + table + [
             "", "Faults injected: " + ", ".join("%s %d" % kv for kv in sorted(faults.items())) + ".",
             "Peak resident memory of any run: %.0f MiB; slowest run %.1f s (m%06d, %s)." % (
                 peak, slowest["seconds"] if slowest else 0, slowest["index"] if slowest else 0,
                 slowest["kind"] if slowest else ""), "",
             "## Findings", ""]
    if not found:
        lines.append("None: no crash, no exit without a message, no file cut short under its "
                     "final name, no run past the memory limit, no hang.")
    for r in found:
        lines.append("- m%06d %s (seed %d, fault %s %s, exit %s): %s" % (
            r["index"], r["kind"], r["seed"], r["fault"], r["fault_detail"], r["exit"],
            "; ".join(r["findings"])))
    with open(os.path.join(out, "report.md.tmp"), "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(os.path.join(out, "report.md.tmp"), os.path.join(out, "report.md"))
    with open(os.path.join(out, "report.json.tmp"), "w") as f:
        json.dump({"mutants": len(records), "seconds": wall, "records": records}, f, indent=1)
    os.replace(os.path.join(out, "report.json.tmp"), os.path.join(out, "report.json"))


if __name__ == "__main__":
    main()
