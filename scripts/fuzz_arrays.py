#!/usr/bin/env python3
"""Fuzzes the Python array path of meshdiff (issue 33): V and F arrays made from
a small valid mesh with seeded mutations (NaN, inf, +-1e80, coordinates just
beyond and within the limit of 1e30, huge or negative or out-of-range face
indices, degenerate and repeated faces, collapsed vertices, odd dtypes and
shapes), through compare(), surface_distance(), profile(), mean_curvature(),
roughness() and DistanceIndex. Every call must return, or raise ValueError /
TypeError; a crash (the worker dies), another exception, or a call that takes
longer than --timeout seconds (a hang) fails the run and prints the trial's
seed, which is then added to tests/fuzz/regressions/arrays.txt (replayed first
on every run).

    python3 scripts/fuzz_arrays.py 45            # 45 s of trials (scripts/test.sh)
    python3 scripts/fuzz_arrays.py --trial 1234  # one trial, in this process

The module is the one of $MESHDIFF_BUILD_DIR (default build/) under python/.
"""
import argparse
import itertools
import os
import pathlib
import queue
import subprocess
import sys
import threading
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
REGRESSIONS = REPO / "tests" / "fuzz" / "regressions" / "arrays.txt"


def base_mesh():
    import numpy as np
    # An octahedron subdivided once: 18 vertices, 32 faces, closed.
    V = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    F = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    V = [np.array(v, float) for v in V]
    mid = {}
    out = []
    for a, b, c in F:
        def m(i, j):
            key = (min(i, j), max(i, j))
            if key not in mid:
                p = (V[i] + V[j]) / 2
                V.append(p / np.linalg.norm(p))
                mid[key] = len(V) - 1
            return mid[key]
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return np.array(V), np.array(out, dtype=np.int64)


def mutate(rng, V, F):
    import numpy as np
    V, F = V.copy(), F.copy()
    kind = rng.integers(0, 16)
    i = int(rng.integers(0, len(V)))
    f = int(rng.integers(0, len(F)))
    special = [np.nan, np.inf, -np.inf, 1e80, -1e80, 1e31, 1e29, 1e-300, 5e-324, 0.0, 1e154, 1e200]
    if kind == 0:
        V[i, rng.integers(0, 3)] = special[rng.integers(0, len(special))]
    elif kind == 1:
        V = V * special[rng.integers(3, len(special))]
    elif kind == 2:
        F[f, rng.integers(0, 3)] = [-1, len(V), 2**31, 2**62, -2**62][rng.integers(0, 5)]
    elif kind == 3:
        F[f] = F[f, 0]  # a face with one corner thrice
    elif kind == 4:
        F = np.vstack([F, F[:3]])  # repeated faces
    elif kind == 5:
        V[:] = V[0]  # every vertex at one place
    elif kind == 6:
        F = F[: rng.integers(0, 3)]  # few or no faces
    elif kind == 7:
        V = V.astype([np.float32, np.int32, np.float16, np.uint8][rng.integers(0, 4)])
    elif kind == 8:
        F = F.astype([np.uint64, np.int8, np.float64, np.uint32][rng.integers(0, 4)])
    elif kind == 9:
        V = V[:, :2] if rng.integers(0, 2) else V.reshape(-1)
    elif kind == 10:
        V = V + rng.normal(0, 10.0 ** rng.integers(-12, 3), V.shape)
    elif kind == 11:
        V = V[: rng.integers(0, len(V))]  # faces refer past the end
    elif kind == 12:
        V = np.vstack([V, [[1e30, 1e30, 1e30]]])  # an isolated vertex at the limit
    elif kind == 13:
        F = F[:, ::-1]  # flipped orientation
    elif kind == 14:
        V = np.asfortranarray(V)[::1]
    else:
        V = V * -1e30  # at the limit, mirrored
    return V, F


