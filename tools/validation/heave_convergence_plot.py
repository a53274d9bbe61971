#!/usr/bin/python3
"""The hydraulic heave at several resolutions: the advance of the gravel's bottom next to the sheet
pile against time after the damping stage, one curve per run, with the advance at which the gravel
reaches the pile tip (the failure) and the experiment's failure time.

  build/bin/porosph_validate hydraulic_heave RUN --series RUN/validate_series.csv   # per run
  tools/validation/heave_convergence_plot.py [--measure M] OUT.png RUN1 RUN2 ...

Each RUN holds run.json and the validate_series.csv written above (docs/validation-studies.md).
It also prints the measure of each run every 0.5 s (up to the shortest run's end) and, for three
runs whose dp halves (whatever their cfl) or, at one dp, whose run.cfl halves, the order
p = log2((a1 - a2) / (a2 - a3)) at each time (a1 coarsest): where p > 0 the measure converges
there, where it is not a number (increments of opposite signs) or negative it does not. Curves
are labelled with dp and, where the runs differ in it, run.cfl.

M (default advance) picks the curve: advance (the lowest gravel particle beside the pile, the
failure measure), sand_crossed (the sand carried under the pile into the pit) or
gravel_settlement (the mean settlement of the gravel that started beside the pile); the last two
are the bulk measures of porosph_validate hydraulic_heave (tools/validation/dam_case_checks.h).
"""
import math
import json
import os
import sys
from collections import namedtuple

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from case_plots import read_csv  # noqa: E402

Curve = namedtuple("Curve", "dp cfl t value")  # one run: its dp, run.cfl and measure over t

# measure -> (its values from a validate_series.csv, the axis label, the printed unit's scale)
MEASURES = {
    "advance": (lambda s: s["gravel_bottom"][0] - s["gravel_bottom"],
                "advance of the gravel bottom at the pile [mm]", 1000),
    "sand_crossed": (lambda s: s["sand_crossed"],
                     "sand carried under the pile into the pit [cm^2 per m]", 1e4),
    "gravel_settlement": (lambda s: s["gravel_settlement"],
                          "mean settlement of the gravel beside the pile [mm]", 1000),
}


def main(argv):
    args = argv[1:]
    measure = "advance"
    if len(args) >= 2 and args[0] == "--measure":
        measure, args = args[1], args[2:]
    if len(args) < 2 or measure not in MEASURES:
        sys.exit(__doc__)
    values_of, axis_label, scale = MEASURES[measure]
    out, runs = args[0], args[1:]
    fig, ax = plt.subplots(figsize=(6.5, 4))
    curves = []
    parameter_sets = []
    for run in runs:
        with open(os.path.join(run, "run.json")) as f:
            parameter_sets.append(json.load(f)["parameters"])
    cfls = {p["run"]["cfl"] for p in parameter_sets}
    for run, parameters in zip(runs, parameter_sets):
        s = read_csv(os.path.join(run, "validate_series.csv"))
        if measure != "advance" and measure not in s:
            sys.exit(f"{run}/validate_series.csv has no column {measure}: rerun porosph_validate")
        values = values_of(s)
        dp, cfl = parameters["run"]["dp"], parameters["run"]["cfl"]
        curves.append(Curve(dp, cfl, list(s["t"]), list(scale * values)))
        label = f"dp {1000 * dp:g} mm" + (f", cfl {cfl:g}" if len(cfls) > 1 else "")
        line, = ax.plot(s["t"], scale * values, label=label)
        tip = [w["min"][1] for w in parameters["walls"] if w.get("label") == "sheet_pile"]
        if tip and measure == "advance":  # the failure: this run's gravel bottom at the pile tip
            ax.axhline(1000 * (s["gravel_bottom"][0] - tip[0]), color=line.get_color(), ls=":")
    if measure == "advance":
        ax.plot([], [], color="gray", ls=":", label="gravel at the pile tip (per run)")
    ax.axvline(4.4, color="k", ls="--", label="experiment: failure at 4.4 s")
    ax.set_xlabel("t after the damping stage [s]")
    ax.set_ylabel(axis_label)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)
    print(axis_label)
    print_orders(sorted(curves, key=lambda c: (-c.dp, -c.cfl)))


def at(t, ts, values):
    """values(t) by linear interpolation; nan outside ts."""
    for k in range(1, len(ts)):
        if ts[k - 1] <= t <= ts[k]:
            w = (t - ts[k - 1]) / (ts[k] - ts[k - 1]) if ts[k] > ts[k - 1] else 0.0
            return values[k - 1] + w * (values[k] - values[k - 1])
    return math.nan


def print_orders(curves):
    """The measure per run (coarse to fine) every 0.5 s, and the self-convergence order.

    curves: Curve per run, coarse first."""
    end = min(c.t[-1] for c in curves)

    def halves(field):  # the three curves halve this field from one to the next
        values = [getattr(c, field) for c in curves]
        return len(values) == 3 and all(abs(values[k] / values[k + 1] - 2) < 1e-6 for k in range(2))

    one_dp = len({c.dp for c in curves}) == 1
    halving = halves("dp") or (one_dp and halves("cfl"))
    print("t [s]  " + "  ".join(f"{f'dp {1000 * c.dp:g} mm cfl {c.cfl:g}':>18}" for c in curves)
          + ("  order p" if halving else ""))
    t = 0.5
    while t <= end + 1e-9:
        a = [at(t, c.t, c.value) for c in curves]
        line = f"{t:5.1f}  " + "  ".join(f"{x:18.1f}" for x in a)
        if halving:
            d1, d2 = a[0] - a[1], a[1] - a[2]
            p = math.log2(d1 / d2) if d1 * d2 > 0 else math.nan
            line += f"  {p:7.2f}"
        print(line)
        t += 0.5


if __name__ == "__main__":
    main(sys.argv)
