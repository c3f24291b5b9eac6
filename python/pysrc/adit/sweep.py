"""Sweeps: one base scene run over a grid or random draws of parameters and joint realizations.

``adit.sweep(spec)`` takes the sweep spec of ``adit sweep`` (docs: README, "Sweeps") as a dict or a
file: each run is independent and goes to a local process pool by default, or to a Dask
distributed cluster when given a scheduler's address or a ``distributed.Client`` (so the same
sweep runs on a workstation or on an HPC allocation through dask-jobqueue). The runs are gathered
into ``sweep.csv`` (and ``sweep.parquet`` when pyarrow is installed) with each run's inputs,
status, wall closure per excavation, yielded zones, largest bolt force and liner thrust, and
``sweep.png`` plots their spread. A failing run is a row with its error. Each finished run leaves
its row in ``<out>/runs/<id>/row.json``: a sweep interrupted and started again runs only what is
missing.

The local pool starts fresh Python processes (spawn), which import the calling script again: a
script that calls ``adit.sweep`` does so under ``if __name__ == "__main__":``.

From the command line, on a Dask cluster: ``python -m adit.sweep SPEC --scheduler ADDRESS``
(which ``adit sweep SPEC --scheduler ADDRESS`` calls).
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import json
import multiprocessing
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Union

from . import _adit

SpecLike = Union[Mapping[str, Any], str, "os.PathLike[str]"]


@dataclass(frozen=True)
class SweepResult:
    """What a sweep gave: one row per run (dicts, in the runs' order), and its files."""

    rows: List[Dict[str, Any]]
    out_dir: Path
    table: Path
    plot: Path
    #: How many runs were made now (the others were done before).
    ran: int


def _run_one(base_json: str, run_id: str, params_json: str, out: str) -> str:
    """One run on a worker (a pool's process or a Dask worker): its row as JSON text."""
    return _adit.sweep_run(base_json, run_id, params_json, out)


def _spec_json(spec: SpecLike) -> "tuple[str, Path]":
    if isinstance(spec, (str, os.PathLike)):
        path = Path(spec)
        return path.read_text(encoding="utf-8-sig"), path.parent
    return json.dumps(spec), Path.cwd()


def sweep(
    spec: SpecLike,
    *,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    workers: Optional[int] = None,
    scheduler: Optional[str] = None,
    client: Any = None,
) -> SweepResult:
    """Run the sweep ``spec`` (a dict or a spec file) and gather its table.

    ``out``: the output folder (default: the spec's ``out``, else ``out/<name>``). ``workers``:
    processes of the local pool (default: the machine's cores). ``scheduler``: a Dask
    scheduler's address, or ``client``: a ``distributed.Client``; either sends the runs to that
    cluster instead of the local pool. Runs already done (their ``row.json`` with the same
    parameters) are not made again. Ctrl-C cancels the runs not started, and raises
    ``KeyboardInterrupt``: run the same sweep again to make what is missing.
    """
    text, spec_dir = _spec_json(spec)
    name, default_out, base_json, runs = _adit.sweep_plan(text, os.fspath(spec_dir))
    out_dir = Path(out if out is not None else default_out).resolve()
    out_dir.mkdir(parents=True, exist_ok=True)
    # A table that exists is of a sweep that finished: the last one's goes now.
    _adit.sweep_clear(os.fspath(out_dir))
    rows: Dict[str, str] = {}
    todo = []
    for run_id, params in runs:
        row = _adit.sweep_done(os.fspath(out_dir), run_id, params)
        if row is None:
            todo.append((run_id, params))
        else:
            rows[run_id] = row
    args = [(base_json, run_id, params, os.fspath(out_dir)) for run_id, params in todo]
    if todo:
        if client is not None or scheduler is not None:
            _on_dask(args, rows, client, scheduler)
        else:
            _on_pool(args, rows, workers)
    ordered = [rows[run_id] for run_id, _ in runs]
    for warning in _adit.sweep_table(os.fspath(out_dir), ordered):
        print(f"warning: {warning}", file=sys.stderr)
    parsed = [json.loads(r) for r in ordered]
    _parquet(out_dir / "sweep.csv", out_dir / "sweep.parquet")
    return SweepResult(
        rows=parsed,
        out_dir=out_dir,
        table=out_dir / "sweep.csv",
        plot=out_dir / "sweep.png",
        ran=len(todo),
    )


def _on_pool(args, rows: Dict[str, str], workers: Optional[int]) -> None:
    # Fresh processes (spawn): no state of this one, nor its threads, is copied into them.
    context = multiprocessing.get_context("spawn")
    with cf.ProcessPoolExecutor(max_workers=workers or os.cpu_count(), mp_context=context) as pool:
        futures = {pool.submit(_run_one, *a): a[1] for a in args}
        try:
            for f in cf.as_completed(futures):
                rows[futures[f]] = f.result()
        except KeyboardInterrupt:
            for f in futures:
                f.cancel()
            raise


def _on_dask(args, rows: Dict[str, str], client: Any, scheduler: Optional[str]) -> None:
    from distributed import Client, as_completed

    own = client is None
    client = client or Client(scheduler)
    try:
        futures = [client.submit(_run_one, *a, key=f"adit-{a[1]}-{hash(a)}", pure=False) for a in args]
        ids = {f.key: a[1] for f, a in zip(futures, args)}
        try:
            for f in as_completed(futures):
                rows[ids[f.key]] = f.result()
        except KeyboardInterrupt:
            client.cancel(futures)
            raise
    finally:
        if own:
            client.close()


def _parquet(table: Path, path: Path) -> None:
    """``sweep.parquet`` beside the CSV, its columns the CSV's, when pyarrow is installed."""
    try:
        import pyarrow.csv as pc
        import pyarrow.parquet as pq
    except ImportError:
        return
    pq.write_table(pc.read_csv(table), path)


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m adit.sweep", description=__doc__.splitlines()[0])
    parser.add_argument("spec")
    parser.add_argument("--out")
    parser.add_argument("--workers", type=int)
    parser.add_argument("--scheduler", help="a Dask scheduler's address")
    a = parser.parse_args(argv)
    try:
        r = sweep(a.spec, out=a.out, workers=a.workers, scheduler=a.scheduler)
    except KeyboardInterrupt:
        print("interrupted: run the same command again to make the runs still missing", file=sys.stderr)
        return 130
    failed = sum(1 for row in r.rows if row["status"] == "failed")
    print(f"{len(r.rows)} runs ({r.ran} made now, {failed} failed); table {r.table}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
