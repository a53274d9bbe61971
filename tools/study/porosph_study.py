#!/usr/bin/python3
"""Accuracy against cost: runs the variants of a scene, compares each with its reference and
writes study.csv and study.png (error against wall time).

  tools/study/porosph_study.py cases/dam_break/scene.toml --check dam_break \\
      --vary run.dp=0.0028575,0.00142875 --out runs/study_dam
  tools/study/porosph_study.py cases/fluidized_bed/scene.toml --check fluidized_bed \\
      --vary run.c_a=0.005,0.05,0.25 --set run.dp=0.002 --out runs/study_bed

Every combination of the --vary values is one variant (a Cartesian product), run with
`coupler run SCENE --set KEY=VALUE ... --out OUT/variant_NN` and compared with
`porosph_validate CHECK OUT/variant_NN`. The error of a variant is the first figure of
porosph_validate's first summary line (its `error` column; an absolute value, % stripped).
Variants already run (OUT/variant_NN/run.json, and study_overrides.json with the same
overrides) are not rerun.
Exit status: 0 when every variant ran to completion, 1 otherwise (the table is still written).
"""
import argparse
import csv
import itertools
import json
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def parse_vary(text):
    if "=" not in text:
        raise SystemExit(f"porosph_study: --vary '{text}': expected KEY=V1,V2,...")
    key, values = text.split("=", 1)
    values = [v for v in values.split(",") if v]
    if not values:
        raise SystemExit(f"porosph_study: --vary '{text}': no values")
    return key, values


def numeric_error(text):
    """'1.25 %' -> 1.25, '+0.0040' -> 0.004, '-' -> nan."""
    match = re.search(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", text)
    return abs(float(match.group(0))) if match else math.nan


def run_variant(args, overrides, out):
    """Runs one variant unless OUT already holds a run with the same overrides; its run.json."""
    record = os.path.join(out, "run.json")
    marker = os.path.join(out, "study_overrides.json")
    if os.path.exists(record) and os.path.exists(marker):
        with open(marker) as f:
            if json.load(f) == overrides:
                with open(record) as g:
                    return json.load(g)
    command = [os.path.join(args.bin, "coupler"), "run", args.scene, "--out", out,
               "--no-progress"]
    for o in overrides:
        command += ["--set", o]
    print("porosph_study: " + " ".join(command), flush=True)
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    if not os.path.exists(record):
        return None
    with open(marker, "w") as f:
        json.dump(overrides, f)
    with open(record) as f:
        return json.load(f)


def validate(args, out):
    command = [os.path.join(args.bin, "porosph_validate"), args.check, out] + args.check_args
    result = subprocess.run(command, capture_output=True, text=True)
    for line in result.stdout.splitlines():
        if line.startswith("summary\t"):
            return line.split("\t")[1:]
    return None


def plot(rows, keys, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.5, 4))
    for row in rows:
        if math.isfinite(row["error_value"]) and row["wall_seconds"]:
            ax.plot(row["wall_seconds"], row["error_value"], "o", color="tab:blue")
            label = ", ".join(f"{k.split('.')[-1]}={row[k]}" for k in keys)
            ax.annotate(label, (row["wall_seconds"], row["error_value"]), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_xlabel("wall time [s]")
    quantity = rows[0]["quantity"] if rows else "error"
    ax.set_ylabel(f"error of {quantity}")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--check", required=True, help="porosph_validate subcommand")
    parser.add_argument("--check-arg", dest="check_args", action="append", default=[],
                        help="extra argument for porosph_validate (repeatable)")
    parser.add_argument("--vary", action="append", default=[], help="KEY=V1,V2,...")
    parser.add_argument("--set", dest="fixed", action="append", default=[],
                        help="KEY=VALUE for every variant")
    parser.add_argument("--out", required=True)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--no-plot", action="store_true")
    args = parser.parse_args()
    if not args.vary:
        raise SystemExit("porosph_study: give at least one --vary KEY=V1,V2,...")
    varies = [parse_vary(v) for v in args.vary]
    keys = [k for k, _ in varies]
    os.makedirs(args.out, exist_ok=True)

    rows, all_completed = [], True
    for index, values in enumerate(itertools.product(*[v for _, v in varies])):
        overrides = args.fixed + [f"{k}={v}" for k, v in zip(keys, values)]
        out = os.path.join(args.out, f"variant_{index:02d}")
        run = run_variant(args, overrides, out)
        row = dict(zip(keys, values))
        row.update(variant=index, status=run["status"] if run else "no run.json")
        if run:
            row.update(steps=run["steps"], wall_seconds=round(run["wall_seconds"]["total"], 3),
                       particles=sum(p["particles"]["total"] for p in run["phases"].values()))
        all_completed &= row["status"] == "completed"
        summary = validate(args, out) if run else None
        if summary:
            row.update(quantity=summary[0], value=summary[1], reference=summary[2],
                       error=summary[3], target=summary[4], verdict=summary[5])
        row["error_value"] = numeric_error(row.get("error", "-"))
        rows.append(row)

    columns = (["variant"] + keys + ["status", "particles", "steps", "wall_seconds", "quantity",
                                     "value", "reference", "error", "error_value", "target",
                                     "verdict"])
    with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    if not args.no_plot:
        plot(rows, keys, os.path.join(args.out, "study.png"))
    for row in rows:
        print("  ".join(f"{c}={row.get(c, '')}" for c in columns))
    return 0 if all_completed else 1


if __name__ == "__main__":
    sys.exit(main())
