"""The seam of the options (issue 26): every option of `meshdiff compare` and
`meshdiff profile`, and batch's pass-through of the compare options, goes
through all three front ends, generated from ONE table (COMPARE, PROFILE
below):

  - the CLI: `meshdiff compare A B ...` / `meshdiff profile A ...`;
  - the CLI's batch: a one-pair list, `meshdiff batch pairs.csv --out o.jsonl ...`;
  - Python: meshdiff.compare_files(A, B, ...) / meshdiff.profile_file(A, ...).

Each case has a normal or a boundary value, accepted or refused. Accepted:
every front end succeeds and the JSON is the same, every number bit for bit
(the batch record's "result" included), and the files an output option writes
are byte for byte the same. Refused: the CLI and batch exit 2 and name the
option by its flag, Python raises ValueError (a bad value) or TypeError (a
wrong type) naming its keyword. The table says where an option does not exist
in a front end and why. test_every_option_is_in_the_table reads the options
each front end offers (`--help`, the Python signatures) and fails on any that
the table does not list, so no new option skips the seam.
"""
import json
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

import meshdiff

from test_cli_agreement import differences


class Case:
    """One run of an option: its CLI tokens, its Python keywords, and the outcome
    ("ok", "value": refused as a value, "type": refused as a wrong type)."""

    def __init__(self, cli, py, outcome, name=""):
        self.cli, self.py, self.outcome, self.name = list(cli), dict(py), outcome, name

    def __repr__(self):
        return self.name or " ".join(self.cli) or repr(self.py)


def ok(cli, py, name=""):
    return Case(cli, py, "ok", name)


def value(cli, py, name=""):
    return Case(cli, py, "value", name)


def type_(cli, py, name=""):
    return Case(cli, py, "type", name)


class Option:
    """A row of the table: the CLI flag, the Python keyword (None: not in Python,
    with the reason in `python`), whether batch passes it to each pair (True) or
    why not (a str), and the cases."""

    def __init__(self, flag, keyword, cases, batch=True, python=None):
        self.flag, self.keyword, self.cases, self.batch, self.python = flag, keyword, cases, batch, python


NO_PYTHON_DISPLAY = "a progress display on stderr for a person at a terminal; Python has no display"
# --bootstrap and --bootstrap-seed: the same cases for compare and profile (fresh Option objects for each table).
def bootstrap_options():
    return [
        Option("--bootstrap", "bootstrap", [
            ok(["--bootstrap", "50", "--levels", "1,2"], dict(bootstrap=50, levels=[1, 2])),
            value(["--bootstrap", "10001"], dict(bootstrap=10001)),
            type_(["--bootstrap", "x"], dict(bootstrap="x")),
        ]),
        Option("--bootstrap-seed", "bootstrap_seed", [
            ok(["--bootstrap", "20", "--bootstrap-seed", "5", "--levels", "1"],
               dict(bootstrap=20, bootstrap_seed=5, levels=[1])),
            value(["--bootstrap-seed", "-1"], dict(bootstrap_seed=-1)),
            type_(["--bootstrap-seed", "1.5"], dict(bootstrap_seed=1.5)),
        ]),
    ]


# --paper (issue 29): the paper's exact method, one flag away; a flag beside it that contradicts it is refused.
def paper_option():
    return Option("--paper", "paper", [
        ok(["--paper", "--levels", "1,2"], dict(paper=True, levels=[1, 2])),
        ok(["--paper", "--curvature", "goldfeather", "--levels", "1"],
           dict(paper=True, curvature="goldfeather", levels=[1]), "the paper's own estimator beside it"),
        value(["--paper", "--curvature", "jet"], dict(paper=True, curvature="jet")),
        value(["--paper", "--trim", "0.1"], dict(paper=True, trim=0.1)),
        type_(["--paper=maybe"], dict(paper="maybe")),
    ])


NOT_IN_BATCH_FILE = "a file per comparison: batch writes one JSON line per pair (--out) and maps with --maps-dir"

