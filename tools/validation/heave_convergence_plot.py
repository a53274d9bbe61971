#!/usr/bin/python3
"""The hydraulic heave at several resolutions: the advance of the gravel's bottom next to the sheet
pile against time after the damping stage, one curve per run, with the advance at which the gravel
reaches the pile tip (the failure) and the experiment's failure time.

  build/bin/porosph_validate hydraulic_heave RUN --series RUN/validate_series.csv   # per run
  tools/validation/heave_convergence_plot.py OUT.png RUN1 RUN2 ...

Each RUN holds run.json and the validate_series.csv written above (docs/validation-studies.md).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from case_plots import read_csv  # noqa: E402


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out, runs = argv[1], argv[2:]
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for run in runs:
        with open(os.path.join(run, "run.json")) as f:
            parameters = json.load(f)["parameters"]
        s = read_csv(os.path.join(run, "validate_series.csv"))
        advance = s["gravel_bottom"][0] - s["gravel_bottom"]
        line, = ax.plot(s["t"], 1000 * advance, label=f"dp {1000 * parameters['run']['dp']:g} mm")
        tip = [w["min"][1] for w in parameters["walls"] if w.get("label") == "sheet_pile"]
        if tip:  # the failure: this run's gravel bottom at the pile tip (its lattice's start)
            ax.axhline(1000 * (s["gravel_bottom"][0] - tip[0]), color=line.get_color(), ls=":")
    ax.plot([], [], color="gray", ls=":", label="gravel at the pile tip (per run)")
    ax.axvline(4.4, color="k", ls="--", label="experiment: failure at 4.4 s")
    ax.set_xlabel("t after the damping stage [s]")
    ax.set_ylabel("advance of the gravel bottom at the pile [mm]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main(sys.argv)
