"""docs/cli.md states each limit of the options once; the numbers there are the
library's constants (meshdiff.LIMITS, made from them), and each limit holds at
its boundary: the last value accepted, the next refused naming the keyword."""
import pathlib
import re

import pytest

import meshdiff

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs"


def row(option):
    """The 'accepted' cell of the limits table's row of \\p option (a backquoted flag)."""
    text = (DOCS / "cli.md").read_text()
    table = text[text.index("## Limits of options"):]
    for line in table.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 3 and cells[1].startswith(option):
            return cells[2]
    raise AssertionError(f"no row for {option} in docs/cli.md's limits table")


def numbers(cell):
    """The numbers of a cell, in order (1,000 is one thousand; 1e-12 is a number)."""
    return [float(x.replace(",", "")) for x in re.findall(r"\d[\d,]*(?:\.\d+)?(?:e-?\d+)?", cell)]


def test_the_table_states_the_library_limits():
    L = meshdiff.LIMITS
    assert numbers(row("`--samples`"))[:2] == [1, L["samples"]]
    assert numbers(row("`--threads`"))[:2] == [0, L["threads"]]
    assert numbers(row("`--levels`"))[:3] == [L["levels"], 1, L["level"]]
    assert numbers(row("`--radii`"))[:4] == [L["radii"], 0, L["radius"], L["mean_ball_vertices"]]
    assert numbers(row("`--hausdorff-tolerance`"))[:2] == list(L["hausdorff_tolerance"])
    assert numbers(row("`--hausdorff-budget`"))[:2] == [1, L["hausdorff_budget"]]
    assert numbers(row("`--fscore`"))[:3] == [L["fscore"], 0, L["fscore_threshold"]]
    assert numbers(row("`--histogram`"))[:2] == [0, L["histogram"]]


def test_python_md_points_to_the_one_table():
    text = (DOCS / "python.md").read_text()
    assert "cli.md#limits-of-options-and-how-outputs-are-written" in text
    for restated in ("at most 200", "at most 64", "1 .. 250"):
        assert restated not in text, f"docs/python.md restates a limit: {restated!r}"


@pytest.fixture(scope="module")
def sphere(data):
    return meshdiff.read_mesh(data / "sphere_ico_2562.ply")


def test_each_limit_holds_at_its_boundary(sphere):
    V, F = sphere
    L = meshdiff.LIMITS
    assert len(meshdiff.profile(V, F, levels=range(1, L["levels"] + 1), global_level=False)["sigma"]) == L["levels"]
    with pytest.raises(ValueError, match="^levels: "):
        meshdiff.profile(V, F, levels=range(1, L["levels"] + 2))
    with pytest.raises(ValueError, match="^levels: "):
        meshdiff.profile(V, F, levels=[L["level"] + 1])
    assert len(meshdiff.profile(V, F, levels=[1], radii=[0.1] * L["radii"])["sigma_radii"]) == L["radii"]
    with pytest.raises(ValueError, match="^radii: "):
        meshdiff.profile(V, F, radii=[0.1] * (L["radii"] + 1))
    with pytest.raises(ValueError, match="^radii: "):
        meshdiff.profile(V, F, radii=[L["radius"] * (1 + 1e-15)])
    for kw in (dict(threads=L["threads"] + 1), dict(samples=L["samples"] + 1), dict(histogram=L["histogram"] + 1),
               dict(hausdorff_budget=L["hausdorff_budget"] + 1), dict(fscore=[L["fscore_threshold"] * 1.5]),
               dict(fscore=[0.01] * (L["fscore"] + 1)), dict(hausdorff_tolerance=L["hausdorff_tolerance"][1] * 1.01),
               dict(hausdorff_tolerance=L["hausdorff_tolerance"][0] * 0.99)):
        with pytest.raises(ValueError, match="^" + next(iter(kw)) + ": "):
            meshdiff.compare(V, F, V, F, roughness=False, **kw)
    r = meshdiff.compare(V, F, V, F, roughness=False, samples=3000, histogram=L["histogram"],
                         hausdorff_tolerance=L["hausdorff_tolerance"][1], fscore=[L["fscore_threshold"]])
    assert len(r["surface_distance"]["forward"]["histogram"]["counts"]) == L["histogram"]
