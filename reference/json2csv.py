#!/usr/bin/env python3
"""Turn meshdiff JSON reports into CSV tables for gnuplot or a spreadsheet.

Standard library only.

  json2csv.py profiles OUT.csv NAME=PROFILE.json [NAME=PROFILE.json ...]
      One row per level (the global level last, written as "global"), one column
      per mesh with its sigma. When a report holds the profile computed from the
      exact curvature (key "exact", from `meshdiff profile --exact`), a column
      NAME_exact follows; otherwise that column is left out. PROFILE.json#original or
      COMPARE.json#processed picks the profile of one side of a `meshdiff compare` report.

  json2csv.py smoothing OUT.csv NAME=SMOOTHING.json [NAME=SMOOTHING.json ...]
      Long table: name,iteration,level,sigma (level is a number or "global").

  json2csv.py smoothing-wide OUT.csv SMOOTHING.json
      One row per recorded iteration: iteration,L1,L5,...,global.

  json2csv.py batch OUT.csv RESULTS.jsonl [RESULTS.jsonl ...]
      One row per pair recorded ok by `meshdiff batch` (the last line per id):
      id, original, processed, hausdorff (the upper end of the certified
      interval; the sampled maximum with --hausdorff sampled or a
      meshdiff.compare/1 result), hausdorff_lower, hausdorff_certified,
      aw_mean_forward, aw_mean_backward (area-weighted means), chamfer_l1,
      chamfer_l2, psnr_mse_db, psnr_hausdorff_db (empty where the report has
      none: older reports, no face samples, infinite PSNR), d_L<L>
      per ring level, d_global, change_L<L>, change_global, and d_r<r>,
      change_r<r> per radius (--radii).

OUT may be "-" for stdout.
"""
import csv
import json
import sys


def load(path):
    """PATH or PATH#KEY: KEY selects a member, e.g. compare.json#processed (the processed
    mesh's profile inside a meshdiff.compare report)."""
    key = None
    if "#" in path:
        path, key = path.rsplit("#", 1)
    with open(path) as f:
        d = json.load(f)
    return d[key] if key else d


def split_arg(arg):
    if "=" in arg:
        name, path = arg.split("=", 1)
    else:
        path = arg
        name = path.rsplit("/", 1)[-1].rsplit(".", 1)[0]
    return name, path


def profile_columns(name, d):
    """{level: sigma} for the estimated and, if present, the exact profile."""
    if d.get("schema", "").split("/")[0] != "meshdiff.profile":
        raise SystemExit(f"json2csv: {name}: not a meshdiff.profile report (schema {d.get('schema')!r})")
    est = dict(zip(d["levels"], d["sigma"]))
    if d.get("sigma_global") is not None:
        est["global"] = d["sigma_global"]
    est.update({f"r{r:g}": s for r, s in zip(d.get("radii", []), d.get("sigma_radii", []))})
    cols = [(name, est)]
    ex = d.get("exact")
    if isinstance(ex, dict) and "sigma" in ex:
        exact = dict(zip(ex.get("levels", d["levels"]), ex["sigma"]))
        if ex.get("sigma_global") is not None:
            exact["global"] = ex["sigma_global"]
        exact.update({f"r{r:g}": s for r, s in zip(ex.get("radii", []), ex.get("sigma_radii", []))})
        cols.append((name + "_exact", exact))
    return cols


def open_out(path):
    return sys.stdout if path == "-" else open(path, "w", newline="")


def fmt(v):
    return "" if v is None else repr(float(v))


def profiles(out, args):
    cols = []
    for a in args:
        name, path = split_arg(a)
        cols += profile_columns(name, load(path))
    levels = sorted({k for _, c in cols for k in c if not isinstance(k, str)})
    if any("global" in c for _, c in cols):
        levels.append("global")
    levels += sorted({k for _, c in cols for k in c if isinstance(k, str) and k.startswith("r")},
                     key=lambda k: float(k[1:]))
    with open_out(out) as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["level"] + [n for n, _ in cols])
        for L in levels:
            w.writerow([L] + [fmt(c.get(L)) for _, c in cols])


