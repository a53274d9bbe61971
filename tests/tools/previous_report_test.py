#!/usr/bin/python3
"""tools/validation/previous_report.py: what `report.py --only` keeps from an earlier report.

The rows kept for a case must come from the summary table only (a B-against-q or Fig. 8 row of
the same case name, or a row of the opening's model-version table, must not reappear there), and the B-against-q rows must be read back with the
spacing of their dp column or, in reports written before that column, of the section's text."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.environ["POROSPH_SOURCE_DIR"], "tools", "validation"))
from previous_report import previous_report, previous_width_rows  # noqa: E402

SUMMARY = """# Validation report

| rows | last run | later model changes |
| --- | --- | --- |
| rockfill_q19 | 2026-12-01 | all since |

| case | quantity | PoroSPH | reference | error | target | verdict | particles | steps | wall time |
| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |
| rockfill_q19 | B parameter | 0.000 m | 0.32 m | -100.0 % | 10 % | not met | soil 3,110 | 10 | 4 s |

"""
OLD_WIDTH = """## Rockfill: B against the discharge per metre (the flume width)

Each row is one run of cases/rockfill_overtopping/scene.toml (dp 0.02 m) with a width.

| case | Q [l/s] | W [m] | q [l/s/m] | B (wet, moved > D15) | experiment at this Q | run to |
| --- | --- | --- | --- | --- | --- | --- |
| rockfill_q19 | 19.36 | 2.50 | 7.7 | 0.000 m | 0.32 m | 70.0 s |
| rockfill_q30_w100 | 30.45 | 1.00 | 30.5 | 0.550 m | 0.68 m | 94.4 s |
"""
NEW_WIDTH = """## Rockfill: B against the discharge per metre (the flume width)

| case | dp [m] | Q [l/s] | W [m] | q [l/s/m] | B (wet, moved > D15) | experiment at this Q | run to |
| --- | --- | --- | --- | --- | --- | --- | --- |
| rockfill_q19_w100_dp01 | 0.01 | 19.36 | 1.00 | 19.4 | 0.330 m | 0.32 m | 80.0 s |
"""


class PreviousReport(unittest.TestCase):
    def test_case_rows_come_from_the_summary_table_only(self):
        with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as f:
            f.write(SUMMARY + OLD_WIDTH)
        rows, _, multi_case = previous_report(f.name)
        os.unlink(f.name)
        self.assertEqual(len(rows["rockfill_q19"]), 1)
        self.assertIn("B parameter", rows["rockfill_q19"][0])
        self.assertNotIn("rockfill_q30_w100", rows)
        self.assertIn("rockfill", multi_case)

    def test_width_rows_without_a_dp_column_take_the_stated_spacing(self):
        rows = previous_width_rows(OLD_WIDTH)
        self.assertEqual([r[5] for r in rows], ["rockfill_q19", "rockfill_q30_w100"])
        q, flow, width, b, t, _, dp = rows[1]
        self.assertAlmostEqual(q, 0.03045, places=6)  # m^2/s = Q / W
        self.assertEqual((flow, width, b, t, dp), (30.45, 1.0, 0.55, 94.4, 0.02))

    def test_width_rows_with_a_dp_column(self):
        (row,) = previous_width_rows(NEW_WIDTH)
        self.assertEqual((row[3], row[6]), (0.33, 0.01))

    def test_a_row_without_any_spacing_is_an_error(self):
        with self.assertRaises(ValueError):
            previous_width_rows(OLD_WIDTH.replace("(dp 0.02 m) ", ""))


if __name__ == "__main__":
    unittest.main()