# Options of `meshdiff compare` (and of `meshdiff batch`, which passes them to each pair).
COMPARE = [
    Option("--levels", "levels", [
        ok(["--levels", "1,3"], dict(levels=[1, 3])),
        ok(["--levels", "2-4"], dict(levels=range(2, 5))),
        value(["--levels", "1-300"], dict(levels=range(1, 301)), "regression: 300 levels refused by both"),
        value(["--levels", "0"], dict(levels=[0])),
        value(["--levels", "100001"], dict(levels=[100001])),
        type_(["--levels", "x"], dict(levels=["x"])),
    ]),
    Option("--radii", "radii", [
        ok(["--radii", "0.125,0.25"], dict(radii=[0.125, 0.25])),
        ok(["--radii", "0.125,0.25"], dict(radii=np.array([0.125, 0.25], dtype=np.float32)), "float32 radii"),
        ok(["--radii", "default"], dict(radii="default")),
        value(["--radii", "5000"], dict(radii=[5000.0]), "regression: radius 5000 refused by both"),
        value(["--radii", ",".join(["0.1"] * 65)], dict(radii=[0.1] * 65)),
        value(["--radii", "0"], dict(radii=[0.0])),
        type_(["--radii", "x"], dict(radii=["x"])),
    ]),
    Option("--no-global", "global_level", [
        ok(["--no-global"], dict(global_level=False)),
        type_(["--no-global=maybe"], dict(global_level="maybe")),
    ]),
    Option("--curvature", "curvature", [
        ok(["--curvature", "quadric"], dict(curvature="quadric")),
        ok(["--curvature", "jet"], dict(curvature="jet")),
        value(["--curvature", "foo"], dict(curvature="foo")),
    ]),
    Option("--weighting", "weighting", [
        ok(["--weighting", "inverse-square", "--curvature", "goldfeather"],
           dict(weighting="inverse-square", curvature="goldfeather")),
        value(["--weighting", "heavy"], dict(weighting="heavy")),
        value(["--weighting", "inverse-square"], dict(weighting="inverse-square"),
              "the jet fit (the default) weights its rows itself"),
    ]),
    Option("--normalize", "normalize", [
        ok(["--normalize", "area"], dict(normalize="area")),
        ok(["--normalize", "original", "--levels", "1,2"], dict(normalize="original", levels=[1, 2])),
        value(["--normalize", "unit"], dict(normalize="unit")),
        value(["--normalize", "area", "--measure", "corsini"], dict(normalize="area", measure="corsini"),
              "corsini's angles take no scaling"),
    ]),
    Option("--trim", "trim", [
        ok(["--trim", "0.01"], dict(trim=0.01)),
        ok(["--trim", "0"], dict(trim=0.0)),
        value(["--trim", "0.5"], dict(trim=0.5)),
        value(["--trim", "-0.1"], dict(trim=-0.1)),
        value(["--trim", "0.01", "--measure", "corsini"], dict(trim=0.01, measure="corsini")),
        type_(["--trim", "x"], dict(trim="x")),
    ]),
    *bootstrap_options(),
    paper_option(),
    Option("--local-trim", "local_trim", [
        ok(["--local-trim", "0"], dict(local_trim=0.0)),
        ok(["--local-trim", "0.2", "--levels", "1"], dict(local_trim=0.2, levels=[1])),
        value(["--local-trim", "0.3"], dict(local_trim=0.3)),
        type_(["--local-trim", "x"], dict(local_trim="x")),
    ]),
    Option("--no-local", "local", [
        ok(["--no-local"], dict(local=False)),
        type_(["--no-local=maybe"], dict(local="maybe")),
    ]),
    Option("--measure", "measure", [
        ok(["--measure", "corsini", "--levels", "1,2"], dict(measure="corsini", levels=[1, 2])),
        value(["--measure", "bogus"], dict(measure="bogus")),
    ]),
    Option("--unbiased-variance", "unbiased_variance", [
        ok(["--measure", "corsini", "--unbiased-variance"], dict(measure="corsini", unbiased_variance=True)),
        value(["--unbiased-variance"], dict(unbiased_variance=True)),
    ]),
    Option("--k", "k", [
        ok(["--k", "1e-3"], dict(k=1e-3)),
        ok(["-k", "1e308"], dict(k=1e308), "k = 1e308 is finite: accepted by both"),
        value(["-k", "0"], dict(k=0.0)),
        value(["-k", "nan"], dict(k=float("nan"))),
        type_(["-k", "abc"], dict(k="abc")),
    ]),
    Option("--no-roughness", "roughness", [
        ok(["--no-roughness"], dict(roughness=False)),
        type_(["--no-roughness=maybe"], dict(roughness="maybe")),
    ]),
    Option("--no-distance", "distance", [
        ok(["--no-distance"], dict(distance=False)),
        value(["--no-distance", "--no-roughness"], dict(distance=False, roughness=False)),
    ]),
    Option("--samples", "samples", [
        ok(["--samples", "3000"], dict(samples=3000)),
        value(["--samples", "0"], dict(samples=0)),
        value(["--samples", "-5"], dict(samples=-5)),
        value(["-n", "300000000"], dict(samples=300_000_000)),
        type_(["-n", "1.5"], dict(samples=1.5)),
    ]),
    Option("--density", "density", [
        ok(["--density", "50"], dict(density=50.0)),
        value(["--density", "0"], dict(density=0.0)),
        value(["--density", "50", "-n", "100"], dict(density=50.0, samples=100)),
        type_(["--density", "lots"], dict(density="lots")),
    ]),
    Option("--face-sampling", "face_sampling", [
        ok(["--face-sampling", "montecarlo"], dict(face_sampling="montecarlo")),
        value(["--face-sampling", "random"], dict(face_sampling="random")),
    ]),
    Option("--seed", "seed", [
        ok(["--face-sampling", "montecarlo", "--seed", "7"], dict(face_sampling="montecarlo", seed=7)),
        ok(["--face-sampling", "montecarlo", "--seed", str(2**64 - 1)], dict(face_sampling="montecarlo", seed=2**64 - 1)),
        value(["--seed", str(2**64)], dict(seed=2**64)),
        value(["--seed", "-1"], dict(seed=-1)),
        type_(["--seed", "1.5"], dict(seed=1.5)),
    ]),
    Option("--no-vertex-samples", "vertex_samples", [ok(["--no-vertex-samples"], dict(vertex_samples=False))]),
    Option("--no-edge-samples", "edge_samples", [ok(["--no-edge-samples"], dict(edge_samples=False))]),
    Option("--no-face-samples", "face_samples", [
        ok(["--no-face-samples"], dict(face_samples=False)),
        value(["--no-vertex-samples", "--no-edge-samples", "--no-face-samples"],
              dict(vertex_samples=False, edge_samples=False, face_samples=False)),
    ]),
    Option("--hausdorff", "hausdorff", [
        ok(["--hausdorff", "sampled"], dict(hausdorff="sampled")),
        value(["--hausdorff", "exact"], dict(hausdorff="exact")),
    ]),
    Option("--hausdorff-tolerance", "hausdorff_tolerance", [
        ok(["--hausdorff-tolerance", "1e-3"], dict(hausdorff_tolerance=1e-3)),
        ok(["--hausdorff-tolerance", "0.3", "--hausdorff-abs-tolerance", "1e-9"],
           dict(hausdorff_tolerance=0.3, hausdorff_abs_tolerance=1e-9), "regression: both tolerances"),
        value(["--hausdorff-tolerance", "0.7"], dict(hausdorff_tolerance=0.7)),
        value(["--hausdorff-tolerance", "1e-13"], dict(hausdorff_tolerance=1e-13)),
        value(["--hausdorff", "sampled", "--hausdorff-tolerance", "1e-3"],
              dict(hausdorff="sampled", hausdorff_tolerance=1e-3), "a tolerance with sampled"),
    ]),
    Option("--hausdorff-abs-tolerance", "hausdorff_abs_tolerance", [
        ok(["--hausdorff-abs-tolerance", "1e-6"], dict(hausdorff_abs_tolerance=1e-6)),
        value(["--hausdorff-abs-tolerance", "0"], dict(hausdorff_abs_tolerance=0.0)),
        value(["--hausdorff-abs-tolerance", "inf"], dict(hausdorff_abs_tolerance=float("inf"))),
    ]),
    Option("--hausdorff-budget", "hausdorff_budget", [
        ok(["--hausdorff-budget", "1000"], dict(hausdorff_budget=1000)),
        value(["--hausdorff-budget", "0"], dict(hausdorff_budget=0)),
        value(["--hausdorff-budget", "2000000000"], dict(hausdorff_budget=2_000_000_000)),
        value(["--hausdorff", "sampled", "--hausdorff-budget", "10"], dict(hausdorff="sampled", hausdorff_budget=10)),
    ]),
    Option("--fscore", "fscore", [
        ok(["--fscore", "0.01,0.05"], dict(fscore=[0.01, 0.05])),
        value(["--fscore", "2e6"], dict(fscore=[2e6])),
        value(["--fscore", ",".join(["0.01"] * 65)], dict(fscore=[0.01] * 65)),
        type_(["--fscore", "x"], dict(fscore=["x"])),
    ]),
    Option("--histogram", "histogram", [
        ok(["--histogram", "10"], dict(histogram=10)),
        ok(["--histogram", "0"], dict(histogram=0), "histogram 0 is none in both"),
        value(["--histogram", "200000"], dict(histogram=200000)),
        type_(["--histogram", "1.5"], dict(histogram=1.5)),
    ]),
    Option("--json", "json", [ok(["--json", "report.json"], dict(json="report.json"))], batch=NOT_IN_BATCH_FILE),
    Option("--distance-map", "distance_map", [
        ok(["--distance-map", "p.ply"], dict(distance_map="p.ply")),
        value(["--distance-map", "p.ply", "--no-distance"], dict(distance_map="p.ply", distance=False)),
        value(["--distance-map", "x.ply", "--json", "x.ply"], dict(distance_map="x.ply", json="x.ply")),
    ], batch=NOT_IN_BATCH_FILE),
    Option("--distance-map-original", "distance_map_original", [
        ok(["--distance-map-original", "o.ply", "--distance-map", "p.ply"],
           dict(distance_map_original="o.ply", distance_map="p.ply")),
        value(["--distance-map-original", "o.ply", "--distance-map", "o.ply"],
              dict(distance_map_original="o.ply", distance_map="o.ply")),
    ], batch=NOT_IN_BATCH_FILE),
    Option("--distance-maps", "distance_maps", [
        ok(["--distance-maps", "maps"], dict(distance_maps="maps")),
        value(["--distance-maps", "maps", "--distance-map", "p.ply"], dict(distance_maps="maps", distance_map="p.ply")),
    ], batch=NOT_IN_BATCH_FILE),
    Option("--samples-out", "samples_out", [
        ok(["--samples-out", "s.ply", "-n", "2000"], dict(samples_out="s.ply", samples=2000)),
        value(["--samples-out", "s.ply", "--no-distance"], dict(samples_out="s.ply", distance=False)),
    ], batch=NOT_IN_BATCH_FILE),
    Option("--html", "html", [
        ok(["--html", "r.html"], dict(html="r.html")),
        ok(["--html", "r.html", "--no-roughness", "--histogram", "5"], dict(html="r.html", roughness=False, histogram=5)),
        value(["--html", "-"], dict(html="-")),
        value(["--html", "r.html", "--json", "r.html"], dict(html="r.html", json="r.html")),
    ], batch=NOT_IN_BATCH_FILE),
    Option("--color-range", "color_range", [
        ok(["--color-range", "0", "0.05", "--distance-maps", "maps"], dict(color_range=(0, 0.05), distance_maps="maps")),
        ok(["--color-range", "0", "0.05"], dict(color_range=[0.0, 0.05])),
        value(["--color-range", "0.05", "0"], dict(color_range=(0.05, 0.0))),
        type_(["--color-range", "x", "1"], dict(color_range=("x", 1))),
        ok(["--color-range", "p95", "--distance-maps", "maps", "--html", "r.html"],
           dict(color_range="p95", distance_maps="maps", html="r.html")),
        ok(["--color-range", "max", "--distance-maps", "maps"], dict(color_range="max", distance_maps="maps")),
        ok(["--color-range", "0:0.05", "--html", "r.html"], dict(color_range="0:0.05", html="r.html")),
        value(["--color-range", "p0"], dict(color_range="p0")),
        value(["--color-range", "p101"], dict(color_range="p101")),
        value(["--color-range", "0.05:0"], dict(color_range="0.05:0")),
        value(["--color-range", "wide"], dict(color_range="wide")),
    ]),
    Option("--html-face-budget", "html_face_budget", [
        ok(["--html", "r.html", "--html-face-budget", "2000"], dict(html="r.html", html_face_budget=2000)),
        value(["--html", "r.html", "--html-face-budget", "999"], dict(html="r.html", html_face_budget=999)),
        value(["--html-face-budget", "5000"], dict(html_face_budget=5000), "a budget needs the HTML report"),
        type_(["--html", "r.html", "--html-face-budget", "x"], dict(html="r.html", html_face_budget="x")),
    ]),  # batch: with --html-dir, passed to every pair (tests/cli_batch_test.sh)
    Option("--threads", "threads", [
        ok(["--threads", "1"], dict(threads=1)),
        value(["--threads", "2000"], dict(threads=2000)),
        value(["--threads", "-1"], dict(threads=-1)),
    ]),
    Option("--progress", None, [ok(["--progress"], {})], batch="batch's own: its per-pair lines", python=NO_PYTHON_DISPLAY),
    Option("--quiet", None, [ok(["-q"], {}), ok(["--quiet"], {})], batch="batch's own: no per-pair lines",
           python=NO_PYTHON_DISPLAY),
]