def batch(out, args):
    last = {}
    for path in args:
        with open(path) as f:
            for line in f:
                try:
                    r = json.loads(line)
                except ValueError:
                    continue  # a torn last line of a killed run
                last[r.get("id")] = r
    recs = [r for r in last.values() if r.get("status") == "ok"]
    levels, radii = [], []
    for r in recs:
        d = r["result"].get("roughness_distance") or {}
        levels += [L for L in d.get("levels", []) if L not in levels]
        radii += [x for x in d.get("radii", []) if x not in radii]
    radii.sort()
    head = ["id", "original", "processed", "hausdorff", "hausdorff_lower", "hausdorff_certified"]
    head += ["aw_mean_forward", "aw_mean_backward", "chamfer_l1", "chamfer_l2", "psnr_mse_db", "psnr_hausdorff_db"]
    head += [f"d_L{L}" for L in levels] + ["d_global"]
    head += [f"change_L{L}" for L in levels] + ["change_global"]
    head += [f"d_r{x:g}" for x in radii] + [f"change_r{x:g}" for x in radii]
    with open_out(out) as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(head)
        for r in recs:
            res = r["result"]
            d = res.get("roughness_distance") or {}
            dl = dict(zip(d.get("levels", []), d.get("distance", [])))
            cl = dict(zip(d.get("levels", []), d.get("relative_change", [])))
            dr = dict(zip(d.get("radii", []), d.get("distance_radii", [])))
            cr = dict(zip(d.get("radii", []), d.get("relative_change_radii", [])))
            g = d.get("global") or {}
            sd = res.get("surface_distance") or {}
            h = sd.get("hausdorff")
            if isinstance(h, dict):  # meshdiff.compare/2: an interval (upper None when only sampled)
                lower, certified = h.get("lower"), bool(h.get("certified"))
                upper = h.get("upper") if h.get("upper") is not None else lower
            else:  # meshdiff.compare/1: the sampled maximum
                lower = upper = h
                certified = False
            row = [r.get("id"), r.get("original"), r.get("processed"), fmt(upper), fmt(lower), str(certified).lower()]
            aw = [((sd.get(side) or {}).get("area_weighted") or {}).get("mean") for side in ("forward", "backward")]
            ch, ps = sd.get("chamfer") or {}, sd.get("psnr") or {}
            row += [fmt(x) for x in aw + [ch.get("l1"), ch.get("l2"), ps.get("mse_db"), ps.get("hausdorff_db")]]
            row += [fmt(dl.get(L)) for L in levels] + [fmt(g.get("distance"))]
            row += [fmt(cl.get(L)) for L in levels] + [fmt(g.get("relative_change"))]
            row += [fmt(dr.get(x)) for x in radii] + [fmt(cr.get(x)) for x in radii]
            w.writerow(row)


def smoothing_records(d):
    if d.get("schema", "").split("/")[0] != "meshdiff.smoothing":
        raise SystemExit(f"json2csv: not a meshdiff.smoothing report (schema {d.get('schema')!r})")
    levels = list(d["levels"])
    glob = d.get("sigma_global")
    for k, it in enumerate(d["iterations"]):
        row = dict(zip(levels, d["sigma"][k]))
        if glob is not None and glob[k] is not None:
            row["global"] = glob[k]
        yield it, row
    return


def smoothing(out, args):
    with open_out(out) as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["name", "iteration", "level", "sigma"])
        for a in args:
            name, path = split_arg(a)
            for it, row in smoothing_records(load(path)):
                for L, s in row.items():
                    w.writerow([name, it, L, fmt(s)])


def smoothing_wide(out, args):
    if len(args) != 1:
        raise SystemExit("json2csv: smoothing-wide takes one report")
    d = load(split_arg(args[0])[1])
    keys = list(d["levels"]) + (["global"] if d.get("sigma_global") is not None else [])
    with open_out(out) as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["iteration"] + [("L%s" % k if k != "global" else k) for k in keys])
        for it, row in smoothing_records(d):
            w.writerow([it] + [fmt(row.get(k)) for k in keys])


def main(argv):
    if len(argv) < 4 or argv[1] not in ("profiles", "smoothing", "smoothing-wide", "batch"):
        sys.stderr.write(__doc__)
        return 2
    modes = {"profiles": profiles, "smoothing": smoothing, "smoothing-wide": smoothing_wide, "batch": batch}
    modes[argv[1]](argv[2], argv[3:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