def trial(seed):
    """One trial: a mutated pair through every array function."""
    import numpy as np
    import meshdiff
    rng = np.random.default_rng(seed)
    V, F = base_mesh()
    V1, F1 = mutate(rng, V, F)
    V2, F2 = mutate(rng, V, F) if rng.integers(0, 2) else (V, F)
    calls = [
        lambda: meshdiff.compare(V1, F1, V2, F2, samples=300, levels=[1, 2]),
        lambda: meshdiff.compare(V1, None, V2, F2, samples=300, roughness=False),
        lambda: meshdiff.surface_distance(V1, F1, V2, F2, samples=300),
        lambda: meshdiff.profile(V1, F1, levels=[1, 3], radii=[0.2]),
        lambda: meshdiff.mean_curvature(V1, F1),
        lambda: meshdiff.roughness(V1, F1, levels=[1]),
        lambda: meshdiff.DistanceIndex(V2, F2).query(V1 if getattr(V1, "ndim", 0) == 2 else V),
    ]
    for call in calls:
        try:
            call()
        except (ValueError, TypeError):
            pass


def worker(seeds):
    """Runs the trials of \p seeds (an iterable), printing each seed before it starts."""
    sys.path.insert(0, str(pathlib.Path(os.environ.get("MESHDIFF_BUILD_DIR", REPO / "build")) / "python"))
    for s in seeds:
        print(s, flush=True)
        trial(int(s))
    print("end", flush=True)


def run_worker(args, timeout, deadline):
    """A worker process on \p args; returns (how it ended, the seed it was on, trials started, why):
    "end", "deadline", "hang" (a trial over \p timeout s) or "died"."""
    p = subprocess.Popen([sys.executable, __file__, "--worker", *args], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    lines = queue.Queue()
    threading.Thread(target=lambda: [lines.put(l.strip()) for l in p.stdout] + [lines.put(None)], daemon=True).start()
    current, started, trials = None, time.monotonic(), 0
    while True:
        try:
            line = lines.get(timeout=0.05)
        except queue.Empty:
            line = ""
        if line is None:  # the worker's stdout closed: it ended or died
            p.wait()
            return "died", current, trials, f"exit {p.returncode}: {p.stderr.read()[-2000:]}"
        if line == "end":
            p.wait()
            return "end", current, trials, ""
        if line:
            current, started, trials = int(line), time.monotonic(), trials + 1
        now = time.monotonic()
        if now - started > timeout:
            p.kill()
            p.wait()
            return "hang", current, trials, f"more than {timeout} s"
        if deadline is not None and now >= deadline:
            p.kill()
            p.wait()
            return "deadline", current, trials, ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("seconds", nargs="?", type=float, default=45.0)
    ap.add_argument("--timeout", type=float, default=20.0, help="the longest one trial may take")
    ap.add_argument("--trial", type=int, help="run one trial here, and show what it raises")
    ap.add_argument("--worker", nargs=argparse.REMAINDER, help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.worker is not None:
        if a.worker[0] == "from":
            worker(itertools.count(int(a.worker[1])))
        else:
            worker(a.worker)
        return 0
    if a.trial is not None:
        sys.path.insert(0, str(pathlib.Path(os.environ.get("MESHDIFF_BUILD_DIR", REPO / "build")) / "python"))
        trial(a.trial)
        return 0
    failures, total = [], 0
    # Every trial that ever failed, first.
    replay = REGRESSIONS.read_text().split() if REGRESSIONS.exists() else []
    while replay:
        how, seed, n, why = run_worker(replay, a.timeout, None)
        total += n
        if how == "end":
            break
        failures.append((seed, f"{how}: {why}"))
        replay = replay[replay.index(str(seed)) + 1:]
    # Then new seeded trials until the time is up.
    deadline, first = time.monotonic() + a.seconds, 1
    while time.monotonic() < deadline:
        how, seed, n, why = run_worker(["from", str(first)], a.timeout, deadline)
        total += n
        if how in ("deadline", "end"):
            break
        failures.append((seed, f"{how}: {why}"))
        first = seed + 1
    print(f"fuzz arrays: {total} trials ({len(REGRESSIONS.read_text().split()) if REGRESSIONS.exists() else 0} "
          f"replayed), {len(failures)} failures")
    for seed, why in failures:
        print(f"fuzz arrays: trial {seed} failed: {why}\n  (run it: python3 scripts/fuzz_arrays.py --trial {seed}; "
              f"add {seed} to {REGRESSIONS.relative_to(REPO)})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