# Options of `meshdiff profile` (batch compares pairs: its profile options are compare's, above).
NOT_IN_BATCH_PROFILE = "batch compares pairs; the profile options it takes are compare's"
PROFILE = [
    Option("--levels", "levels", [
        ok(["--levels", "1,3"], dict(levels=[1, 3])),
        value(["--levels", "1-300"], dict(levels=range(1, 301)), "regression: 300 levels refused by both"),
        type_(["--levels", "x"], dict(levels=[1.5])),
    ]),
    Option("--radii", "radii", [
        ok(["--radii", "0.125"], dict(radii=[0.125])),
        value(["--radii", "5000"], dict(radii=[5000.0]), "regression: radius 5000 refused by both"),
    ]),
    Option("--no-global", "global_level", [ok(["--no-global"], dict(global_level=False))]),
    Option("--curvature", "curvature", [
        ok(["--curvature", "meyer"], dict(curvature="meyer")),
        ok(["--curvature", "jet"], dict(curvature="jet")),
        value(["--curvature", "foo"], dict(curvature="foo")),
    ]),
    Option("--weighting", "weighting", [
        ok(["--weighting", "inverse-square", "--curvature", "quadric"], dict(weighting="inverse-square", curvature="quadric")),
        value(["--weighting", "inverse-square", "--curvature", "jet"], dict(weighting="inverse-square", curvature="jet"),
              "the jet fit weights its rows itself"),
    ]),
    Option("--normalize", "normalize", [
        ok(["--normalize", "area"], dict(normalize="area")),
        value(["--normalize", "original"], dict(normalize="original"), "a profile has no original"),
    ]),
    Option("--trim", "trim", [ok(["--trim", "0.001"], dict(trim=0.001)), value(["--trim", "1"], dict(trim=1.0))]),
    Option("--measure", "measure", [
        ok(["--measure", "corsini"], dict(measure="corsini")),
        value(["--measure", "corsini", "--radii", "0.1"], dict(measure="corsini", radii=[0.1])),
    ]),
    *bootstrap_options(),
    paper_option(),
    Option("--unbiased-variance", "unbiased_variance", [
        ok(["--measure", "corsini", "--unbiased-variance"], dict(measure="corsini", unbiased_variance=True)),
        value(["--unbiased-variance"], dict(unbiased_variance=True)),
    ]),
    Option("--json", "json", [ok(["--json", "p.json"], dict(json="p.json"))]),
    Option("--vertex-data", "vertex_data", [
        ok(["--vertex-data", "v.ply"], dict(vertex_data="v.ply")),
        value(["--vertex-data", "v.ply", "--measure", "corsini"], dict(vertex_data="v.ply", measure="corsini")),
        value(["--vertex-data", "v.ply", "--json", "v.ply"], dict(vertex_data="v.ply", json="v.ply")),
    ]),
    Option("--html", "html", [
        ok(["--html", "p.html", "--levels", "1,2"], dict(html="p.html", levels=[1, 2])),
        ok(["--html", "p.html", "--color-range", "0.5"], dict(html="p.html", color_range=0.5)),
        value(["--html", "p.html", "--measure", "corsini"], dict(html="p.html", measure="corsini")),
        value(["--html", "-"], dict(html="-")),
    ]),
    Option("--color-range", "color_range", [
        ok(["--color-range", "0.5", "--vertex-data", "v.ply"], dict(color_range=0.5, vertex_data="v.ply")),
        value(["--color-range", "-1"], dict(color_range=-1.0)),
        type_(["--color-range", "x"], dict(color_range="x")),
    ]),
    Option("--html-face-budget", "html_face_budget", [
        ok(["--html", "p.html", "--html-face-budget", "1000"], dict(html="p.html", html_face_budget=1000)),
        value(["--html", "p.html", "--html-face-budget", "0"], dict(html="p.html", html_face_budget=0)),
        value(["--html-face-budget", "5000"], dict(html_face_budget=5000), "a budget needs the HTML report"),
    ]),
    Option("--exact", "exact", [
        ok(["--exact"], dict(exact=True)),
        value(["--exact", "--measure", "corsini"], dict(exact=True, measure="corsini")),
    ]),
    Option("--exact-property", "exact_property", [
        ok(["--exact", "--exact-property", "exact_H"], dict(exact=True, exact_property="exact_H")),
        value(["--exact", "--exact-property", "nope"], dict(exact=True, exact_property="nope")),
    ]),
    Option("--threads", "threads", [ok(["--threads", "1"], dict(threads=1)), value(["--threads", "2000"], dict(threads=2000))]),
    Option("--progress", None, [ok(["--progress"], {})], python=NO_PYTHON_DISPLAY),
    Option("--quiet", None, [ok(["-q"], {})], python=NO_PYTHON_DISPLAY),
]
for o in PROFILE:
    o.batch = NOT_IN_BATCH_PROFILE

