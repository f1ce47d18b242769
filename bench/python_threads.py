#!/usr/bin/env python3
"""Two Python threads running two compares at once, against the same two run one
after the other (issue 32: the GIL is released, so the threads overlap).

Prints the median over the runs of the serial and the threaded wall time and
their ratio threaded / serial (1.0: no overlap; 0.5: perfect on 2 cores). Each
compare runs with threads=1 (one OpenMP thread), so the two Python threads are
the only parallelism.

Usage: python3 bench/python_threads.py [ORIGINAL PROCESSED] [--runs N]
(default: tests/data/bunny_res3.ply tests/data/bunny_res4_ascii.ply, 7 runs;
needs meshdiff importable: pip install ., or PYTHONPATH=build/python)
"""
import argparse
import pathlib
import statistics
import threading
import time
import warnings

import meshdiff

# The meshes' report warnings (non-manifold edges, ...) are not what is measured here.
warnings.simplefilter("ignore", meshdiff.MeshWarning)

REPO = pathlib.Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="*", default=[str(REPO / "tests/data/bunny_res3.ply"),
                                                  str(REPO / "tests/data/bunny_res4_ascii.ply")])
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()
    V1, F1 = meshdiff.read_mesh(args.meshes[0])
    V2, F2 = meshdiff.read_mesh(args.meshes[1])

    def one() -> None:
        meshdiff.compare(V1, F1, V2, F2, threads=1)

    one()  # warm-up
    serial, threaded = [], []
    for _ in range(args.runs):
        t0 = time.perf_counter()
        one()
        one()
        serial.append(time.perf_counter() - t0)
        workers = [threading.Thread(target=one) for _ in range(2)]
        t0 = time.perf_counter()
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        threaded.append(time.perf_counter() - t0)
    s, t = statistics.median(serial), statistics.median(threaded)
    print(f"two compares, {args.runs} runs, medians: serial {s:.3f} s, two threads {t:.3f} s, ratio {t / s:.2f}")


if __name__ == "__main__":
    main()
