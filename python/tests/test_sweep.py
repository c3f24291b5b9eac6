"""adit.sweep: the same sweep on a Dask LocalCluster and on the local pool gives the same table;
killed half way, a sweep started again makes only the runs still missing."""

import csv
import json
import os
import subprocess
import sys
import time

import pytest

import adit


def figures(table):
    """The table's rows without the seconds (the only column that differs between machines)."""
    with open(table) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r.pop("wall_seconds")
    return rows


@pytest.fixture(scope="module")
def on_dask(root, tmp_path_factory):
    from distributed import Client, LocalCluster

    out = tmp_path_factory.mktemp("dask")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        with Client(cluster) as client:
            r = adit.sweep(root / "models" / "tunnel_sweep.json", out=out, client=client)
    return r


@pytest.fixture(scope="module")
def root():
    from conftest import ROOT

    return ROOT


def test_sixteen_realizations_run_on_a_dask_cluster(on_dask):
    r = on_dask
    assert len(r.rows) == 16 and r.ran == 16
    assert all(row["status"] == "converged" for row in r.rows), [row.get("error") for row in r.rows]
    assert r.table.exists() and r.plot.exists()
    closures = [row["closure_m"]["tunnel"] for row in r.rows]
    assert len(set(closures)) > 8, "realizations differ"
    assert all(row["max_bolt_force_n_per_m"] > 0 for row in r.rows)


def test_the_local_pool_killed_half_way_and_restarted_gives_the_dask_table(on_dask, root, tmp_path):
    spec = root / "models" / "tunnel_sweep.json"
    command = [sys.executable, "-m", "adit.sweep", str(spec), "--out", str(tmp_path), "--workers", "2"]
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    runs = tmp_path / "runs"
    start = time.time()
    while len(list(runs.glob("*/row.json"))) < 3 and time.time() - start < 300:
        time.sleep(0.02)
    child.kill()
    child.wait()
    done = len(list(runs.glob("*/row.json")))
    assert 3 <= done < 16, f"{done} runs done when killed"
    assert not (tmp_path / "sweep.csv").exists()
    again = adit.sweep(spec, out=tmp_path, workers=2)
    assert again.ran == 16 - done
    assert figures(again.table) == figures(on_dask.table)


def test_a_spec_as_a_dict_draws_its_runs_and_a_failing_run_is_a_row(root, tmp_path):
    spec = {
        "name": "small",
        "base": str(root / "models" / "kirsch.json"),
        "grid": {
            "zoning.edge_far": [8.0],
            "zoning.edge_at_excavation": [0.3],
            # The second value is not a Poisson's ratio: that run fails, naming the field.
            "materials.rock.poisson": [0.25, 0.7],
        },
        "draws": {"count": 2, "seed": 5, "uniform": {"in_situ.sxx": [-20e6, -10e6]}},
    }
    r = adit.sweep(spec, out=tmp_path, workers=2)
    assert [row["id"] for row in r.rows] == ["run_0000", "run_0001", "run_0002", "run_0003"]
    statuses = [row["status"] for row in r.rows]
    assert statuses == ["converged", "converged", "failed", "failed"], statuses
    assert all("poisson" in row["error"] for row in r.rows[2:])
    sxx = [row["params"]["in_situ.sxx"] for row in r.rows]
    assert sxx[0] == sxx[2] and sxx[1] == sxx[3] and sxx[0] != sxx[1], "common draws"
    assert all(-20e6 <= x < -10e6 for x in sxx)
    again = adit.sweep(spec, out=tmp_path, workers=2)
    assert again.ran == 0, "every run, failed ones too, has its row"
    try:
        import pyarrow.parquet as pq
    except ImportError:
        return
    assert pq.read_table(tmp_path / "sweep.parquet").num_rows == 4


def test_the_command_line_hands_a_sweep_to_a_dask_scheduler(root, cli, tmp_path):
    """`adit sweep SPEC --scheduler ADDRESS`: the CLI hands the sweep to `python -m adit.sweep`."""
    from distributed import LocalCluster

    spec = {
        "name": "small",
        "base": str(root / "models" / "kirsch.json"),
        "grid": {"zoning.edge_far": [8.0], "zoning.edge_at_excavation": [0.3, 0.4]},
    }
    path = tmp_path / "spec.json"
    path.write_text(json.dumps(spec))
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True) as cluster:
        done = subprocess.run(
            [cli, "sweep", path, "--scheduler", cluster.scheduler_address, "--out", tmp_path / "out"],
            capture_output=True,
            text=True,
            env={**os.environ, "ADIT_PYTHON": sys.executable},
        )
    assert done.returncode == 0, done.stderr
    rows = figures(tmp_path / "out" / "sweep.csv")
    assert [r["status"] for r in rows] == ["converged", "converged"]
