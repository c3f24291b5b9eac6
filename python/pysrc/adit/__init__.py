"""adit: a 2D distinct element engine for jointed rock, from Python.

Load a scene from a file or build it as a dict, change it, run it and get its results as NumPy
arrays::

    import adit
    scene = adit.load_scene("models/kirsch.json")
    scene["in_situ"]["sxx"] = -15e6
    result = adit.run(scene, out="out/kirsch_15", progress=lambda row: print(row["ratio"]))
    result.zones["stress_pa"]          # (zones, 4): sxx, syy, szz, sxy in Pa, tension positive

Units are SI (m, Pa, kg, s). A run writes the same files as ``adit run`` (ParaView collection,
history, summary) into its output folder and gives the same numbers to the last bit.
Sweeps of parameters and joint realizations: ``adit.sweep`` (module ``adit.sweep``).
"""

from __future__ import annotations

import csv
import json
import os
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Dict, List, Mapping, Optional, TypedDict, Union

import numpy as np

from . import _adit

__all__ = [
    "AditWarning",
    "ProgressRow",
    "Results",
    "SceneLike",
    "check",
    "load_scene",
    "run",
    "sweep",
    "version",
]

#: A scene: a dict as the scene format describes it (docs/scene-format.md), or the path of a
#: scene file.
SceneLike = Union[Mapping[str, Any], str, "os.PathLike[str]"]


class ProgressRow(TypedDict):
    """What ``progress`` receives at each monitor step."""

    cycle: int
    time_s: float
    ratio: float
    kinetic_energy_j_per_m: float


def version() -> str:
    """The engine's version."""
    return _adit.version()


def load_scene(path: Union[str, "os.PathLike[str]"]) -> Dict[str, Any]:
    """The scene file at ``path`` as a dict, to change before ``run``."""
    with open(path, encoding="utf-8-sig") as f:
        return json.load(f)


class AditWarning(UserWarning):
    """What a run says that is worth a look but is no error: a run stopped at its cycle limit
    (not at equilibrium), a build's repairs, a liner over capacity."""