# batch's own options (not passed to the pairs), with what they are.
BATCH_ONLY = {
    "--out": "the JSON-lines output",
    "--shard": "which pairs this process takes",
    "--pair-timeout": "the time one pair may take",
    "--maps-dir": "the distance maps of every pair",
    "--html-dir": "the HTML report of every pair",
    "--progress": "its per-pair lines (the default)",
    "--quiet": "no per-pair lines",
}


# Keywords of compare() and compare_files() that only Python has (no CLI flag, so no batch either), with why,
# and their cases, run in Python only: an accepted one leaves the report the CLI's without it, every number bit
# for bit; a refused one names the keyword. A value may be a function of the two paths (a DistanceIndex).
class PythonOnly:
    def __init__(self, keyword, why, cases):
        self.keyword, self.why, self.cases = keyword, why, cases


def index_of(k):
    return lambda a, b: meshdiff.DistanceIndex(*meshdiff.read_mesh((a, b)[k]))


PYTHON_ONLY = [
    PythonOnly("maps", "per-vertex numpy arrays in the result; the CLI writes them as PLY (--distance-maps)", [
        ok([], dict(maps=True)),
        ok([], dict(maps=True, normalize="area", radii=[0.1])),
        type_([], dict(maps="yes")),
    ]),
    PythonOnly("index_original", "a DistanceIndex object kept between calls; a CLI run builds its own", [
        ok([], dict(index_original=index_of(0))),
        ok([], dict(index_original=index_of(0), roughness=False)),
        value([], dict(index_original=index_of(1)), "an index of the processed mesh"),
        type_([], dict(index_original="a.ply")),
    ]),
    PythonOnly("index_processed", "a DistanceIndex object kept between calls; a CLI run builds its own", [
        ok([], dict(index_processed=index_of(1))),
        ok([], dict(index_processed=index_of(1), index_original=index_of(0), levels=[1, 2])),
        value([], dict(index_processed=index_of(0)), "an index of the original"),
        type_([], dict(index_processed=1)),
    ]),
]


