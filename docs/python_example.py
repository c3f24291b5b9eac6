# %% [markdown]
# # adit from Python: a tunnel's support, a sweep of its joint realizations
#
# Run it cell by cell (VS Code, Jupyter with jupytext) or whole:
# `python docs/python_example.py` from the repository root, after `pip install ./python`.
# Each cell's work sits under `if __name__ == "__main__":` (true in a notebook too): the sweep's
# process pool starts fresh Python processes, which import this file again.

# %%
import adit
import numpy as np

scene = adit.load_scene("models/tunnel.json")

# %% [markdown]
# Change the scene as a dict: a stiffer rock, then run it with a progress callback.

# %%
if __name__ == "__main__":
    print(scene["name"], "stages:", [s["name"] for s in scene["stages"]])
    scene["materials"]["rock"]["young"] *= 1.5
    last = {}
    result = adit.run(scene, out="out/tunnel_stiffer", progress=last.update)
    print(result.status, "after", last["cycle"], "cycles, ratio", f"{last['ratio']:.1e}")
    print(f"closure {1e3 * result.closure('tunnel'):.2f} mm")

# %% [markdown]
# Results are NumPy arrays: zone stresses (Pa, tension positive), the recovered nodal stress,
# contacts, bolts.

# %%
if __name__ == "__main__":
    z = result.zones
    live = z["excavated"] == 0
    sxx, syy, szz, sxy = z["stress_pa"][live].T
    c, r = (sxx + syy) / 2, np.hypot((sxx - syy) / 2, sxy)
    sigma1 = np.minimum(c - r, szz)
    print(f"most compressive zone: {sigma1.min() / 1e6:.1f} MPa; yielded zones: {(z['state'][live] != 0).sum()}")
    bolts = result.bolts
    on = bolts["installed"] == 1
    print(f"largest bolt force {bolts['axial_force_n_per_m'][on].max() / 1e3:.1f} kN/m")
    states = np.bincount(result.contacts["state"], minlength=3)
    print("contacts elastic / slipping / open:", states)

# %% [markdown]
# A sweep of 16 joint realizations (`models/tunnel_sweep.json`) on a local process pool; give
# `scheduler="tcp://host:8786"` (or `client=`) to run it on a Dask cluster instead.

# %%
if __name__ == "__main__":
    sweep = adit.sweep("models/tunnel_sweep.json", workers=2)
    closures = [row["closure_m"]["tunnel"] for row in sweep.rows]
    print(f"{len(closures)} realizations: closure {1e3 * min(closures):.2f} to {1e3 * max(closures):.2f} mm")
    print("table", sweep.table, "plot", sweep.plot)
