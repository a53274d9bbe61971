#!/usr/bin/python3
"""tools/study/porosph_study.py on a real scene: two resolutions of the Darcy column, shortened.

The Darcy column's steady velocity is reached after ~10 drag relaxation times rho k / mu (~1 ms):
at t = 0.01 s both variants are within the case's 2 % bound (measured 0.03-0.04 % at 0.02 s), so
the table must show two completed variants with finite errors below 2, the finer one with four
times the particles, and a PNG. A malformed --vary must fail with a message naming it.
Environment: POROSPH_SOURCE_DIR, POROSPH_BIN_DIR (set by ctest)."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

SOURCE = os.environ["POROSPH_SOURCE_DIR"]
BIN = os.environ["POROSPH_BIN_DIR"]
TOOL = os.path.join(SOURCE, "tools", "study", "porosph_study.py")
SCENE = os.path.join(SOURCE, "cases", "darcy_column", "scene.toml")


class StudyTool(unittest.TestCase):
    def test_runs_every_variant_and_writes_the_table_and_the_plot(self):
        out = tempfile.mkdtemp(prefix="porosph-study-")
        result = subprocess.run(
            [sys.executable, TOOL, SCENE, "--check", "darcy_column", "--vary",
             "run.dp=0.005,0.0025", "--set", "run.end_time=0.01", "--set",
             "run.output_interval=0.005", "--out", out, "--bin", BIN],
            capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(os.path.join(out, "study.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["run.dp"] for r in rows], ["0.005", "0.0025"])
        for r in rows:
            self.assertEqual(r["status"], "completed")
            self.assertLess(float(r["error_value"]), 2.0)
            self.assertGreater(float(r["wall_seconds"]), 0.0)
        self.assertEqual(int(rows[1]["particles"]), 4 * int(rows[0]["particles"]))
        self.assertGreater(os.path.getsize(os.path.join(out, "study.png")), 1000)

    def test_malformed_vary_is_an_error(self):
        result = subprocess.run(
            [sys.executable, TOOL, SCENE, "--check", "darcy_column", "--vary", "run.dp",
             "--out", tempfile.mkdtemp(prefix="porosph-study-")], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("--vary 'run.dp'", result.stderr)


if __name__ == "__main__":
    unittest.main()