def cli_options(cli, command):
    """The long options `meshdiff COMMAND --help` lists (the help flag aside)."""
    text = subprocess.run([cli, command, "--help"], check=True, capture_output=True, text=True).stdout
    names = set(re.findall(r"^\s+(?:-\w,)?(--[\w-]+)", text, re.M))
    return names - {"--help"}


def python_keywords(function):
    """The keyword-only parameters of a module function, from its signature line."""
    signature = function.__doc__.split("\n", 1)[0]
    return set(re.findall(r"(\w+): \w+ = ", signature.split("*,", 1)[1]))


def test_every_option_is_in_the_table(cli):
    """Each option of each front end is a row of the table, and each row's spelling exists where the table says."""
    counts = {}
    for command, table, function in (("compare", COMPARE, meshdiff.compare_files),
                                      ("profile", PROFILE, meshdiff.profile_file)):
        flags = {o.flag for o in table}
        assert cli_options(cli, command) == flags, f"{command}: the table and --help differ"
        keywords = {o.keyword for o in table if o.keyword} | {"threads"}
        if command == "compare":
            keywords |= {o.keyword for o in PYTHON_ONLY}
        assert python_keywords(function) == keywords, f"{function.__name__}: the table and the signature differ"
        for o in table:
            assert o.cases, f"{command} {o.flag}: no case"
            assert (o.keyword is None) == (o.python is not None), f"{o.flag}: a keyword, or the reason there is none"
        counts[command] = len(table)
    # Python's compare() on arrays takes the keywords of compare_files().
    assert python_keywords(meshdiff.compare) == python_keywords(meshdiff.compare_files)
    assert python_keywords(meshdiff.profile) == python_keywords(meshdiff.profile_file)
    passed = {o.flag for o in COMPARE if o.batch is True}
    assert cli_options(cli, "batch") == passed | set(BATCH_ONLY)
    assert counts == {"compare": 41, "profile": 22}, counts  # the options covered, stated
    assert [o.keyword for o in PYTHON_ONLY] == ["maps", "index_original", "index_processed"]
    assert all(o.cases and o.why for o in PYTHON_ONLY)


