"""What an earlier docs/validation.md holds, read back so that `report.py --only` can rewrite some
cases and keep every other one as it was measured (its run directory may be gone: the long runs
live outside the repository)."""
import os
import re

# The columns of the B-against-q table: report.py writes them, previous_width_rows reads them.
CASE, DP, FLOW, WIDTH, B, RUN_TO = ("case", "dp [m]", "Q [l/s]", "W [m]", "B (wet, moved > D15)",
                                    "run to")
WIDTH_COLUMNS = [CASE, DP, FLOW, WIDTH, "q [l/s/m]", B, "experiment at this Q", RUN_TO]


def previous_report(path):
    """The rows and sections of an existing report by case name (and its sections over several
    cases: "heave", the Fig. 8 grid; "rockfill", B against q), so that --only can rewrite some
    cases and keep the others as they were measured."""
    rows, sections, multi_case = {}, {}, {}
    if not os.path.exists(path):
        return rows, sections, multi_case
    with open(path) as f:
        text = f.read()
    blocks = re.split(r"\n(?=## )", text)  # the summary table, then one block per section
    in_summary = False  # the opening's other tables (the model version of the rows) are prose
    for line in blocks[0].splitlines():
        if line.startswith("| case |"):
            in_summary = True
            continue
        if not line.startswith("| "):
            in_summary = False
            continue
        cells = line.split(" | ")
        if in_summary and len(cells) > 2 and not line.startswith("| ---"):
            rows.setdefault(cells[0][2:].strip(), []).append(line)
    for block in blocks[1:]:
        title = block.splitlines()[0]
        if title.startswith("## Failure time against"):
            multi_case["heave"] = block.rstrip("\n") + "\n"
        elif title.startswith("## Rockfill: B against"):
            multi_case["rockfill"] = block.rstrip("\n") + "\n"
        elif title.startswith("## Convergence of each verdict"):
            multi_case["convergence"] = block.rstrip("\n") + "\n"
        else:
            sections[title[3:].split(":")[0]] = block.rstrip("\n") + "\n"
    return rows, sections, multi_case


def previous_width_rows(block):
    """The rows of an earlier report's B-against-q section, as rockfill_width_section builds them,
    so that a report of some rockfill runs keeps the others as they were measured (their run
    directories may be gone). Reports written before the table had a dp column ran every row at the
    spacing named in their opening paragraph ("(dp 0.02 m)")."""
    header, rows = None, []
    stated_dp = re.search(r"\(dp ([0-9.]+) m\)", block or "")
    for line in (block or "").splitlines():
        cells = [x.strip() for x in line.strip().strip("|").split("|")]
        if cells[0] == CASE:
            header = cells
        elif header and line.startswith("| ") and not line.startswith("| ---"):
            col = dict(zip(header, cells))
            if DP in col:
                dp = float(col[DP])
            elif stated_dp:
                dp = float(stated_dp.group(1))
            else:
                raise ValueError(f"B-against-q row without a spacing: {line}")
            flow, width = float(col[FLOW]), float(col[WIDTH])
            rows.append((1e-3 * flow / width, flow, width, float(col[B].split()[0]),
                         float(col[RUN_TO].split()[0]), col[CASE], dp))
    return rows
