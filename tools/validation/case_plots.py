"""Figures of the validation report (tools/validation/report.py): one function per case, each
reading a finished run directory (timeseries.csv, water.h5 / soil.h5, validate_series.csv) and
writing PNG files; returns their paths."""
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# B [m] of the experiments (Larese et al. 2015; seed paper Table 3) by flow rate Q [l/s].
ROCKFILL_B_EXPERIMENT = {19.36: 0.32, 30.45: 0.68}


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    names, data = rows[0], np.array([[float(x) if x else math.nan for x in r] for r in rows[1:]])
    return {n: data[:, k] for k, n in enumerate(names)} if len(data) else {n: [] for n in names}


def water_snapshot_path(out):
    """The water's snapshots of run directory `out`: water.h5, or fluid.h5 in a run written
    before the phase had one name (io/run_files.h)."""
    current, former = os.path.join(out, "water.h5"), os.path.join(out, "fluid.h5")
    return former if not os.path.exists(current) and os.path.exists(former) else current


def last_snapshot(path):
    f = h5py.File(path, "r")
    key = sorted(f["snapshots"].keys())[-1]
    return f["snapshots"][key], f["snapshots"][key].attrs["time"]


def run_json(out):
    with open(os.path.join(out, "run.json")) as f:
        return json.load(f)


