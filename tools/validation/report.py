#!/usr/bin/python3
"""Validation report: runs (or reads) the seed paper's cases and the classic benchmarks, compares
each with its reference through build/bin/porosph_validate, plots the time series against the
reference and writes docs/validation.md with the figures in docs/validation/.

  tools/validation/report.py                  # read finished runs in runs/validation/, write the report
  tools/validation/report.py --run            # first run every case whose run is missing (hours)
  tools/validation/report.py --run --only hydraulic_heave rockfill_q19
                                              # --only: rewrite these cases' rows and sections,
                                              # keep every other case as the existing report has it
  tools/validation/report.py --list           # the cases, their scenes and overrides

Needs python3-numpy, python3-h5py and python3-matplotlib (Debian packages; scripts/report.sh
installs them and runs this script). The case list (scene, overrides, validate command) is CASES below; the physics
of each check is in tools/validation/*.h and docs/validation-studies.md.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

import case_plots
import convergence_section
import report_header
from previous_report import WIDTH_COLUMNS, previous_report, previous_width_rows

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def case(name, title, scene, check, overrides=(), extra=(), plot=None, notes="", run_dir=None):
    """run_dir: where the run lives relative to --runs (default: the case name); the long runs
    of runs/long/ are read where they run."""
    return dict(name=name, title=title, scene=scene, check=check, overrides=list(overrides),
                extra=list(extra), plot=plot, notes=notes, run_dir=run_dir or name)


HEAVE_GRID = [(26, 40), (29, 40), (29, 45), (32, 40), (35, 40)]  # with eq. 10's cone
HEAVE_GRID_FLOW_RULE = [(26, 40), (29, 40), (32, 40)]              # the scene's yield fit
EQ10 = ["soil.materials[0].yield_fit=eq10", "soil.materials[1].yield_fit=eq10"]

CASES = [
    case("dam_break", "Dam break against Martin & Moyce (1952), n^2 = 2",
         "cases/dam_break/scene.toml", "dam_break", plot=case_plots.dam_break,
         notes="Front Z = z/a against T = t sqrt(2g/a); resolution series in "
               "docs/validation-studies.md."),
    case("hydrostatic_tank", "Still water tank, 2 s", "cases/hydrostatic_tank/scene.toml",
         "hydrostatic_tank", plot=case_plots.hydrostatic_tank),
    case("soil_column", "Dry soil column at rest", "cases/soil_column/scene.toml", "soil_column",
         plot=case_plots.soil_column),
    case("granular_collapse", "Granular column collapse (Bui et al. 2008)",
         "cases/granular_collapse/scene.toml", "granular_collapse",
         plot=case_plots.granular_collapse,
         notes="The experiment's profile is not available here: the run-out is reported without "
               "an error."),
    case("darcy_column", "Darcy column (Kozeny-Carman)", "cases/darcy_column/scene.toml",
         "darcy_column", plot=case_plots.darcy_column),
    case("darcy_column_forchheimer", "Forchheimer column (Den Adel)",
         "cases/darcy_column/scene_forchheimer.toml", "darcy_column",
         plot=case_plots.darcy_column),
    case("fluidized_bed", "Fluidised bed (paper 4.1), quick variant",
         "cases/fluidized_bed/scene.toml", "fluidized_bed",
         overrides=["run.dp=0.002", "run.end_time=4.0", "water.inflow[0].ramp_time=1.0"]
         + [f"soil.materials[{m}].young_modulus=2.0e5" for m in range(3)],
         extra=["--window", "0.5"], plot=case_plots.fluidized_bed,
         notes="dp 2 mm, E softened 25x and the ramp shortened to 1 s (docs/coupling.md says why "
               "the equilibrium does not depend on either); the paper-resolution runs, and why "
               "the scene has the Shepard density filter off, are in "
               "docs/validation-studies.md."),
    case("rockfill_q19", "Rockfill core overtopping (paper 4.2), Q = 19.36 l/s",
         "cases/rockfill_overtopping/scene.toml", "rockfill_overtopping",
         overrides=["run.dp=0.02", "run.end_time=300.2", "run.checkpoint_wall_minutes=10"],
         plot=case_plots.rockfill, run_dir="../long/rockfill_q19",
         notes="dp 0.02 m (half the docs/cases.md resolution), flume width W = 2.5 m (assumed); run "
               "towards the experiment's steady state (~300 s), checkpointed."),
    case("rockfill_q30", "Rockfill core overtopping (paper 4.2), Q = 30.45 l/s",
         "cases/rockfill_overtopping/scene.toml", "rockfill_overtopping",
         overrides=["run.dp=0.02", "run.end_time=300.2", "run.checkpoint_wall_minutes=10",
                    "water.inflow[0].flow_rate=0.03045"],
         plot=case_plots.rockfill, run_dir="../long/rockfill_q30",
         notes="dp 0.02 m, W = 2.5 m (assumed); run towards the experiment's steady state, "
               "checkpointed."),
] + [
    case(f"rockfill_q{q}_{tag}", f"Rockfill core overtopping, Q = {Q} l/s in a flume of W = {w} m "
         "(the flume-width sensitivity)", "cases/rockfill_overtopping/scene.toml",
         "rockfill_overtopping",
         overrides=["run.dp=0.02", "run.end_time=300.2", "run.checkpoint_wall_minutes=10",
                    f"water.inflow[0].flow_rate={Q / 1000:.5f}",
                    f"water.inflow[0].cross_section={0.04 * w:g}"],
         plot=case_plots.rockfill, run_dir=f"../long/rockfill_q{q}_{tag}",
         notes=f"dp 0.02 m; flume width W = {w} m instead of the scene's assumed 2.5 m, so "
               f"q = Q / W is {2.5 / w:g} times the scene's (docs/validation-studies.md, "
               "\"Rockfill to steady state\").")
    for (tag, w) in [("w125", 1.25), ("w100", 1.0), ("w094", 0.94), ("w090", 0.9),
                     ("w080", 0.8)]
    for (q, Q) in [(19, 19.36), (30, 30.45)]
] + [
    case(f"rockfill_q{q}_w100_dp01", f"Rockfill core overtopping, Q = {Q} l/s, W = 1.0 m, at the "
         "docs/cases.md spacing dp = 0.01 m", "cases/rockfill_overtopping/scene.toml",
         "rockfill_overtopping",
         overrides=["run.dp=0.01", "run.end_time=300.2", "run.checkpoint_wall_minutes=10",
                    f"water.inflow[0].flow_rate={Q / 1000:.5f}",
                    "water.inflow[0].cross_section=0.04"],
         plot=case_plots.rockfill, run_dir=f"../long/rockfill_q{q}_w100_dp01",
         notes="dp 0.01 m (the docs/cases.md spacing, 4 times the particles of dp 0.02 m), W = 1.0 m: "
               "the resolution check of the W = 1.0 m pair (docs/validation-studies.md).")
    for (q, Q) in [(19, 19.36), (30, 30.45)]
] + [
    case("hydraulic_heave", "Hydraulic heave next to a sheet pile (paper 4.3), phi 29 / 40",
         "cases/hydraulic_heave/scene.toml", "hydraulic_heave",
         overrides=["run.dp=0.0025", "run.checkpoint_wall_minutes=10"],
         plot=case_plots.hydraulic_heave, run_dir="../long/heave_dp2.5_s34",
         notes="dp 2.5 mm (the paper's spacing); Drucker-Prager matched to Mohr-Coulomb for "
               "psi = 0 (yield_fit = flow_rule, docs/soil.md). The verdict over three resolutions "
               "(dp 10 / 5 / 2.5 mm) is in docs/validation-studies.md, 'Hydraulic heave at three "
               "resolutions': at the scene's cfl 0.2 it does not converge; at one time step "
               "(9.3e-6 s) no level fails by 6 s ('Heave: the coarse levels' late advance and "
               "failure are the time step'). The sand carried under the pile and the gravel's "
               "mean settlement are bulk measures beside the one-particle failure, for "
               "self-convergence; the time step's error in them is the drag's weighting over the "
               "step ('Heave: where the time step's error comes from')."),
    case("heave_eq10", "Hydraulic heave with the seed paper's eq. 10 cone, phi 29 / 40",
         "cases/hydraulic_heave/scene.toml", "hydraulic_heave",
         overrides=["run.dp=0.005"] + EQ10, plot=case_plots.hydraulic_heave,
         notes="dp 5 mm; eq. 10's Drucker-Prager constants (associated-flow fit, a narrower "
               "cone for psi = 0) instead of the scene's flow_rule fit."),
] + [
    case(f"heave_s{s}_g{g}", f"Hydraulic heave, eq. 10, phi sand {s} / gravel {g} (Fig. 8 grid)",
         "cases/hydraulic_heave/scene.toml", "hydraulic_heave",
         overrides=["run.dp=0.005", "run.end_time=5.2", f"soil.materials[0].friction_angle={s}",
                    f"soil.materials[1].friction_angle={g}"] + EQ10)
    for (s, g) in HEAVE_GRID if (s, g) != (29, 40)
] + [
    case(f"heave_fr_s{s}_g{g}", f"Hydraulic heave, phi sand {s} / gravel {g} (Fig. 8 grid)",
         "cases/hydraulic_heave/scene.toml", "hydraulic_heave",
         overrides=["run.dp=0.005", "run.end_time=5.2", f"soil.materials[0].friction_angle={s}",
                    f"soil.materials[1].friction_angle={g}"])
    for (s, g) in HEAVE_GRID_FLOW_RULE if (s, g) != (29, 40)
] + [
    case("heave_mls", "Hydraulic heave, dp 5 mm, with the (mls) stress filter every 10 steps",
         "cases/hydraulic_heave/scene.toml", "hydraulic_heave",
         overrides=["run.dp=0.005", "soil.stress_filter_every=10"] + EQ10,
         plot=case_plots.hydraulic_heave,
         notes="The scene runs without a stress filter, as the seed paper; this variant filters "
               "the soil stress every 10 steps with the first-order (mls) weights "
               "(docs/validation-studies.md, \"The stress filter near a free face\")."),
]


def run_path(c, args):
    return os.path.normpath(os.path.join(args.runs, c["run_dir"]))


def readable_copy(out, scratch):
    """A run still in progress: a copy of its outputs (not its checkpoints), read without HDF5's
    file locks, so that neither the run nor the report disturbs the other."""
    copy = os.path.join(scratch, os.path.basename(out))
    os.makedirs(copy, exist_ok=True)
    for name in os.listdir(out):
        if os.path.isfile(os.path.join(out, name)):
            shutil.copy2(os.path.join(out, name), copy)
    return copy


def run_case(c, args):
    out = run_path(c, args)
    command = [os.path.join(args.bin, "coupler"), "run", os.path.join(ROOT, c["scene"]),
               "--out", out, "--overwrite"]  # a rerun replaces the missing or stale run
    for o in c["overrides"]:
        command += ["--set", o]
    print("running:", " ".join(command), flush=True)
    subprocess.run(command, check=False, stdout=subprocess.DEVNULL)


def validate(c, args, out=None):
    out = out or run_path(c, args)
    series = os.path.join(out, "validate_series.csv")
    command = [os.path.join(args.bin, "porosph_validate"), c["check"], out] + c["extra"]
    if c["check"] in ("rockfill_overtopping", "hydraulic_heave", "dam_break"):
        command += ["--series", series]
    result = subprocess.run(command, capture_output=True, text=True)
    text = result.stdout + result.stderr
    summaries = [line.split("\t")[1:] for line in result.stdout.splitlines()
                 if line.startswith("summary\t")]
    return text, summaries


def run_facts(out):
    with open(os.path.join(out, "run.json")) as f:
        run = json.load(f)
    particles = {p: v["initial"]["particle_count"] for p, v in run["phases"].items()}
    status = run["status"]
    if status == "failed" and run.get("message", "").startswith("interrupted by signal"):
        status = "stopped (signal; checkpointed, `coupler run --resume` continues it)"
    return dict(particles=particles, steps=run["steps"], wall=run["wall_seconds"]["total"],
                status=status, time=run["simulated_time"])


def command_line(c):
    sets = "".join(f" --set '{o}'" for o in c["overrides"])
    where = os.path.normpath(os.path.join("runs/validation", c["run_dir"]))
    return (f"build/bin/coupler run {c['scene']}{sets} --out {where}\n"
            f"build/bin/porosph_validate {c['check']} {where}"
            + "".join(" " + e for e in c["extra"]))


def heave_grid_rows(args, grid, name_of):
    rows = []
    for (s, g) in grid:
        out = os.path.join(args.runs, name_of(s, g))
        if os.path.exists(os.path.join(out, "run.json")):
            _, summaries = validate(dict(check="hydraulic_heave", extra=[], run_dir=name_of(s, g)),
                                    args)
            rows.append((s, g, summaries[0][1] if summaries else "?"))
    return rows


def heave_grid_section(args):
    fits = [("flow_rule (the scene)", heave_grid_rows(
                args, HEAVE_GRID_FLOW_RULE,
                lambda s, g: "hydraulic_heave" if (s, g) == (29, 40) else f"heave_fr_s{s}_g{g}")),
            ("eq. 10", heave_grid_rows(
                args, HEAVE_GRID,
                lambda s, g: "heave_eq10" if (s, g) == (29, 40) else f"heave_s{s}_g{g}"))]
    if not any(rows for _, rows in fits):
        return ""
    text = ["## Failure time against the friction angles (the paper's Fig. 8 idea)", "",
            "dp 5 mm, other inputs as cases/hydraulic_heave/scene.toml (`--set "
            "'soil.materials[0].friction_angle=S' --set 'soil.materials[1].friction_angle=G'`; "
            "eq. 10 rows also `--set 'soil.materials[0].yield_fit=eq10' --set "
            "'soil.materials[1].yield_fit=eq10'`), 5 s after the damping stage (phi 29 / 40: the "
            "scene's 6 s).", "",
            "| Drucker-Prager fit | phi sand | phi gravel | time of complete failure "
            "(experiment 4.4 s) |", "| --- | --- | --- | --- |"]
    text += [f"| {fit} | {s} | {g} | {v} |" for fit, rows in fits for (s, g, v) in rows]
    figure = case_plots.heave_grid(fits, args.figures)
    if figure:
        text += ["", f"![failure time vs friction angles]({os.path.relpath(figure, args.docs)})"]
    return "\n".join(text) + "\n"


def rockfill_width_section(args, b_values, previous_block=""):
    """B against the discharge per metre over the rockfill runs (the flume width W is not known:
    each run's q = Q / W). b_values: case name -> the B its check reported; previous_block: the
    earlier report's section, whose rows stand for the cases not measured this time."""
    rows = [r for r in previous_width_rows(previous_block) if r[5] not in b_values]
    for c in CASES:
        if c["name"] not in b_values:
            continue
        name, b = c["name"], b_values[c["name"]]
        with open(os.path.join(run_path(c, args), "run.json")) as f:
            run = json.load(f)
        inflow = run["parameters"]["water"]["inflow"][0]
        width = inflow["cross_section"] / (inflow["max"][1] - inflow["min"][1])
        rows.append((inflow["flow_rate"] / width, 1e3 * inflow["flow_rate"], width, b,
                     run["simulated_time"], name, run["parameters"]["run"]["dp"]))
    if not rows:
        return ""
    rows.sort()
    text = ["## Rockfill: B against the discharge per metre (the flume width)", "",
            "The paper gives Q, not the flume width W; the 2D model needs q = Q / W. Each row is "
            "one run of cases/rockfill_overtopping/scene.toml with "
            "`--set 'water.inflow[0].cross_section=0.04 W'` (the scene assumes W = 2.5 m).", "",
            "| " + " | ".join(WIDTH_COLUMNS) + " |", "|" + " --- |" * len(WIDTH_COLUMNS)]
    for (q, flow, width, b, t, name, dp) in rows:
        b_exp = case_plots.ROCKFILL_B_EXPERIMENT.get(round(flow, 2))
        exp = f"{b_exp} m" if b_exp is not None else "-"
        text.append(f"| {name} | {dp:g} | {flow:.2f} | {width:.2f} | {1e3 * q:.1f} | {b:.3f} m "
                    f"| {exp} | {t:.1f} s |")
    figure = case_plots.rockfill_b_against_q([r[:4] + (r[6],) for r in rows], args.figures)
    text += ["", f"![B against q]({os.path.relpath(figure, args.docs)})"]
    return "\n".join(text) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", default=os.path.join(ROOT, "runs", "validation"))
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "validation.md"))
    parser.add_argument("--run", action="store_true", help="run the cases whose run is missing")
    parser.add_argument("--only", nargs="*", help="case names (default: all)")
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    args.docs = os.path.dirname(args.out)
    args.figures = os.path.join(args.docs, "validation")
    os.makedirs(args.figures, exist_ok=True)
    cases = [c for c in CASES if not args.only or c["name"] in args.only]
    if args.list:
        for c in cases:
            print(f"{c['name']:28s} {c['scene']} {' '.join(c['overrides'])}")
        return 0
    if args.run:
        for c in cases:
            if not os.path.exists(os.path.join(run_path(c, args), "run.json")):
                run_case(c, args)
        for s in convergence_section.STUDIES if not args.only else []:
            if not os.path.exists(convergence_section.csv_path(args.runs, s)):
                convergence_section.run_study(s, args.runs, args.bin)
    os.environ["HDF5_USE_FILE_LOCKING"] = "FALSE"  # also for the plots (h5py)
    scratch = tempfile.mkdtemp(prefix="porosph-report-")

    table = ["| case | quantity | PoroSPH | reference | error | target | verdict | particles "
             "(initial, per phase, walls included) | steps | wall time |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    sections = []
    rockfill_b = {}
    kept_rows, kept_sections, kept_multi = previous_report(args.out) if args.only else ({}, {}, {})
    grows = convergence_section.grown(args.runs)
    for c in CASES:
        if args.only and c["name"] not in args.only:
            table += kept_rows.get(c["name"], [f"| {c['name']} | not run | | | | | | | | |"])
            if c["name"] in kept_sections:
                sections.append(kept_sections[c["name"]])
            continue
        out = run_path(c, args)
        if not os.path.exists(os.path.join(out, "run.json")):
            if c["name"] in kept_rows:
                print(f"{c['name']}: no run in {out}; the previous report's figures are kept")
                table += kept_rows[c["name"]]
                sections += [kept_sections[c["name"]]] if c["name"] in kept_sections else []
                continue
            table.append(f"| {c['name']} | not run | | | | | | | | |")
            continue
        facts = run_facts(out)
        partial = facts["status"] == "running"
        if partial:
            out = readable_copy(out, scratch)
        text, summaries = validate(c, args, out)
        state = f"partial: running, t = {facts['time']:.1f} s so far; " if partial else ""
        particles = ", ".join(f"{p} {n:,}" for p, n in facts["particles"].items())
        if c["check"] == "rockfill_overtopping" and summaries:
            rockfill_b[c["name"]] = float(summaries[0][1].split()[0])
        for cells in summaries:
            if (c["name"], cells[0]) in grows:  # met or not here, the series fails
                cells = cells[:5] + [cells[5] + "; **error grows with dp** (see convergence)"]
            quantity, value, reference, error, target, verdict = (x.replace("|", "\\|")
                                                                  for x in cells)
            table.append(f"| {c['name']} | {state}{quantity} | {value} | {reference} | {error} | "
                         f"{target} | {verdict} | {particles} | {facts['steps']:,} | "
                         f"{facts['wall']:.0f} s |")
        if c["name"].startswith(("heave_s", "heave_fr_s")):
            continue  # the grid's runs appear in the Fig. 8 table only
        figures = c["plot"](out, args.figures, c["name"]) if c["plot"] else []
        body = [f"## {c['name']}: {c['title']}", "", c["notes"], "", "```", command_line(c),
                "```", "", f"Run: {facts['status']} to t = {facts['time']:.3f} s"
                f"{' (in progress: a copy of its outputs so far)' if partial else ''}, "
                f"{facts['steps']:,} steps, {facts['wall']:.0f} s wall time; {particles}.", "",
                "```", text.strip(), "```", ""]
        body += [f"![{c['name']}]({os.path.relpath(f, args.docs)})" for f in figures]
        sections.append("\n".join(body) + "\n")

    header = list(report_header.HEADER)
    grid_cases = [c["name"] for c in CASES if c["name"].startswith(("heave_s", "heave_fr_s"))]
    rockfill_cases = {c["name"] for c in CASES if c["check"] == "rockfill_overtopping"}
    keep = args.only is not None and not set(args.only) & set(grid_cases + ["hydraulic_heave",
                                                                          "heave_eq10"])
    grid = kept_multi.get("heave", "") if keep else heave_grid_section(args)
    keep = args.only is not None and not set(args.only) & rockfill_cases
    # The rockfill cases measured now, and the earlier report's rows for the others.
    grid += "\n" + (kept_multi.get("rockfill", "") if keep else
                    rockfill_width_section(args, rockfill_b, kept_multi.get("rockfill", "")))
    # Every verdict's resolution series (convergence_section.py runs them; rows kept when gone).
    grid = convergence_section.section(args.runs, kept_multi.get("convergence", "")) + "\n" + grid
    with open(args.out, "w") as f:
        f.write("\n".join(header + table) + "\n\n" + grid + "\n"
                + "\n".join(sections))
    shutil.rmtree(scratch, ignore_errors=True)
    print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