CASES = [pytest.param("compare", o, c, id=f"compare {o.flag}: {c!r}") for o in COMPARE for c in o.cases] + [
    pytest.param("profile", o, c, id=f"profile {o.flag}: {c!r}") for o in PROFILE for c in o.cases]


@pytest.fixture(scope="module")
def meshes(cli, tmp_path_factory):
    d = tmp_path_factory.mktemp("seam")
    a, b = d / "a.ply", d / "b.ply"
    subprocess.run([cli, "generate", "sphere", "--subdivisions", "3", str(a)], check=True, capture_output=True)
    subprocess.run([cli, "generate", "noisy-sphere", "--frequency", "10", str(b)], check=True, capture_output=True)
    return str(a), str(b)


def run(args, cwd):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=120)


def files_of(folder):
    """The files of a folder; in an HTML report, the command line that made it (the meta element) left out."""
    meta = re.compile(rb'(<script type="application/json" id="meshdiff-meta">).*?(</script>)')
    return {p.name: meta.sub(rb"\1\2", p.read_bytes()) if p.suffix == ".html" else p.read_bytes()
            for p in pathlib.Path(folder).iterdir()}


def python_call(command, a, b, kw, cwd):
    here = os.getcwd()
    os.chdir(cwd)
    try:
        if command == "compare":
            return meshdiff.compare_files(a, b, **kw)
        return meshdiff.profile_file(a, **kw)
    finally:
        os.chdir(here)


