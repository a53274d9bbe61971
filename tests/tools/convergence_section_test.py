#!/usr/bin/python3
"""tools/validation/convergence_section.py: the convergence section of docs/validation.md.

A study's row must carry its levels, errors, observed orders and the study tool's verdict (a
growing error marked as a failed verdict); a study whose runs are gone keeps the earlier report's
row; and previous_report must hand that section back whole, not as a case's section."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.environ["POROSPH_SOURCE_DIR"], "tools", "validation"))
import convergence_section as cs  # noqa: E402
from previous_report import previous_report  # noqa: E402

COLUMNS = ("level,run.dp,status,particles,steps,wall_seconds,quantity,value,reference,error,"
           "error_value,observed_order,richardson_value,target,verdict,convergence_verdict")
GROWING = [
    "0,0.0028575,completed,1670,5678,5.1,mean |dZ|,0.077,M&M,0.077,0.077,,,<= 0.10,met,V",
    "1,0.00142875,completed,4928,11394,41.8,mean |dZ|,0.125,M&M,0.125,0.125,-0.699,,<= 0.10,"
    "not met,V",
    "2,0.000714375,completed,16238,22823,323.0,mean |dZ|,0.187,M&M,0.187,0.187,-0.581,,<= 0.10,"
    "not met,V"]


def write_study(runs, study, lines, verdict):
    os.makedirs(cs.study_dir(runs, study), exist_ok=True)
    with open(cs.csv_path(runs, study), "w") as f:
        f.write(COLUMNS + "\n" + "\n".join(x.replace(",V", "," + verdict) for x in lines) + "\n")


class ConvergenceSection(unittest.TestCase):
    def test_a_growing_error_is_a_failed_verdict_with_its_orders(self):
        runs = tempfile.mkdtemp(prefix="porosph-conv-")
        dam = next(s for s in cs.STUDIES if s["name"] == "dam_break")
        write_study(runs, dam, GROWING, "ERROR GROWS WITH REFINEMENT - verdict fails")
        line = cs.row(dam, runs)
        self.assertIn("| dam_break | mean \\|dZ\\| |", line)
        self.assertIn("0.002857 / 0.001429 / 0.0007144", line)
        self.assertIn("0.077 / 0.125 / 0.187", line)
        self.assertIn("-0.70, -0.58", line)
        self.assertIn("**ERROR GROWS WITH REFINEMENT - verdict fails**", line)
        self.assertIn("5 / 42 / 323 s", line)

    def test_a_self_convergence_row_shows_the_values_and_their_changes(self):
        runs = tempfile.mkdtemp(prefix="porosph-conv-")
        front = next(s for s in cs.STUDIES if s["name"] == "dam_break_front")
        lines = ["0,0.0028575,completed,1,1,3.1,mean Z,2.7654,-,-,,,,-,no target,V",
                 "1,0.00142875,completed,1,1,22.5,mean Z,2.8165,-,-,0.0511,,,-,no target,V",
                 "2,0.000714375,completed,1,1,298.8,mean Z,2.8019,-,-,0.0146,1.807,2.79606,-,"
                 "no target,V"]
        write_study(runs, front, lines, "error falls with refinement")
        line = cs.row(front, runs)
        self.assertIn("value 2.7654 / 2.8165 / 2.8019; change - / 0.0511 / 0.0146", line)
        self.assertIn("| 1.81 | 2.79606 | error falls with refinement |", line)
        self.assertIn("--error-from change", cs.shell_line(front))

    def test_a_study_whose_runs_are_gone_keeps_the_earlier_row(self):
        runs = tempfile.mkdtemp(prefix="porosph-conv-")
        earlier = ("| soil_column | sigma_v error | 0.02 / 0.01 / 0.005 | 1.2 / 1.1 / 1.0 % "
                   "| 0.1, 0.1 | - | error falls with refinement | 2 / 13 / 97 s |")
        text = cs.section(runs, cs.TITLE + "\n\n| study (case) | x |\n| --- | --- |\n" + earlier)
        self.assertIn(earlier, text)
        self.assertNotIn("| dam_break |", text)  # neither run nor in the earlier report
        for case, _, where in cs.ELSEWHERE:
            self.assertIn(f"| {case} |", text)
            self.assertIn(where, text)

    def test_the_earlier_report_hands_the_section_back_whole(self):
        path = os.path.join(tempfile.mkdtemp(prefix="porosph-conv-"), "validation.md")
        runs = tempfile.mkdtemp(prefix="porosph-conv-")
        dam = next(s for s in cs.STUDIES if s["name"] == "dam_break")
        write_study(runs, dam, GROWING, "ERROR GROWS WITH REFINEMENT - verdict fails")
        with open(path, "w") as f:
            f.write("# Validation report\n\n| case | quantity | value |\n| --- | --- | --- |\n"
                    "| dam_break | x | 1 |\n\n"
                    + cs.section(runs) + "\n## dam_break: Dam break\n\ntext\n")
        rows, sections, multi = previous_report(path)
        self.assertEqual(list(rows), ["dam_break"])
        self.assertIn("convergence", multi)
        self.assertIn("| dam_break | mean \\|dZ\\| |", multi["convergence"])
        self.assertNotIn("Convergence of each verdict", sections)
        self.assertIn("dam_break", sections)


if __name__ == "__main__":
    unittest.main()