def _plain(value: Any) -> Any:
    """``value`` as JSON can hold it: NumPy scalars as Python numbers, arrays as lists."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise TypeError(f"a scene holds numbers, strings, lists and dicts, not {type(value).__name__}")


def _scene_json(scene: SceneLike) -> str:
    if isinstance(scene, (str, os.PathLike)):
        scene = load_scene(scene)
    return json.dumps(scene, default=_plain)


def check(scene: SceneLike) -> None:
    """Validate and build ``scene`` as ``run`` does, without solving: raises ``ValueError``
    naming the field (its JSON path) for exactly what ``run`` would refuse."""
    _adit.check(_scene_json(scene))


@dataclass(frozen=True)
class Results:
    """The results of a run, as NumPy arrays in SI units (names carry the unit).

    Tables (dicts of equal-length arrays, one row per item):

    - ``nodes``: ``position_m`` (n, 2), ``displacement_m`` (n, 2), ``velocity_m_per_s`` (n, 2),
      ``stress_nodal_pa`` (n, 4: the recovered nodal stress sxx, syy, szz, sxy), ``block``,
      ``fixed`` (bit flags: 1 x, 2 y, 4 part of a rigid or simple block);
    - ``zones``: ``nodes`` (z, 3), ``stress_pa`` (z, 4: sxx, syy, szz, sxy), ``state`` (yield
      bit flags, 0 elastic), ``block``, ``material`` (index into ``materials``), ``area_m2``,
      ``plastic_strain``, ``recovery_error_pa`` (the zone's error indicator), ``excavated``
      (1 when its block was excavated);
    - ``contacts``: ``node``, ``edge_nodes`` (c, 2), ``block`` (the edge's block),
      ``position_m`` (c, 2), ``length_m``, ``normal_stress_pa``, ``shear_stress_pa``,
      ``normal_displacement_m``, ``shear_displacement_m``, ``jrc_mobilized`` (Barton–Bandis
      joints; 0 for the other laws), ``state`` (0 elastic, 1 slipping, 2 open), ``material`` (index into ``joint_materials``);
    - ``bolts`` (one row per segment) and ``liners`` (one row per element): ``ends_m`` (s, 4:
      x0, y0, x1, y1), ``group`` (index into ``bolt_groups`` or ``liner_groups``),
      ``installed``, ``axial_force_n_per_m`` (tension positive, per metre of tunnel); bolts
      ``yielded``, liners ``moment_n_m_per_m`` (s, 2: at each end), ``shear_force_n_per_m``
      and ``utilization`` (1 over the element's factor of safety; 0 without a ``capacity``);
    - ``history``: ``cycle``, ``time_s``, ``ratio``, ``kinetic_energy_j_per_m`` per monitor step.

    ``summary`` is ``summary.json`` as a dict (with ``stages``, each with its ``closure`` per
    excavation in m and its ``walls``: crown, invert and side walls' moves); ``out_dir`` the
    folder the run wrote; ``histories`` the monitoring points' records.
    """

    nodes: Dict[str, np.ndarray]
    zones: Dict[str, np.ndarray]
    contacts: Dict[str, np.ndarray]
    bolts: Dict[str, np.ndarray]
    liners: Dict[str, np.ndarray]
    history: Dict[str, np.ndarray]
    materials: List[str]
    joint_materials: List[str]
    bolt_groups: List[str]
    liner_groups: List[str]
    summary: Dict[str, Any] = field(repr=False)
    out_dir: Path

    def __repr__(self) -> str:
        s = self.summary
        return (
            f"Results({s['scene']!r}, status={self.status!r}, zones={s['zones']}, "
            f"nodes={s['nodes']}, blocks={s['blocks']}, cycles={s['cycles']}, "
            f"out_dir={str(self.out_dir)!r})"
        )

    @property
    def status(self) -> str:
        """``converged``, ``cycle_limit``, ``failed`` or ``interrupted``."""
        return self.summary["status"]

    @property
    def histories(self) -> Dict[str, np.ndarray]:
        """The monitoring points' records (scene ``histories``, ``histories.csv``): ``cycle``,
        ``time_s`` and one array per point, named as the file's columns
        (``<name>:<quantity>_<unit>``, e.g. ``crown:displacement_y_m``); empty without them."""
        path = self.out_dir / "histories.csv"
        if not path.exists():
            return {}
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header, values = rows[0], np.array(rows[1:], dtype=float).reshape(-1, len(rows[0]))
        return {name: values[:, i] for i, name in enumerate(header)}

    @property
    def stages(self) -> List[Dict[str, Any]]:
        """Each stage's summary, in order (empty for a scene without stages)."""
        return self.summary.get("stages", [])

    def closure(self, excavation: str) -> float:
        """Mean wall closure (m, inward positive) of ``excavation`` at the end of the run."""
        for stage in reversed(self.stages):
            if excavation in stage["closure"]:
                return stage["closure"][excavation]
        made = sorted({name for stage in self.stages for name in stage["closure"]})
        there = ", ".join(repr(name) for name in made) if made else "none"
        raise KeyError(
            f"no stage excavated {excavation!r}; the excavations the stages made: {there}"
        )


def run(
    scene: SceneLike,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    progress: Optional[Callable[[ProgressRow], None]] = None,
    from_stage: int = 1,
    from_checkpoint: Optional[Union[str, "os.PathLike[str]"]] = None,
) -> Results:
    """Run ``scene`` and return its results.

    The run writes its files into ``out`` (default: the scene's ``output.folder``, else the
    first of ``out/<name>``, ``out/<name>-2``, ... that no earlier run wrote, so that a run never
    writes over another), as ``adit run`` does; ``Results.out_dir`` is that folder, absolute.
    ``progress`` is called at each monitor step. Ctrl-C stops the run at the end of a cycle,
    writes its last state (summary status ``interrupted``) and raises ``KeyboardInterrupt``; an
    exception in ``progress`` stops it the same way and is raised. A scene that is not valid
    raises ``ValueError`` naming the field; a run that cannot be built, or whose solve fails (a
    NaN, runaway energy, interpenetration), raises ``RuntimeError`` with the reason (its files,
    summary status ``failed``, stay in ``out_dir``). A run that stops at its cycle limit, not at
    equilibrium, and each warning of the build (``summary["warnings"]``) issue an
    ``AditWarning``.

    Each stage that ends leaves a checkpoint in ``out/checkpoints/``; ``from_stage=N`` goes on
    from the one stage N - 1 left, giving the numbers of the run that was not stopped (the
    results then hold the whole run). ``from_checkpoint`` branches (UDEC's save and restore):
    the checkpoint of a stage of this scene, or of another whose stages up to it are the same
    (the same excavation, another bolt pattern, liner or strength after it), and only the later
    stages run; ``out`` then holds the files of a whole run of ``scene``. A scene whose earlier
    stages differ is refused (``RuntimeError``) naming the first field that differs.
    """
    raw = _adit.run(
        _scene_json(scene),
        None if out is None else os.fspath(out),
        progress,
        from_stage,
        None if from_checkpoint is None else os.fspath(from_checkpoint),
    )
    results = Results(
        nodes=raw["nodes"],
        zones=raw["zones"],
        contacts=raw["contacts"],
        bolts=raw["bolts"],
        liners=raw["liners"],
        history=raw["history"],
        materials=raw["materials"],
        joint_materials=raw["joint_materials"],
        bolt_groups=raw["bolt_groups"],
        liner_groups=raw["liner_groups"],
        summary=json.loads(raw["summary_json"]),
        out_dir=Path(raw["out_dir"]),
    )
    _report(results)
    return results


def _report(results: Results) -> None:
    """Raise on a failed solve; warn of a cycle limit and of each build warning."""
    s = results.summary
    if results.status == "failed":
        raise RuntimeError(
            f"the solve failed: {s.get('reason', 'no reason given')} "
            f"(its last state is in {results.out_dir})"
        )
    for w in s.get("warnings", []):
        warnings.warn(w, AditWarning, stacklevel=3)
    if results.status == "cycle_limit":
        ratio = s.get("final_ratio")
        warnings.warn(
            f"the run stopped at its cycle limit ({s['cycles']} cycles, ratio {ratio}), not at "
            "equilibrium: its results are not converged (raise solve.max_cycles, or see "
            "summary['stages'])",
            AditWarning,
            stacklevel=3,
        )


from .sweep import sweep  # noqa: E402  (sweep uses run)
