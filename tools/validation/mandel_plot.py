#!/usr/bin/python3
"""Plots `porosph_validate mandel RUN --series FILE` outputs: the centre's pore pressure per p0
(left) and the plate's displacement (right) of each run against Mandel's closed form.

  tools/validation/mandel_plot.py OUT.png LABEL=FILE.csv [LABEL=FILE.csv ...]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from consolidation_plot import read  # noqa: E402  (same folder: the CSV reader of the series)


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    out, pairs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    for label, path in pairs:
        s = read(path)
        left.plot(s["T"], s["centre"], lw=1, label=label)
        right.plot(s["T"], [1e3 * v for v in s["plate"]], lw=1, label=label)
    s = read(pairs[-1][1])
    left.plot(s["T"], s["centre_closed"], "k--", lw=1.5, label="closed form, centre column")
    right.plot(s["T"], [1e3 * v for v in s["plate_closed"]], "k--", lw=1.5, label="closed form")
    left.set_xlabel("c t / a^2")
    left.set_ylabel("pore pressure of the centre column / p0")
    left.set_title("Mandel-Cryer effect at the centre")
    right.set_xlabel("c t / a^2")
    right.set_ylabel("plate displacement [mm]")
    right.set_title("The rigid plate")
    for ax in (left, right):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