@pytest.mark.parametrize("command,option,case", CASES)
def test_the_three_front_ends_agree(cli, meshes, tmp_path, command, option, case):
    a, b = meshes
    inputs = [a, b] if command == "compare" else [a]
    writes_json = "--json" in case.cli
    for d in ("cli", "batch", "py"):
        (tmp_path / d).mkdir()
    got = run([cli, command, *inputs, *case.cli, *([] if writes_json else ["--json", "-"])], tmp_path / "cli")
    # Batch runs the case when every option of it passes through batch.
    batch_flags = {o.flag for o in COMPARE if o.batch is True} | {"-k", "-n"}
    with_batch = command == "compare" and option.batch is True and all(
        t.split("=")[0] in batch_flags for t in case.cli if t.startswith("--") or t in ("-k", "-n"))
    if with_batch:
        pairs = tmp_path / "pairs.csv"
        pairs.write_text(f"{a},{b},p1\n")
        batch = run([cli, "batch", str(pairs), "--out", str(tmp_path / "o.jsonl"), "-q", *case.cli],
                    tmp_path / "batch")
    if option.keyword is not None:
        try:
            py_result, py_error = python_call(command, a, b, case.py, tmp_path / "py"), None
        except (ValueError, TypeError) as e:
            py_result, py_error = None, e

    if case.outcome == "ok":
        assert got.returncode == 0, got.stderr
        if writes_json:
            target = case.cli[case.cli.index("--json") + 1]
            expected = json.loads((tmp_path / "cli" / target).read_text())
        else:
            expected = json.loads(got.stdout)
        if with_batch:
            assert batch.returncode == 0, batch.stderr
            record = json.loads((tmp_path / "o.jsonl").read_text().splitlines()[0])
            assert record["status"] == "ok", record
            assert differences(record["result"], expected) == []
        if option.keyword is not None:
            assert py_error is None, py_error
            assert differences(py_result, expected) == []
            # The files written are the same, byte for byte.
            assert files_of(tmp_path / "py") == files_of(tmp_path / "cli")
        return
    # Refused: exit 2 naming the option's flag; ValueError / TypeError naming its keyword.
    flag_names = {option.flag, "-k" if option.flag == "--k" else option.flag, "-n" if option.flag == "--samples" else option.flag}
    assert got.returncode == 2, (got.returncode, got.stderr)
    assert any(f in got.stderr for f in flag_names), got.stderr
    assert files_of(tmp_path / "cli") == {}, "a refused run wrote a file"
    if with_batch:
        assert batch.returncode == 2, (batch.returncode, batch.stderr)
        assert any(f in batch.stderr for f in flag_names), batch.stderr
    if option.keyword is not None:
        expected_class = ValueError if case.outcome == "value" else TypeError
        assert type(py_error) is expected_class, (py_error, case)
        assert re.search(rf"\b{option.keyword}\b", str(py_error)), py_error
        assert files_of(tmp_path / "py") == {}


@pytest.mark.parametrize("option,case", [pytest.param(o, c, id=f"python {o.keyword}: {c!r}")
                                         for o in PYTHON_ONLY for c in o.cases])
