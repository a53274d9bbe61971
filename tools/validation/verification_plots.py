#!/usr/bin/python3
"""Figures of the closed-form verification cases (docs/verification.md): the runs of one case at
several resolutions against the closed form, from their timeseries.csv and run.json.

  tools/validation/verification_plots.py taylor_green RUN_DIR [RUN_DIR ...]
  tools/validation/verification_plots.py elastic_column RUN_DIR [RUN_DIR ...]
  tools/validation/verification_plots.py seepage_embankment CSV [CSV ...]
    (CSV: porosph_validate seepage_embankment RUN --series CSV, one per resolution)

writes docs/validation/<case>.png (or --out FILE)."""
import argparse
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read_run(out):
    with open(os.path.join(out, "timeseries.csv")) as f:
        rows = list(csv.reader(f))
    data = np.array([[float(x) if x else math.nan for x in r] for r in rows[1:]])
    series = {name: data[:, k] for k, name in enumerate(rows[0])}
    with open(os.path.join(out, "run.json")) as f:
        return series, json.load(f)["parameters"]


def taylor_green(runs, ax):
    """ln(E / E0) against t with the analytic line -4 nu k^2 t and the fit window shaded."""
    t_end = 0.0
    for out in runs:
        s, p = read_run(out)
        e = s["water_kinetic_energy"]
        ax.plot(s["t"], np.log(e / e[0]), label="dp = %g m" % p["run"]["dp"])
        t_end = max(t_end, s["t"][-1])
    w = p["water"]
    nu = w["viscosity"] / w["rho0"]
    k = 2 * math.pi / w["taylor_green_wavelength"]
    t = np.linspace(0, t_end, 100)
    ax.plot(t, -4 * nu * k * k * t, "k--", label="exp(-4 nu k^2 t) (Taylor & Green 1937)")
    convective = w["taylor_green_wavelength"] / w["taylor_green_speed"]
    ax.axvspan(0.1 * convective, 1.0 * convective, color="0.9", label="fit window")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("ln(E / E(0))")
    ax.set_title("Taylor-Green vortex, Re = %.0f" % (w["taylor_green_speed"] *
                                                     w["taylor_green_wavelength"] / nu))


def elastic_column_top(t, height, c, g):
    """Top displacement of a fixed-free bar under a suddenly applied uniform body force g:
    u(y, t) = u_s(y) - sum_n b_n sin(k_n y) cos(c k_n t), u_s = g (H y - y^2 / 2) / c^2,
    k_n = (2n - 1) pi / (2H), b_n = 2 g / (c^2 H k_n^3) (the sine coefficients of u_s)."""
    u = np.full_like(t, g * height * height / (2 * c * c))
    for n in range(1, 200):
        kn = (2 * n - 1) * math.pi / (2 * height)
        bn = 2 * g / (c * c * height * kn ** 3)
        u -= bn * math.sin(kn * height) * np.cos(c * kn * t)
    return u


def elastic_column(runs, ax):
    for out in runs:
        s, p = read_run(out)
        ax.plot(s["t"], 1e3 * s["top_displacement"], label="dp = %g m" % p["run"]["dp"])
    m = p["soil"]["materials"][0]
    e, nu = m["young_modulus"], m["poisson_ratio"]
    modulus = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    c = math.sqrt(modulus / m["density"])
    b = p["soil"]["blocks"][0]
    height = b["max"][1] - b["min"][1]
    g = math.hypot(*p["run"]["gravity"])
    t = np.linspace(0, s["t"][-1], 2000)
    ax.plot(t, 1e3 * elastic_column_top(t, height, c, g), "k--", lw=1,
            label="closed form, T = 4 H / c_p")
    ax.axhline(1e3 * m["density"] * g * height ** 2 / (2 * modulus), color="0.5", lw=0.8,
               label="static settlement rho g H^2 / (2 M)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("top displacement [mm]")
    ax.set_title("Elastic column loaded suddenly by gravity")


def seepage_embankment(files, ax):
    """The phreatic line of each run (top of the water + dp/2 per particle column, averaged over
    the window) against Baiocchi's free surface for that run's measured pool heads."""
    for k, path in enumerate(files):
        with open(path) as f:
            rows = list(csv.reader(f))
        d = np.array([[float(x) for x in r] for r in rows[1:]])
        x, sph, ref = d[:, 0], d[:, 1], d[:, 2]
        line = ax.plot(x, sph, "o", ms=3, label="SPH, dp = %.3g m" % (x[1] - x[0]))
        ax.plot(x, ref, "-", color=line[0].get_color(), lw=1,
                label="line: Baiocchi for that run's h1, h2" if k == len(files) - 1 else None)
    ax.axvline(x[-1] + 0.5 * (x[1] - x[0]), color="0.5", lw=0.8)
    ax.set_xlabel("x from the upstream face [m]")
    ax.set_ylabel("phreatic surface [m]")
    ax.set_title("Unconfined seepage through a rectangular dam, L = 0.4 m")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", choices=["taylor_green", "elastic_column", "seepage_embankment"])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out", help="PNG file (default docs/validation/<case>.png)")
    args = parser.parse_args()
    fig, ax = plt.subplots(figsize=(7, 4.2))
    plots = {"taylor_green": taylor_green, "elastic_column": elastic_column,
             "seepage_embankment": seepage_embankment}
    plots[args.case](args.runs, ax)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out = args.out or os.path.join(ROOT, "docs", "validation", args.case + ".png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
