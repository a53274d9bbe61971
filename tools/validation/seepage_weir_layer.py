#!/usr/bin/env python3
"""Separates the sand layer's error from the pools' in a cases/seepage_weir run.

`porosph_validate seepage_weir RUN` compares the discharge under the weir with a finite-volume
(FV) solution whose top boundary is each pool's mean head. This script instead solves the same
two-point-flux FV scheme (tools/validation/laplace_fv.h, 2.5 mm cells) with the run's own heads
as the top boundary: per cell, the mean head of the water particles 0 .. 2 dp above the layer
and within dp of the cell's centre, over the same window (the last quarter of the run). If the
SPH discharge matches this solution but not the validator's, the error is in the pools (their
head is not uniform), not in the layer. It also prints the pools' head next to the weir and far
from it, as a share of dh. Geometry as cases/seepage_weir/scene.toml.

Usage: seepage_weir_layer.py RUN_DIR   (needs python3-h5py, python3-scipy)
"""
import json
import sys

import h5py
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

LAYER_TOP, LENGTH, WEIR = 0.2, 1.2, (0.5, 0.7)
CELL = 0.0025


def water_head(p, y, rho0, c0, gamma, g):
    """Inverse of the still-water pressure p(d) of eq. 4: the head y + d."""
    b = rho0 * c0 ** 2 / gamma
    return y + ((p / b + 1.0) ** ((gamma - 1.0) / gamma) - 1.0) * b * gamma / ((gamma - 1.0) * rho0 * g)


def fv_discharge(top_heads, conductivity):
    """Discharge per unit width under the weir's centre for the top heads per cell (NaN: no flow)."""
    nx, ny = len(top_heads), int(round(LAYER_TOP / CELL))
    index = lambda i, j: j * nx + i
    rows, cols, vals, rhs = [], [], [], np.zeros(nx * ny)
    for j in range(ny):
        for i in range(nx):
            k, diagonal = index(i, j), 0.0
            for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                ii, jj = i + di, j + dj
                if 0 <= ii < nx and 0 <= jj < ny:
                    rows.append(k), cols.append(index(ii, jj)), vals.append(-1.0)
                    diagonal += 1.0
                elif jj == ny and not np.isnan(top_heads[i]):
                    diagonal += 2.0
                    rhs[k] += 2.0 * top_heads[i]
            rows.append(k), cols.append(k), vals.append(diagonal)
    h = spl.spsolve(sp.csr_matrix((vals, (rows, cols)), shape=(nx * ny, nx * ny)), rhs)
    h = h.reshape(ny, nx)
    i = int(round(0.5 * (WEIR[0] + WEIR[1]) / CELL))
    return conductivity * (h[:, i - 1] - h[:, i]).sum()


def main(run):
    parameters = json.load(open(run + "/run.json"))["parameters"]
    water = parameters["water"]
    dp = parameters["run"]["dp"]
    g = -parameters["run"]["gravity"][1]
    conductivity = parameters["soil"]["materials"][0]["hydraulic_conductivity"]
    head = lambda p, y: water_head(p, y, water["rho0"], water["sound_speed"], water.get("gamma", 7.0), g)
    f = h5py.File(run + "/fluid.h5", "r")
    snaps = sorted(f["snapshots"].keys(), key=lambda s: f["snapshots"][s].attrs["time"])
    t_end = f["snapshots"][snaps[-1]].attrs["time"]
    xs, hs, discharge = [], [], []
    for s in snaps:
        group = f["snapshots"][s]
        if group.attrs["time"] < 0.75 * t_end - 1e-9:
            continue
        free = group["fixed"][:] == 0
        x, v = group["position"][:][free], group["velocity"][:][free]
        volume = group["mass"][:][free] / group["density"][:][free]
        xs.append(x)
        hs.append(head(group["pressure"][:][free], x[:, 1]))
        under = (x[:, 0] > WEIR[0] + 2 * dp) & (x[:, 0] < WEIR[1] - 2 * dp) & (x[:, 1] < LAYER_TOP)
        discharge.append((volume[under] * v[under, 0]).sum() / (WEIR[1] - WEIR[0] - 4 * dp))
    x, h, q = np.vstack(xs), np.concatenate(hs), np.mean(discharge)
    centres = (np.arange(int(round(LENGTH / CELL))) + 0.5) * CELL
    top = np.full(len(centres), np.nan)
    for i, xc in enumerate(centres):
        if WEIR[0] < xc < WEIR[1]:
            continue
        m = (np.abs(x[:, 0] - xc) < dp) & (x[:, 1] > LAYER_TOP) & (x[:, 1] < LAYER_TOP + 2 * dp)
        top[i] = h[m].mean()

    def pool(x0, x1):
        m = (x[:, 0] > x0) & (x[:, 0] < x1) & (x[:, 1] > LAYER_TOP + 2 * dp) & (x[:, 1] < 0.28)
        return h[m].mean()

    h1, h2 = pool(2 * dp, WEIR[0] - 2 * dp), pool(WEIR[1] + 2 * dp, LENGTH - 2 * dp)
    dh = h1 - h2
    q_own = fv_discharge(top, conductivity)
    print(f"{run}: window {0.75 * t_end:.3f} .. {t_end:.3f} s, dh {dh:.5f} m")
    print(f"SPH discharge {q:.5e} m^2/s; FV with the run's own top heads {q_own:.5e}: {q / q_own - 1:+.2%}")
    near_up, far_up = pool(WEIR[0] - 0.1, WEIR[0] - 2 * dp), pool(2 * dp, 0.2)
    near_down, far_down = pool(WEIR[1] + 2 * dp, WEIR[1] + 0.1), pool(1.0, LENGTH - 2 * dp)
    print(f"upstream pool head: within 0.1 m of the weir {(near_up - h1) / dh:+.2%} of dh from its mean, "
          f"beyond 0.3 m from it {(far_up - h1) / dh:+.2%}")
    print(f"downstream pool head: within 0.1 m of the weir {(near_down - h2) / dh:+.2%} of dh from its mean, "
          f"beyond 0.3 m from it {(far_down - h2) / dh:+.2%}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
