"""The friction a new user met in the Python package (issue 49), each item's fix held by a test."""

import json
import os
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import adit


def small_kirsch(root):
    """The Kirsch hole zoned coarsely: a run of a second or less."""
    scene = adit.load_scene(root / "models" / "kirsch.json")
    scene["zoning"] = {"edge_at_excavation": 0.3, "edge_far": 8.0}
    scene["excavations"][0]["circle"]["segments"] = 24
    return scene


def test_a_failed_solve_raises_with_its_reason(tmp_path):
    """Item 2: a run whose solve fails raises ``RuntimeError`` naming the reason, its files kept."""
    loose = {
        "name": "loose",
        "materials": {"rock": {"density": 2500, "young": 10e9, "poisson": 0.25}},
        "region": {"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"},
        "zoning": {"edge_at_excavation": 0.5, "edge_far": 0.5},
        "boundary": [{"part": "outer", "normal_stress": -1e6}],
        "solve": {"method": "implicit"},
    }
    with pytest.raises(RuntimeError, match=r"the solve failed: .*held by nothing"):
        adit.run(loose, out=tmp_path)
    assert json.loads((tmp_path / "summary.json").read_text())["status"] == "failed"


def test_a_cycle_limit_and_build_warnings_are_python_warnings(root, tmp_path):
    """Item 2: a run stopped at its cycle limit, and each build warning, is an ``AditWarning``."""
    scene = small_kirsch(root)
    scene["solve"]["max_cycles"] = 20
    scene["solve"]["method"] = "explicit"
    # Compression positive, as RS2 users give it: tensile in-situ stress, warned by the build.
    scene["in_situ"]["sxx"] = 5e6
    with pytest.warns(adit.AditWarning) as caught:
        r = adit.run(scene, out=tmp_path)
    assert r.status == "cycle_limit"
    said = [str(w.message) for w in caught]
    assert any("cycle limit" in m and "not converged" in m for m in said), said
    assert any("in_situ.sxx" in m for m in said), said
    # A converged run with nothing to say warns of nothing.
    with warnings.catch_warnings():
        warnings.simplefilter("error", adit.AditWarning)
        assert adit.run(small_kirsch(root), out=tmp_path / "quiet").status == "converged"


def test_runs_without_out_go_to_fresh_absolute_folders(root, tmp_path, monkeypatch):
    """Item 3: two runs given no folder write two folders, absolute, never one over the other."""
    monkeypatch.chdir(tmp_path)
    scene = small_kirsch(root)
    first = adit.run(scene)
    second = adit.run(scene)
    assert first.out_dir.is_absolute() and second.out_dir.is_absolute()
    assert first.out_dir == tmp_path / "out" / "kirsch"
    assert second.out_dir == tmp_path / "out" / "kirsch-2"
    assert (first.out_dir / "summary.json").exists() and (second.out_dir / "summary.json").exists()
    given = adit.run(scene, out="relative")
    assert given.out_dir == tmp_path / "relative"


def test_check_refuses_what_run_refuses(root, tmp_path):
    """Item 4: a scene valid as JSON whose run would stop once built (here the implicit path
    asked of large-strain zones, which it does not assemble) is refused by ``check`` too, with
    the same words."""
    scene = small_kirsch(root)
    scene["solve"]["method"] = "implicit"
    scene["solve"]["large_strain"] = True
    with pytest.raises(ValueError, match=r"^solve.method: implicit cannot solve this model") as c:
        adit.check(scene)
    with pytest.raises(RuntimeError) as r:
        adit.run(scene, out=tmp_path)
    assert str(c.value) == str(r.value)
    scene["solve"]["method"] = "auto"
    adit.check(scene)


def test_numpy_scalars_and_arrays_are_scene_values_and_results_print_short(root, tmp_path):
    """Item 5: NumPy numbers and arrays go in a scene as they are; ``repr`` of the results is a
    line, not every array."""
    scene = small_kirsch(root)
    base = adit.run(scene, out=tmp_path / "plain")
    scene["in_situ"]["sxx"] = np.float32(-10e6)
    scene["in_situ"]["syy"] = np.int64(-20_000_000)
    scene["region"]["polygon"] = np.array(scene["region"]["polygon"], dtype=float)
    scene["excavations"][0]["circle"]["segments"] = np.int32(24)
    r = adit.run(scene, out=tmp_path / "numpy")
    assert np.array_equal(r.zones["stress_pa"], base.zones["stress_pa"])
    text = repr(r)
    assert len(text) < 300 and "status='converged'" in text and "kirsch" in text, text
    with pytest.raises(TypeError, match="not set"):
        adit.check({**scene, "name": {"a"}})


def test_a_wrong_type_from_a_dict_names_its_json_path(root):
    """Item 6: the error names the dict's path, not a line of JSON the user never wrote, and
    says "a number", not ``f64``."""
    scene = small_kirsch(root)
    scene["materials"]["rock"]["young"] = "ten"
    with pytest.raises(ValueError) as e:
        adit.check(scene)
    text = str(e.value)
    assert text == 'materials.rock.young: invalid type: string "ten", expected a number', text
    scene = small_kirsch(root)
    scene["boundary"][1]["fix"] = 3
    with pytest.raises(ValueError, match=r"^boundary\[1\]"):
        adit.check(scene)


def _elf_sections(path):
    """The section names of the ELF shared object at ``path``."""
    data = Path(path).read_bytes()
    assert data[:4] == b"\x7fELF" and data[4] == 2, "a 64-bit ELF"
    endian = "<" if data[5] == 1 else ">"
    import struct

    shoff = struct.unpack_from(endian + "Q", data, 0x28)[0]
    shentsize, shnum, shstrndx = struct.unpack_from(endian + "HHH", data, 0x3A)
    headers = [struct.unpack_from(endian + "IIQQQQ", data, shoff + i * shentsize) for i in range(shnum)]
    strtab = headers[shstrndx]
    names = data[strtab[4] : strtab[4] + strtab[5]]
    return [names[h[0] : names.index(b"\0", h[0])].decode() for h in headers]


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads an ELF shared object")
def test_the_installed_module_ships_no_debug_info():
    """Item 1: the wheel is built without debug info (59 MB with it)."""
    from adit import _adit

    sections = _elf_sections(_adit.__file__)
    assert ".text" in sections
    assert not any(s.startswith(".debug_") for s in sections), sections
    assert os.path.getsize(_adit.__file__) < 30e6