def test_python_only_keywords(cli, meshes, tmp_path, option, case):
    a, b = meshes
    kw = {k: v(a, b) if callable(v) else v for k, v in case.py.items()}
    if case.outcome == "ok":
        got = meshdiff.compare_files(a, b, **kw)
        maps = got.pop("maps", None)
        assert (maps is not None) == bool(kw.get("maps"))
        flags = {"normalize": "--normalize", "radii": "--radii", "levels": "--levels", "roughness": "--no-roughness"}
        args = []
        for k, v in kw.items():
            if k in ("normalize",):
                args += [flags[k], v]
            elif k in ("radii", "levels"):
                args += [flags[k], ",".join(map(str, v))]
            elif k == "roughness":
                args += [flags[k]]
        expected = json.loads(run([cli, "compare", a, b, *args, "--json", "-"], tmp_path).stdout)
        assert differences(got, expected) == []
        return
    expected_class = ValueError if case.outcome == "value" else TypeError
    with pytest.raises(expected_class, match=rf"^{option.keyword}\b"):
        meshdiff.compare_files(a, b, **kw)


def test_regression_batch_with_every_boolean_flag(cli, meshes, tmp_path):
    """Issue 26 (1): batch with any flag wrote an error line for every pair; now each pair's
    result is compare's for the same flags."""
    a, b = meshes
    pairs = tmp_path / "pairs.csv"
    pairs.write_text(f"{a},{b},p1\n")
    flags = [o.flag for o in COMPARE if o.batch is True and o.flag.startswith("--no-")] + ["--unbiased-variance"]
    assert len(flags) == 8
    for flag in flags:
        extra = ["--measure", "corsini"] if flag == "--unbiased-variance" else []
        out = tmp_path / f"{flag}.jsonl"
        r = run([cli, "batch", str(pairs), "--out", str(out), "-q", flag, *extra], tmp_path)
        assert r.returncode == 0, r.stderr
        record = json.loads(out.read_text())
        expected = json.loads(run([cli, "compare", a, b, flag, *extra, "--json", "-"], tmp_path).stdout)
        assert differences(record["result"], expected) == [], flag


def test_regression_both_tolerances(meshes, cli, tmp_path):
    """Issue 26 (2): with both tolerances the interval stops at max(relative x value, absolute)
    in every front end (Python used to let the absolute one replace the relative one)."""
    a, b = meshes
    py = meshdiff.compare_files(a, b, roughness=False, hausdorff_tolerance=0.3, hausdorff_abs_tolerance=1e-9)
    got = json.loads(run([cli, a, b, "--no-roughness", "--hausdorff-tolerance", "0.3",
                          "--hausdorff-abs-tolerance", "1e-9", "--json", "-"], tmp_path).stdout)
    assert differences(py, got) == []
    for direction in ("forward", "backward"):
        c = got["surface_distance"][direction]["hausdorff"]
        assert c["tolerance"] == max(0.3 * c["lower"], 1e-9), "the larger of the two decides"
        assert c["upper"] - c["lower"] <= c["tolerance"] * (1 + 1e-12)
        assert c["tolerance"] > 1e-3


def test_regression_limits(meshes, cli, tmp_path):
    """Issue 26 (3): the limits of levels and radii are the library's, the same in both front ends."""
    a, _ = meshes
    assert run([cli, "profile", a, "--levels", "1-300"], tmp_path).returncode == 2
    assert run([cli, "profile", a, "--radii", "5000"], tmp_path).returncode == 2
    with pytest.raises(ValueError, match="levels"):
        meshdiff.profile_file(a, levels=range(1, 301))
    with pytest.raises(ValueError, match="radii"):
        meshdiff.profile_file(a, radii=[5000.0])
    assert meshdiff.LIMITS["levels"] == 200 and meshdiff.LIMITS["radius"] == 1000.0


def test_tools_hold_no_limit_or_rule():
    """Issue 26: the command line only maps names. No numeric limit is defined in tools/ (the
    library's constants are used by name), and no CLI11 range check is left there; only the
    exit-code constants are numbers."""
    tools = pathlib.Path(__file__).resolve().parents[2] / "tools"
    # An exit code (as coreutils' timeout), and how the terminal display and batch-summary's text
    # look (no option sets them; they change no result): not limits or defaults of an option.
    allowed = {"kPairTimeout", "kShown", "kTerminalDelay", "kRedraw"}
    for path in sorted(tools.rglob("*.[ch]*")):  # tools/ and tools/batch/
        text = path.read_text()
        for name in re.findall(r"constexpr\s+[\w:<>]+\s+(\w+)\s*(?:=\s*|\{)[\d.]", text):
            assert name in allowed, f"{path.name}: constexpr {name} is a number defined in tools/"
        for check in re.findall(r"->check\(([^)]*)\)", text):
            assert check.startswith("CLI::IsMember(enum_names<"), f"{path.name}: ->check({check}) in tools/"
        assert "in_range(" not in text and "1.8e19" not in text, path.name