def save(fig, figures, name, suffix):
    path = os.path.join(figures, f"{name}_{suffix}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def dam_break(out, figures, name):
    ts = read_csv(os.path.join(out, "timeseries.csv"))
    ref = read_csv(os.path.join(ROOT, "cases", "dam_break", "reference.csv"))
    params = run_json(out)["parameters"]
    block = params["water"]["blocks"][0]
    a = block["max"][0] - block["min"][0]
    g = abs(params["run"]["gravity"][1])
    dp = params["run"]["dp"]
    scale = math.sqrt(2 * g / a)
    bulk = read_csv(os.path.join(out, "validate_series.csv"))  # porosph_validate --series
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(bulk["T"], bulk["Z"], label="PoroSPH, bulk front (judged)")
    ax.plot(ts["t"] * scale, (ts["front"] + dp / 2) / a, ":", label="PoroSPH, farthest particle")
    ax.plot(ref["T"], ref["Z"], "o", label="Martin & Moyce (1952)")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = front / a")
    ax.legend()
    return [save(fig, figures, name, "front")]


def free_field(snap, name):
    """Field `name` of the free (not wall) particles of a snapshot."""
    return snap[name][:][snap["fixed"][:] == 0]


def against_weight(figures, name, suffix, value, y, t, weight, top, labels):
    """A vertical profile (value against height) beside the weight of the column above,
    weight * (top - y). labels: (x axis, y axis, reference)."""
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(value, y, ".", ms=2, label=f"PoroSPH, t = {t:.2f} s")
    height = np.linspace(0, top, 50)
    ax.plot(weight * (top - height), height, "k-", label=labels[2])
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.legend()
    return [save(fig, figures, name, suffix)]


def hydrostatic_tank(out, figures, name):
    snap, t = last_snapshot(water_snapshot_path(out))
    params = run_json(out)["parameters"]
    weight = params["water"]["rho0"] * abs(params["run"]["gravity"][1])
    top = params["water"]["blocks"][0]["max"][1]
    return against_weight(figures, name, "pressure", free_field(snap, "pressure"),
                          free_field(snap, "position")[:, 1], t, weight, top,
                          ("pressure [Pa]", "z [m]", "rho g (H - z)"))


def soil_column(out, figures, name):
    snap, t = last_snapshot(os.path.join(out, "soil.h5"))
    params = run_json(out)["parameters"]
    weight = params["soil"]["materials"][0]["density"] * abs(params["run"]["gravity"][1])
    top = params["soil"]["blocks"][0]["max"][1]
    syy = free_field(snap, "stress")[:, 4]  # N x 9, row-major 3x3 (README, soil.h5)
    return against_weight(figures, name, "stress", -syy, free_field(snap, "position")[:, 1], t,
                          weight, top,
                          ("vertical stress, compression [Pa]", "y [m]", "rho g (H - y)"))


def granular_collapse(out, figures, name):
    snap, t = last_snapshot(os.path.join(out, "soil.h5"))
    x = free_field(snap, "position")
    u = np.linalg.norm(free_field(snap, "displacement"), axis=1)
    fig, ax = plt.subplots(figsize=(7, 2.5))
    sc = ax.scatter(x[:, 0], x[:, 1], c=u, s=1, cmap="viridis")
    fig.colorbar(sc, ax=ax, label="displacement [m]")
    ax.set_aspect("equal")
    ax.set_title(f"deposit at t = {t:.2f} s")
    return [save(fig, figures, name, "deposit")]


def darcy_column(out, figures, name):
    ts = read_csv(os.path.join(out, "timeseries.csv"))
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(ts["t"], -ts["darcy_velocity"], label="PoroSPH mean water velocity")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("q [m/s]")
    ax.legend()
    return [save(fig, figures, name, "velocity")]


def fluidized_bed(out, figures, name):
    ts = read_csv(os.path.join(out, "timeseries.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    axes[0].plot(ts["t"], ts["sand_porosity"], label="PoroSPH")
    axes[0].axhline(0.51, color="k", ls="--", label="experiment 0.51")
    axes[0].set_xlabel("t [s]")
    axes[0].set_ylabel("mean sand porosity")
    axes[0].legend()
    axes[1].plot(ts["t"], -ts["sand_stress_yy"])
    axes[1].set_xlabel("t [s]")
    axes[1].set_ylabel("vertical effective stress, lower sand [Pa]")
    return [save(fig, figures, name, "porosity")]


def rockfill(out, figures, name):
    paths = []
    series = os.path.join(out, "validate_series.csv")
    run = run_json(out)
    q = run["parameters"]["water"]["inflow"][0]["flow_rate"]
    b_exp = ROCKFILL_B_EXPERIMENT.get(round(1e3 * q, 2))
    if os.path.exists(series):
        s = read_csv(series)
        fig, ax = plt.subplots(figsize=(5, 3.5))
        ax.plot(s["t"], s["B_wet"], label="PoroSPH, wet particles moved > D15")
        ax.plot(s["t"], s["B_all"], ":", label="PoroSPH, all slope particles")
        if b_exp:
            ax.axhline(b_exp, color="k", ls="--", label=f"experiment {b_exp} m")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("B [m]")
        ax.legend()
        paths.append(save(fig, figures, name, "B"))
    ts = read_csv(os.path.join(out, "timeseries.csv"))
    levels = [k for k in ts if k.startswith("level_x")]
    if levels:
        fig, ax = plt.subplots(figsize=(5, 3.5))
        for k in levels:
            ax.plot(ts["t"], ts[k], label=f"x = {int(k[7:]) / 100:.1f} m")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("water level in the shell [m]")
        ax.set_title("phreatic surface (Dupuit-Forchheimer on the porosity plot)")
        ax.legend()
        paths.append(save(fig, figures, name, "levels"))
    snap, t = last_snapshot(os.path.join(out, "soil.h5"))
    x = free_field(snap, "position")
    n = free_field(snap, "porosity")
    water, _ = last_snapshot(water_snapshot_path(out))
    w = free_field(water, "position")
    fig, ax = plt.subplots(figsize=(9, 3.5))
    sc = ax.scatter(x[:, 0], x[:, 1], c=n, s=3, cmap="copper_r")
    fig.colorbar(sc, ax=ax, label="porosity")
    ax.scatter(w[:, 0], w[:, 1], s=1, c="tab:blue", alpha=0.4, label="water")
    dupuit = series.replace(".csv", "_dupuit.csv")
    if os.path.exists(dupuit):
        d = read_csv(dupuit)
        ax.plot(d["x"], d["h"], "k--", lw=1, label="Dupuit-Forchheimer water table")
        ax.legend(loc="upper right", fontsize=7)
    ax.set_aspect("equal")
    ax.set_xlim(-0.1, 3.3)
    ax.set_title(f"porosity and water at t = {t:.1f} s")
    paths.append(save(fig, figures, name, "porosity"))
    return paths


def hydraulic_heave(out, figures, name):
    paths = []
    ts = read_csv(os.path.join(out, "timeseries.csv"))
    damping = run_json(out)["parameters"]["soil"]["damping_duration"]
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    axes[0].plot(ts["t"] - damping, ts["upstream_level"] - ts["downstream_level"])
    axes[0].set_xlabel("t after the damping stage [s]")
    axes[0].set_ylabel("overall head [m]")
    series = os.path.join(out, "validate_series.csv")
    if os.path.exists(series):
        s = read_csv(series)
        axes[1].plot(s["t"], s["gravel_bottom"][0] - s["gravel_bottom"], label="PoroSPH")
        axes[1].axvline(4.4, color="k", ls="--", label="experiment: failure at 4.4 s")
        tip = [w["min"][1] for w in run_json(out)["parameters"]["walls"]
               if w.get("label") == "sheet_pile"]
        if tip:
            axes[1].axhline(s["gravel_bottom"][0] - tip[0], color="tab:red", ls=":",
                            label="gravel at the pile tip (failure)")
        axes[1].set_xlabel("t after the damping stage [s]")
        axes[1].set_ylabel("advance of the gravel bottom at the pile [m]")
        axes[1].legend()
    paths.append(save(fig, figures, name, "head_gravel"))
    snap, t = last_snapshot(os.path.join(out, "soil.h5"))
    x = free_field(snap, "position")
    m = free_field(snap, "material")
    fig, ax = plt.subplots(figsize=(8, 2.5))
    ax.scatter(x[m == 0, 0], x[m == 0, 1], s=2, c="goldenrod", label="sand")
    ax.scatter(x[m == 1, 0], x[m == 1, 1], s=2, c="dimgray", label="gravel")
    ax.set_aspect("equal")
    ax.legend(loc="upper left")
    ax.set_title(f"soil at t = {t - damping:.2f} s after the damping stage")
    paths.append(save(fig, figures, name, "soil"))
    return paths


def heave_grid(fits, figures):
    """fits: (label, rows) with rows (phi_sand, phi_gravel, 'T s' or 'none by ...')."""
    fig, ax = plt.subplots(figsize=(5, 3.5))
    for label, rows in fits:
        for g in sorted({r[1] for r in rows}):
            pts = [(s, float(v.split()[0])) for (s, gg, v) in rows if gg == g and v[0].isdigit()]
            if pts:
                ax.plot(*zip(*sorted(pts)), "o-", label=f"{label}, gravel phi {g}")
    ax.axhline(4.4, color="k", ls="--", label="experiment 4.4 s")
    ax.set_xlabel("sand friction angle [deg]")
    ax.set_ylabel("time of complete failure [s]")
    ax.legend(fontsize=7)
    return save(fig, figures, "hydraulic_heave", "grid")


def rockfill_b_against_q(rows, figures):
    """rows: (discharge per metre [m^2/s], Q [l/s], W [m], B [m], dp [m]) of the rockfill runs."""
    fig, ax = plt.subplots(figsize=(5, 3.5))
    for dp in sorted({r[4] for r in rows}, reverse=True):
        for flow, marker in zip(ROCKFILL_B_EXPERIMENT, ("o", "s") if dp >= 0.02 else ("*", "D")):
            pts = sorted((1e3 * q, b) for (q, qq, w, b, d) in rows
                         if abs(qq - flow) < 0.01 and d == dp)
            if pts:
                ax.plot(*zip(*pts), marker, label=f"PoroSPH, Q = {flow} l/s, dp {dp:g} m")
    for flow, b_exp in ROCKFILL_B_EXPERIMENT.items():
        ax.axhline(b_exp, color="k", ls="--", lw=0.8)
        ax.text(1, b_exp + 0.01, f"experiment, Q = {flow} l/s", fontsize=7)
    ax.set_xlabel("discharge per metre q = Q / W [l/s/m]")
    ax.set_ylabel("B (wet particles moved > D15) [m]")
    ax.set_xlim(left=0)
    ax.legend(fontsize=7)
    return save(fig, figures, "rockfill", "B_vs_q")
