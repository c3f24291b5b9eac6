"""adit.run: a scene from a file or a dict, results as NumPy arrays, the same numbers as the CLI."""

import os
import signal
import subprocess
import time

import meshio
import numpy as np
import pytest

import adit


def test_kirsch_gives_the_cli_stresses_to_the_last_bit(root, cli, tmp_path):
    scene = root / "models" / "kirsch.json"
    r = adit.run(scene, out=tmp_path / "py")
    subprocess.run([cli, "run", scene, "--quiet", "--out", tmp_path / "cli"], check=True)
    steps = sorted((tmp_path / "cli").glob("kirsch_zones_*.vtu"))
    m = meshio.read(steps[-1])
    stress = m.cell_data["stress"][0].reshape(-1, 9)
    mine = r.zones["stress_pa"]
    assert stress.shape[0] == mine.shape[0] == r.summary["zones"]
    # The file holds the 3x3 tensor: sxx sxy 0 / sxy syy 0 / 0 0 szz.
    assert np.array_equal(stress[:, 0], mine[:, 0])
    assert np.array_equal(stress[:, 4], mine[:, 1])
    assert np.array_equal(stress[:, 8], mine[:, 2])
    assert np.array_equal(stress[:, 1], mine[:, 3])
    assert np.array_equal(m.points[:, :2], r.nodes["position_m"])
    assert np.array_equal(m.point_data["displacement"][:, :2], r.nodes["displacement_m"])
    assert r.status == "converged"


def test_a_scene_changed_as_a_dict_runs_changed(root, tmp_path):
    scene = adit.load_scene(root / "models" / "kirsch.json")
    scene["zoning"]["edge_at_excavation"] = 0.3
    scene["zoning"]["edge_far"] = 8.0
    scene["excavations"][0]["circle"]["segments"] = 24
    a = adit.run(scene, out=tmp_path / "a")
    scene["in_situ"]["sxx"] *= 2
    scene["in_situ"]["syy"] *= 2
    b = adit.run(scene, out=tmp_path / "b")
    # Elastic: twice the load, twice the stress (to the solver's tolerance).
    assert np.allclose(b.zones["stress_pa"], 2 * a.zones["stress_pa"], rtol=1e-3, atol=1e4)
    assert a.zones["nodes"].shape == (a.summary["zones"], 3)
    assert a.nodes["stress_nodal_pa"].shape == (a.summary["nodes"], 4)
    assert a.materials[a.zones["material"][0]] == scene["region"]["material"]
    assert len(a.history["ratio"]) > 0 and a.history["ratio"][-1] <= scene["solve"]["ratio"]


def test_a_bad_scene_names_its_field(root):
    scene = adit.load_scene(root / "models" / "kirsch.json")
    scene["materials"]["rock"]["poisson"] = 0.7
    with pytest.raises(ValueError, match="poisson"):
        adit.check(scene)
    scene["materials"]["rock"]["poisson"] = 0.25
    scene["zoning"]["edge_far"] = "far"
    with pytest.raises(ValueError, match="edge_far"):
        adit.run(scene)


def test_jointed_results_have_contacts_and_supports(root, tmp_path):
    r = adit.run(root / "models" / "tunnel.json", out=tmp_path)
    c = r.contacts
    n = len(c["node"])
    assert n > 1000
    assert c["position_m"].shape == (n, 2) and c["edge_nodes"].shape == (n, 2)
    assert set(np.unique(c["state"])) <= {0, 1, 2}
    assert (c["normal_stress_pa"] < 0).mean() > 0.9
    assert r.bolts["ends_m"].shape[1] == 4 and len(r.bolts["axial_force_n_per_m"]) > 0
    assert r.liners["moment_n_m_per_m"].shape[1] == 2
    # The shotcrete is over capacity somewhere: utilization 1/FS above 1, as the summary says.
    least = r.summary["liners"][0]["factor_of_safety"]
    assert np.isclose(r.liners["utilization"].max(), 1 / least, rtol=1e-12)
    assert least < 1 and len(r.liners["shear_force_n_per_m"]) == len(r.liners["group"])
    assert r.stages[-1]["name"] == "bolts and shotcrete"
    # The monitoring points, as histories.csv holds them (issue 49).
    h = r.histories
    assert {"cycle", "time_s", "crown:displacement_y_m"} <= set(h)
    assert len(h["cycle"]) == len(h["crown:displacement_y_m"]) > 10
    walls = r.stages[-1]["walls"]["tunnel"]
    assert np.isclose(-h["crown:displacement_y_m"][-1], walls["crown_m"], rtol=0.05)
    assert 5e-3 < r.closure("tunnel") < 2e-2
    # A misspelt excavation is named with those there are (issue 49, friction item 7).
    with pytest.raises(KeyError, match="the excavations the stages made: 'tunnel'"):
        r.closure("Tunnel")
    # Excavated zones are flagged, and hold no stress.
    gone = r.zones["excavated"] == 1
    assert gone.sum() > 100 and np.all(r.zones["stress_pa"][gone] == 0)


