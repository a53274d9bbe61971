#!/usr/bin/python3
"""Plots `porosph_validate consolidation RUN --series FILE` outputs: U(T_v) of each run against
Terzaghi's closed form (left) and the isochrones of the last run (right).

  tools/validation/consolidation_plot.py OUT.png LABEL=FILE.csv [LABEL=FILE.csv ...]

FILE_isochrones.csv (written beside FILE.csv) gives the isochrones; the last pair's are drawn.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    out, pairs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    for label, path in pairs:
        s = read(path)
        left.plot(s["T"], s["U"], label=f"PoroSPH {label}")
    s = read(pairs[-1][1])
    left.plot(s["T"], s["U_closed"], "k--", label="Terzaghi (ramp 0.1 s)")
    left.set(xscale="log", xlim=(0.01, 2.0), ylim=(0, 1.1), xlabel="T_v = c_v t / H^2",
             ylabel="degree of consolidation U")
    left.legend()
    iso = read(pairs[-1][1].rsplit(".", 1)[0] + "_isochrones.csv")
    for t in sorted(set(iso["T"])):
        rows = [i for i, v in enumerate(iso["T"]) if v == t]
        line, = right.plot([iso["u"][i] for i in rows], [iso["depth"][i] for i in rows], "o",
                           markersize=3, label=f"T_v = {t:.2f} ({pairs[-1][0]})")
        right.plot([iso["u_closed"][i] for i in rows], [iso["depth"][i] for i in rows], "-",
                   color=line.get_color())
    right.invert_yaxis()
    right.set(xlabel="excess pore pressure u / p0", ylabel="depth below the drained top [m]")
    right.legend(title="points: PoroSPH, lines: Terzaghi")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
