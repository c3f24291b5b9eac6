"""The scikit-fem peer of adit's implicit static solve (issue 17).

Reads a problem that adit's validation wrote (`validation/src/peer.rs`): the nodes and triangles
of a zoned Kirsch model, its fixed components, the out-of-balance nodal force of its initial
(in-situ) stress and loads, the rock's elastic constants, and the zones whose stress error is
measured with their exact stress. Assembles the plane-strain stiffness of linear triangles (P1)
with scikit-fem, solves K u = R with SciPy's sparse direct solver (scikit-fem's `solve`), takes
each triangle's stress σ = σ0 + D ε(u), and prints as JSON the seconds that took (assembly, solve
and stresses), the relative L2 stress error over the measured zones (the measure of
`validation/src/kirsch_case.rs`) and, when the file holds adit's stresses, their largest
difference from the peer's relative to the largest exact stress.

Usage: python3 kirsch_skfem.py PROBLEM.json
"""

import json
import sys
import time

import numpy as np
from skfem import Basis, ElementTriP1, ElementVector, MeshTri, asm, condense, solve
from skfem.models.elasticity import lame_parameters, linear_elasticity


def main(path):
    with open(path) as f:
        d = json.load(f)
    p = np.array(d["nodes"], dtype=float)
    t = np.array(d["triangles"], dtype=np.int64)
    force = np.array(d["force"], dtype=float)
    fixed = np.array(d["fixed"], dtype=np.int64)
    initial = np.array(d["initial_stress"], dtype=float)  # per zone: sxx, syy, sxy (Pa)
    lam, mu = lame_parameters(d["young"], d["poisson"])

    start = time.perf_counter()
    mesh = MeshTri(p.T.copy(), t.T.copy())
    basis = Basis(mesh, ElementVector(ElementTriP1()))
    stiffness = asm(linear_elasticity(lam, mu), basis)
    dofs = basis.nodal_dofs  # (component, vertex) -> dof
    rhs = np.zeros(basis.N)
    rhs[dofs[0]] = force[:, 0]
    rhs[dofs[1]] = force[:, 1]
    held = np.concatenate([dofs[0][(fixed & 1) != 0], dofs[1][(fixed & 2) != 0]])
    u = solve(*condense(stiffness, rhs, D=held))
    ux, uy = u[dofs[0]], u[dofs[1]]
    # Constant strain of each triangle from its vertices' displacements.
    x, y = p[t, 0], p[t, 1]
    two_a = (x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) - (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0])
    dndx = np.stack([y[:, 1] - y[:, 2], y[:, 2] - y[:, 0], y[:, 0] - y[:, 1]], axis=1) / two_a[:, None]
    dndy = np.stack([x[:, 2] - x[:, 1], x[:, 0] - x[:, 2], x[:, 1] - x[:, 0]], axis=1) / two_a[:, None]
    exx = np.sum(dndx * ux[t], axis=1)
    eyy = np.sum(dndy * uy[t], axis=1)
    gxy = np.sum(dndy * ux[t] + dndx * uy[t], axis=1)
    stress = initial + np.stack(
        [(lam + 2 * mu) * exx + lam * eyy, lam * exx + (lam + 2 * mu) * eyy, mu * gxy], axis=1
    )
    seconds = time.perf_counter() - start

    zones = np.array(d["measured"], dtype=np.int64)
    exact = np.array(d["exact"], dtype=float)
    area = np.abs(two_a[zones]) / 2
    diff = stress[zones] - exact
    norm2 = lambda s: s[:, 0] ** 2 + s[:, 1] ** 2 + 2 * s[:, 2] ** 2
    out = {
        "seconds": seconds,
        "unknowns": int(basis.N - len(held)),
        "stress_l2": float(np.sqrt(np.sum(area * norm2(diff)) / np.sum(area * norm2(exact)))),
    }
    if "adit_stress" in d:
        adit = np.array(d["adit_stress"], dtype=float)
        out["difference"] = float(np.abs(adit - stress).max() / np.abs(exact).max())
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
