#!/usr/bin/env python3
"""A CLI-level hostile-input campaign: N mutated files per format (from tests/fuzz/seeds and the bundled meshes),
each through `meshdiff profile FILE --levels 1,2 --json -` with a time cap; counts the outcomes. A hang (time cap),
a signal, exit 70 or a NaN/Inf in a report is a failure; the failing files are kept in OUT/failures/.

    tests/fuzz/campaign.py build/meshdiff --cases 10000 --seconds 10 --out /tmp/campaign

Seeded (--seed), so a run can be repeated; a few minutes per 10,000 cases on 2 cores (4 processes at a time)."""
import argparse, concurrent.futures as cf, json, math, os, random, shutil, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data")
TOKENS = [b"-1", b"0", b"1", b"3", b"2147483647", b"4294967295", b"9223372036854775807", b"1e308", b"1e31",
          b"-1e400", b"nan", b"inf", b"-0", b"0x10", b"", b" ", b"\n", b"\x00", b"\xff", b"/", b"//", b"#",
          b"element vertex 2\n", b"property float x\n", b"end_header\n", b"f /1", b"f 1 2", b"mtllib x\n", b"OFF\n",
          b"solid x\n", b"facet normal 0 0 0\n", b"\x1b[31m"]


def seeds(fmt):
    out = []
    d = os.path.join(HERE, "seeds", fmt)
    out += [os.path.join(d, f) for f in sorted(os.listdir(d))]
    small = {"ply": ["hemisphere.ply"], "obj": [], "off": [], "stl": []}[fmt]
    out += [os.path.join(DATA, f) for f in small]
    return [open(p, "rb").read() for p in out]


def mutate(data, rng):
    b = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        op = rng.randrange(6)
        if not b:
            b += rng.choice(TOKENS)
            continue
        i = rng.randrange(len(b))
        if op == 0:
            b[i] ^= 1 << rng.randrange(8)
        elif op == 1:
            del b[i:i + rng.randint(1, 16)]
        elif op == 2:
            b[i:i] = rng.choice(TOKENS)
        elif op == 3:  # replace a number-like token
            j = i
            while j < len(b) and chr(b[j]) in "0123456789.-+e":
                j += 1
            b[i:j] = rng.choice(TOKENS)
        elif op == 4:
            del b[rng.randrange(len(b)):]  # truncate
        else:
            k = rng.randrange(len(b))
            b[i:i] = b[k:k + rng.randint(1, 64)]  # duplicate a chunk
    return bytes(b)


def finite(x):
    if isinstance(x, dict):
        return all(finite(v) for v in x.values())
    if isinstance(x, list):
        return all(finite(v) for v in x)
    return not isinstance(x, float) or math.isfinite(x)


def run(meshdiff, path, seconds):
    try:
        p = subprocess.run([meshdiff, "profile", path, "--levels", "1,2", "--json", "-"], capture_output=True,
                           timeout=seconds)
    except subprocess.TimeoutExpired:
        return "hang"
    if p.returncode < 0:
        return f"signal {-p.returncode}"
    if p.returncode == 70:
        return "exit 70"
    if p.returncode == 0:
        try:
            if not finite(json.loads(p.stdout)):
                return "nan"
        except ValueError:
            return "bad json"
        return "ok"
    if p.returncode in (3, 4) and p.stderr.count(b"\n") == 1:
        return f"exit {p.returncode}"
    lines = p.stderr.count(b"\n")
    return f"exit {p.returncode} ({lines} lines)"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshdiff")
    ap.add_argument("--cases", type=int, default=10000)
    ap.add_argument("--seconds", type=float, default=10)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--formats", default="ply,obj,off,stl")
    ap.add_argument("--out", default="/tmp/meshdiff-campaign")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.out, "failures"), exist_ok=True)
    total_bad = 0
    for fmt in a.formats.split(","):
        rng = random.Random(f"{a.seed}-{fmt}")
        pool = seeds(fmt)
        files = []
        for k in range(a.cases):
            p = os.path.join(a.out, f"case{k}.{fmt}")
            with open(p, "wb") as f:
                f.write(mutate(rng.choice(pool), rng))
            files.append(p)
        counts = {}
        with cf.ThreadPoolExecutor(4) as ex:
            for p, r in zip(files, ex.map(lambda p: run(a.meshdiff, p, a.seconds), files)):
                counts[r] = counts.get(r, 0) + 1
                if not (r == "ok" or r in ("exit 3", "exit 4")):
                    total_bad += 1
                    shutil.copy(p, os.path.join(a.out, "failures", os.path.basename(p)))
        for p in files:
            os.remove(p)
        print(f"{fmt}: {a.cases} cases: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())), flush=True)
    print(f"campaign: {total_bad} failures (kept in {a.out}/failures)")
    sys.exit(1 if total_bad else 0)


if __name__ == "__main__":
    main()