def test_progress_is_called_and_its_exception_stops_the_run(root, tmp_path):
    """Explicitly, every monitor step calls back (the default ``auto`` solves the elastic hole
    implicitly in a few iterations)."""
    kirsch = adit.load_scene(root / "models" / "kirsch.json")
    kirsch["solve"]["method"] = "explicit"
    rows = []
    adit.run(kirsch, out=tmp_path / "a", progress=rows.append)
    assert len(rows) > 5 and rows[-1]["ratio"] < rows[0]["ratio"]
    assert set(rows[0]) == {"cycle", "time_s", "ratio", "kinetic_energy_j_per_m"}

    def fail(row):
        if row["cycle"] >= 100:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        adit.run(kirsch, out=tmp_path / "b", progress=fail)


def test_ctrl_c_stops_the_run_and_leaves_it_interrupted(root, tmp_path):
    """A real SIGINT, as Ctrl-C sends it, half way through the tunnel model cycled explicitly:
    sent once the run has cycled 200 times (a timer could fire before the run starts or after
    it ends on a loaded machine)."""
    tunnel = adit.load_scene(root / "models" / "tunnel.json")
    tunnel["solve"]["method"] = "explicit"
    sent = []

    def ctrl_c(row):
        if row["cycle"] >= 200 and not sent:
            sent.append(row["cycle"])
            os.kill(os.getpid(), signal.SIGINT)
            # Python hands the signal to the main thread, which looks every 20 ms; on a loaded
            # machine the run (on its own thread) could end before it looks: wait for it here.
            time.sleep(1.0)

    # A shell starts a background job with SIGINT ignored, and Python then leaves it ignored:
    # give it Python's own handler, as an interactive session has.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            adit.run(tunnel, out=tmp_path, progress=ctrl_c)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert sent
    summary = (tmp_path / "summary.json").read_text()
    assert '"interrupted"' in summary
    # The next run of this process is not stopped by the earlier Ctrl-C.
    assert adit.run(root / "models" / "kirsch.json", out=tmp_path / "next").status == "converged"


def test_a_run_from_stage_2_equals_the_whole_run(root, tmp_path):
    scene = root / "models" / "tunnel.json"
    whole = adit.run(scene, out=tmp_path)
    again = adit.run(scene, out=tmp_path, from_stage=2)
    assert np.array_equal(whole.zones["stress_pa"], again.zones["stress_pa"])
    assert np.array_equal(whole.nodes["displacement_m"], again.nodes["displacement_m"])
    assert np.array_equal(whole.history["ratio"], again.history["ratio"])
    assert whole.summary["stages"] == again.summary["stages"]


def test_a_branch_from_the_excavation_equals_the_whole_run_of_its_scene(root, tmp_path):
    """Issue 49: the tunnel excavated once, continued with bolts closer together."""
    base = adit.run(root / "models" / "tunnel.json", out=tmp_path / "base")
    closer = adit.load_scene(root / "models" / "tunnel.json")
    closer["bolts"][0]["pattern"].update(spacing=0.9, count=13)
    whole = adit.run(closer, out=tmp_path / "whole")
    checkpoint = base.out_dir / "checkpoints" / "stage_02.ckpt"
    branch = adit.run(closer, out=tmp_path / "branch", from_checkpoint=checkpoint)
    for table in ("zones", "nodes", "bolts", "liners"):
        for name, values in whole.__dict__[table].items():
            assert np.array_equal(values, branch.__dict__[table][name]), (table, name)
    assert whole.summary["stages"] == branch.summary["stages"]
    assert len(branch.bolts["group"]) > len(base.bolts["group"])
    earlier = adit.load_scene(root / "models" / "tunnel.json")
    earlier["stages"][1]["support_fraction"] = 0.3
    with pytest.raises(RuntimeError, match=r"first at stages\[1\]\.support_fraction"):
        adit.run(earlier, out=tmp_path / "refused", from_checkpoint=checkpoint)
