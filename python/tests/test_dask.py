"""Scale out on Dask (issue 32, the recipe of docs/python.md): a list of pairs
evaluated on a distributed.LocalCluster of two worker processes gives, pair for
pair, the results of `meshdiff batch` (its JSON lines' "result"); a DistanceIndex
travels to the workers (it pickles)."""
import functools
import json
import subprocess

import numpy as np
import pytest
from distributed import Client, LocalCluster

import meshdiff
from conftest import child_env

PAIRS = [("bunny_res3.ply", "bunny_res4_ascii.ply"), ("sphere_ico_2562.ply", "sphere_irregular_3072.ply"),
         ("hemisphere.ply", "hemisphere.ply"), ("bunny_res4_ascii.ply", "bunny_res3.ply")]


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    # The workers are new interpreters: they import the meshdiff the tests import (the build tree's
    # through PYTHONPATH, or the installed one).
    with pytest.MonkeyPatch.context() as mp:
        for key, value in child_env().items():
            mp.setenv(key, value)
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                          local_directory=str(tmp_path_factory.mktemp("dask"))) as cluster, Client(cluster) as c:
            yield c


def test_pairs_on_dask_equal_the_batch_lines(client, cli, data, tmp_path):
    originals = [str(data / a) for a, _ in PAIRS]
    processed = [str(data / b) for _, b in PAIRS]
    compare = functools.partial(meshdiff.compare_files, levels=[1, 2, 5], samples=5000, threads=1)
    results = client.gather(client.map(compare, originals, processed, pure=False))

    pairs_csv = tmp_path / "pairs.csv"
    pairs_csv.write_text("".join(f"{a},{b},pair{i}\n" for i, (a, b) in enumerate(zip(originals, processed))))
    out = tmp_path / "results.jsonl"
    subprocess.run([cli, "batch", str(pairs_csv), "--out", str(out), "--levels", "1,2,5", "-n", "5000",
                    "--threads", "1", "-q"], check=True, capture_output=True)
    records = {r["id"]: r for r in map(json.loads, out.read_text().splitlines())}
    assert sorted(records) == [f"pair{i}" for i in range(len(PAIRS))]
    for i, result in enumerate(results):
        record = records[f"pair{i}"]
        assert record["status"] == "ok"
        assert result == record["result"], PAIRS[i]


def test_a_distance_index_goes_to_the_workers(client, data):
    V, F = meshdiff.read_mesh(data / "bunny_res3.ply")
    index = meshdiff.DistanceIndex(V, F, threads=1)
    P = np.random.default_rng(3).uniform(V.min(0), V.max(0), (200, 3))
    remote = client.submit(index.query, P).result()
    for a, b in zip(remote, index.query(P)):
        assert np.array_equal(a, b)


def test_one_original_index_scattered_to_the_workers(client, data):
    """The recipe of docs/python.md: the original's index built once, scattered to every worker and reused by
    compare_files(index_original=...) for each processed mesh: the results of compare_files() without it."""
    a = str(data / "bunny_res3.ply")
    processed = [str(data / "bunny_res4_ascii.ply"), a]
    compare = functools.partial(meshdiff.compare_files, levels=[1, 2], samples=5000, threads=1)
    index = client.scatter(meshdiff.DistanceIndex(*meshdiff.read_mesh(a)), broadcast=True)
    results = client.gather(client.map(compare, [a] * len(processed), processed, index_original=index, pure=False))
    assert results == [compare(a, b) for b in processed]
