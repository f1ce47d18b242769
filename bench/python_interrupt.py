#!/usr/bin/env python3
"""The delay between Ctrl-C (SIGINT) and the KeyboardInterrupt of a running
meshdiff call (issue 32: within 0.2 s). A child interpreter runs compare_files()
on two generated spheres of about 164K vertices each and gets SIGINT after
--after seconds; prints the median and the largest delay over --runs runs.

Usage: python3 bench/python_interrupt.py --cli build/meshdiff [--runs N] [--after S]
(needs meshdiff importable by this interpreter: pip install ., or PYTHONPATH=build/python)
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

CHILD = """
import os, signal, sys, threading, time, meshdiff
sent = []
def interrupt():
    time.sleep(float(sys.argv[3]))
    sent.append(time.perf_counter())
    os.kill(os.getpid(), signal.SIGINT)
threading.Thread(target=interrupt, daemon=True).start()
try:
    meshdiff.compare_files(sys.argv[1], sys.argv[2])
    print("finished")
except KeyboardInterrupt:
    print(time.perf_counter() - sent[0])
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="build/meshdiff")
    ap.add_argument("--runs", type=int, default=9)
    ap.add_argument("--after", type=float, default=1.5)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        a, b = os.path.join(d, "a.ply"), os.path.join(d, "b.ply")
        subprocess.run([args.cli, "generate", "sphere", "--subdivisions", "7", a], check=True, capture_output=True)
        subprocess.run([args.cli, "generate", "noisy-sphere", "--subdivisions", "7", b], check=True,
                       capture_output=True)
        delays = []
        for _ in range(args.runs):
            r = subprocess.run([sys.executable, "-c", CHILD, a, b, str(args.after)], capture_output=True, text=True,
                               check=True)
            if r.stdout.strip() == "finished":
                sys.exit(f"the call finished before SIGINT at {args.after} s: lower --after")
            delays.append(float(r.stdout))
    print(f"Ctrl-C after {args.after} s, {args.runs} runs: median delay {1000 * statistics.median(delays):.0f} ms, "
          f"largest {1000 * max(delays):.0f} ms")


if __name__ == "__main__":
    main()
