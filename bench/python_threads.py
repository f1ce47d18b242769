#!/usr/bin/env python3
"""Two Python threads running two compares at once, against the same two run one
after the other (issue 32: the GIL is released, so the threads overlap).

Prints the median over the runs of the serial and the threaded wall time and
their ratio threaded / serial (1.0: no overlap; 0.5: perfect on 2 cores). Each
compare runs with threads=1 (one OpenMP thread), so the two Python threads are
the only parallelism.

Also the cores the process got in each mode (its CPU time / wall time, medians)
and the load average: the ratio can only be 0.5 if the threaded runs got two
cores. On a machine busy with other work (load above the core count) the
threaded runs get less than two (and the serial one less than one): the same
CPU time in both modes then says the threads do not serialise each other, a
ratio near 1 that the machine had no second core to give.

Usage: python3 bench/python_threads.py [ORIGINAL PROCESSED] [--runs N]
(default: tests/data/bunny_res3.ply tests/data/bunny_res4_ascii.ply, 7 runs;
needs meshdiff importable: pip install ., or PYTHONPATH=build/python)
"""
import argparse
import os
import pathlib
import resource
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

    def cpu() -> float:
        r = resource.getrusage(resource.RUSAGE_SELF)
        return r.ru_utime + r.ru_stime

    one()  # warm-up
    serial, threaded, serial_cpu, threaded_cpu = [], [], [], []
    for _ in range(args.runs):
        c0, t0 = cpu(), time.perf_counter()
        one()
        one()
        serial.append(time.perf_counter() - t0)
        serial_cpu.append(cpu() - c0)
        workers = [threading.Thread(target=one) for _ in range(2)]
        c0, t0 = cpu(), time.perf_counter()
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        threaded.append(time.perf_counter() - t0)
        threaded_cpu.append(cpu() - c0)
    s, t = statistics.median(serial), statistics.median(threaded)
    cores = [statistics.median(c / w for c, w in zip(cs, ws)) for cs, ws in ((serial_cpu, serial),
                                                                              (threaded_cpu, threaded))]
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"CPU time, medians: serial {statistics.median(serial_cpu):.3f} s, two threads "
          f"{statistics.median(threaded_cpu):.3f} s; cores used: serial {cores[0]:.2f}, two threads {cores[1]:.2f} "
          f"(of {os.cpu_count()}; load average {load})")
    print(f"two compares, {args.runs} runs, medians: serial {s:.3f} s, two threads {t:.3f} s, ratio {t / s:.2f}")


if __name__ == "__main__":
    main()
