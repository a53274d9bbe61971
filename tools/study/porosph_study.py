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
overrides and the same scene file, by its SHA-256; not one whose status is still "running") are
not rerun; a run of an edited scene is.
Exit status: 0 when every variant ran to completion, 1 otherwise (the table is still written).

Convergence mode: --converge KEY=V1,V2,... instead of --vary runs one level per value (KEY is the
resolution, normally run.dp; its values are sorted coarse to fine) into OUT/dp_VALUE and writes
convergence.csv (error per level, observed order p between successive levels, Richardson value of
the measured quantity with that p) and convergence.png (log-log error against dp with the slope
--expected-order, default 2, drawn). Its verdict fails, exit status 1, when the error grows from
one level to the next (or a level has no error); arithmetic in tools/study/convergence.py.

  tools/study/porosph_study.py cases/darcy_column/scene.toml --check darcy_column \\
      --converge run.dp=0.005,0.0025,0.00125 --out runs/converge_darcy

--quantity TEXT (either mode) takes the error from the summary line whose quantity contains TEXT
(case-insensitive) instead of the first one, e.g. --quantity "max speed". --error-from value takes
|value - reference| (first number of each column) instead of the error column, whose rounding
(e.g. "0.02 %") can hide a change between levels. --error-from change (--converge only, three or
more levels) takes the change of the value from the next coarser level, |Q_i - Q_{i-1}|: the
self-convergence of a quantity whose reference is missing or carries an error of its own (the
dam break's release); the order is that of the changes and Richardson extrapolates the value.
"""
import argparse
import csv
import itertools
import json
import hashlib
import math
import os
import re
import subprocess
import sys

import convergence

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def parse_vary(text, option="--vary"):
    if "=" not in text:
        raise SystemExit(f"porosph_study: {option} '{text}': expected KEY=V1,V2,...")
    key, values = text.split("=", 1)
    values = [v for v in values.split(",") if v]
    if not values:
        raise SystemExit(f"porosph_study: {option} '{text}': no values")
    return key, values


def numeric_value(text):
    """The first number in text: '1.25 %' -> 1.25, '-0.0040 m' -> -0.004, '-' -> nan."""
    match = re.search(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", text)
    return float(match.group(0)) if match else math.nan


def reference_value(text):
    """A reference that is a measured value: its text starts with the number ('0.0096889 m/s (i =
    1)' -> 0.0096889); a citation or formula ('Bui et al. (2008)', 'rho g (H - y)') -> nan, so
    that a year or a coefficient in it is never taken for the reference."""
    match = re.match(r"\s*([-+]?\d+(\.\d*)?([eE][-+]?\d+)?)", text)
    return float(match.group(1)) if match else math.nan


def numeric_error(text):
    """'1.25 %' -> 1.25, '+0.0040' -> 0.004, '-' -> nan."""
    return abs(numeric_value(text))


def show(x, spec):
    return "-" if math.isnan(x) else format(x, spec)


def run_marker(args, overrides):
    """What study_overrides.json records of a run: its overrides and its scene file's SHA-256."""
    with open(args.scene, "rb") as f:
        scene = hashlib.sha256(f.read()).hexdigest()
    return {"overrides": overrides, "scene_sha256": scene}


def run_variant(args, overrides, out):
    """Runs one variant unless OUT already holds a run with the same overrides of the same scene
    file; its run.json."""
    record = os.path.join(out, "run.json")
    marker = os.path.join(out, "study_overrides.json")
    if os.path.exists(record) and os.path.exists(marker):
        with open(marker) as f:
            if json.load(f) == run_marker(args, overrides):
                with open(record) as g:
                    run = json.load(g)
                if run.get("status") != "running":  # not one still running or killed
                    return run
    command = [os.path.join(args.bin, "coupler"), "run", args.scene, "--out", out,
               "--overwrite", "--no-progress"]  # a variant whose earlier run did not match
    for o in overrides:
        command += ["--set", o]
    print("porosph_study: " + " ".join(command), flush=True)
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    if not os.path.exists(record):
        return None
    with open(marker, "w") as f:
        json.dump(run_marker(args, overrides), f)
    with open(record) as f:
        return json.load(f)


def validate(args, out):
    command = [os.path.join(args.bin, "porosph_validate"), args.check, out] + args.check_args
    result = subprocess.run(command, capture_output=True, text=True)
    lines = [l.split("\t")[1:] for l in result.stdout.splitlines() if l.startswith("summary\t")]
    if not args.quantity:
        return lines[0] if lines else None
    for line in lines:
        if args.quantity.lower() in line[0].lower():
            return line
    print(f"porosph_study: no summary line of {args.check} names '{args.quantity}'; it has: "
          + "; ".join(l[0] for l in lines), file=sys.stderr)
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


def measure(args, overrides, out, row):
    """Runs (or reuses) one variant, validates it and fills row; True when the run completed."""
    run = run_variant(args, overrides, out)
    row["status"] = run["status"] if run else "no run.json"
    if run:
        row.update(steps=run["steps"], wall_seconds=round(run["wall_seconds"]["total"], 3),
                   particles=sum(p["particles"]["total"] for p in run["phases"].values()))
    summary = validate(args, out) if run else None
    if summary:
        row.update(quantity=summary[0], value=summary[1], reference=summary[2],
                   error=summary[3], target=summary[4], verdict=summary[5])
    row["error_value"] = numeric_error(row.get("error", "-"))
    if args.error_from == "value":  # |value - reference|, in the unit of the value
        row["error_value"] = abs(numeric_value(row.get("value", "-"))
                                 - reference_value(row.get("reference", "-")))
    return row["status"] == "completed"


def converge(args):
    """--converge KEY=V1,V2,...: one level per value, coarse to fine; convergence.csv/png."""
    key, values = parse_vary(args.converge, "--converge")
    try:
        levels = sorted(values, key=float, reverse=True)
    except ValueError:
        raise SystemExit(f"porosph_study: --converge '{args.converge}': values must be numbers")
    if len({float(v) for v in levels}) != len(levels) or len(levels) < 2:
        raise SystemExit(f"porosph_study: --converge '{args.converge}': need two or more "
                         "different levels")
    rows, all_completed = [], True
    for index, value in enumerate(levels):
        row = {"level": index, key: value}
        out = os.path.join(args.out, f"{key.split('.')[-1]}_{value}")  # a level added later
        all_completed &= measure(args, args.fixed + [f"{key}={value}"], out, row)
        row["value_numeric"] = numeric_value(row.get("value", "-"))
        rows.append(row)
    dps = [float(v) for v in levels]
    # Richardson applies to a measured quantity, not to a value that is the error itself
    values = [math.nan if r.get("value") == r.get("error") else r["value_numeric"] for r in rows]
    first = 0
    if args.error_from == "change":  # self-convergence: |Q_i - Q_{i-1}|, none at the coarsest
        if len(rows) < 3:
            raise SystemExit("porosph_study: --error-from change needs three or more levels")
        for i, row in enumerate(rows):
            row["error_value"] = abs(values[i] - values[i - 1]) if i > 0 else math.nan
        first = 1
    orders, extrapolated, verdict, passed = convergence.analyse(
        dps[first:], [r["error_value"] for r in rows[first:]], values[first:])
    orders, extrapolated = [math.nan] * first + orders, [math.nan] * first + extrapolated
    for row, p, q in zip(rows, orders, extrapolated):
        row.update(observed_order=p, richardson_value=q, convergence_verdict=verdict)
    columns = ["level", key, "status", "particles", "steps", "wall_seconds", "quantity", "value",
               "reference", "error", "error_value", "observed_order", "richardson_value",
               "target", "verdict", "convergence_verdict"]
    convergence.write_csv(rows, columns, os.path.join(args.out, "convergence.csv"))
    quantity = next((r["quantity"] for r in rows if r.get("quantity")), "error")
    if not args.no_plot:
        ylabel = {"value": "|value - reference|", "change": "|value - coarser level's|"}.get(
            args.error_from, "error (summary's error column)")
        convergence.plot(dps, [r["error_value"] for r in rows], orders, args.expected_order,
                         f"{args.check}: {quantity}\n{verdict}", ylabel,
                         os.path.join(args.out, "convergence.png"))
    print(f"{'level':>5} {key:>10} {'wall [s]':>9} {'value':>16} {'error':>10} {'e used':>10}"
          f" {'order p':>8} {'Richardson Q':>13}")
    for r in rows:
        print(f"{r['level']:>5} {r[key]:>10} {convergence.fmt(r.get('wall_seconds', '')):>9} "
              f"{r.get('value', '-'):>16} {r.get('error', '-'):>10} "
              f"{show(r['error_value'], '.4g'):>10} {show(r['observed_order'], '.3f'):>8} "
              f"{show(r['richardson_value'], '.6g'):>13}")
    print(f"quantity: {quantity}; p = log(e_i/e_i+1)/log(dp_i/dp_i+1); Richardson "
          "Q_R = Q_f + (Q_f - Q_c)/(r^p - 1) with the p of the same row")
    print(f"verdict: {verdict}")
    return 0 if passed and all_completed else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--check", required=True, help="porosph_validate subcommand")
    parser.add_argument("--check-arg", dest="check_args", action="append", default=[],
                        help="extra argument for porosph_validate (repeatable)")
    parser.add_argument("--vary", action="append", default=[], help="KEY=V1,V2,...")
    parser.add_argument("--converge", help="KEY=DP1,DP2,...: convergence mode (see above)")
    parser.add_argument("--expected-order", type=float, default=2.0,
                        help="slope of the reference line in convergence.png (default 2)")
    parser.add_argument("--quantity", help="pick the summary line whose quantity contains this")
    parser.add_argument("--error-from", choices=["column", "value", "change"], default="column",
                        help="error = the summary's error column (default), |value - reference| "
                        "or (--converge) |value - the coarser level's value|")
    parser.add_argument("--set", dest="fixed", action="append", default=[],
                        help="KEY=VALUE for every variant")
    parser.add_argument("--out", required=True)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--no-plot", action="store_true")
    args = parser.parse_args()
    if bool(args.vary) == bool(args.converge):
        raise SystemExit("porosph_study: give --vary KEY=V1,V2,... or --converge KEY=DP1,DP2,...")
    os.makedirs(args.out, exist_ok=True)
    if args.converge:
        return converge(args)
    varies = [parse_vary(v) for v in args.vary]
    keys = [k for k, _ in varies]

    rows, all_completed = [], True
    for index, values in enumerate(itertools.product(*[v for _, v in varies])):
        overrides = args.fixed + [f"{k}={v}" for k, v in zip(keys, values)]
        out = os.path.join(args.out, f"variant_{index:02d}")
        row = dict(zip(keys, values))
        row["variant"] = index
        all_completed &= measure(args, overrides, out, row)
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
