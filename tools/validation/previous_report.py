"""What an earlier docs/validation.md holds, read back so that `report.py --only` can rewrite some
cases and keep every other one as it was measured (its run directory may be gone: the long runs
live outside the repository)."""
import os
import re


def previous_report(path):
    """The rows and sections of an existing report by case name (and its sections over several
    cases: "heave", the Fig. 8 grid; "rockfill", B against q), so that --only can rewrite some
    cases and keep the others as they were measured."""
    rows, sections, multi_case = {}, {}, {}
    if not os.path.exists(path):
        return rows, sections, multi_case
    with open(path) as f:
        text = f.read()
    summary_table = text.split("\n## ")[0]  # the per-case rows; later tables are per section
    for line in summary_table.splitlines():
        cells = line.split(" | ")
        if line.startswith("| ") and len(cells) > 2 and not line.startswith(("| case", "| ---")):
            rows.setdefault(cells[0][2:].strip(), []).append(line)
    for block in re.split(r"\n(?=## )", text)[1:]:
        title = block.splitlines()[0]
        if title.startswith("## Failure time against"):
            multi_case["heave"] = block.rstrip("\n") + "\n"
        elif title.startswith("## Rockfill: B against"):
            multi_case["rockfill"] = block.rstrip("\n") + "\n"
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
        if line.startswith("| case"):
            header = cells
        elif header and line.startswith("| ") and not line.startswith("| ---"):
            col = dict(zip(header, cells))
            if "dp [m]" in col:
                dp = float(col["dp [m]"])
            elif stated_dp:
                dp = float(stated_dp.group(1))
            else:
                raise ValueError(f"B-against-q row without a spacing: {line}")
            flow, width = float(col["Q [l/s]"]), float(col["W [m]"])
            rows.append((1e-3 * flow / width, flow, width,
                         float(col["B (wet, moved > D15)"].split()[0]),
                         float(col["run to"].split()[0]), col["case"], dp))
    return rows
