#!/usr/bin/python3
"""tools/study/porosph_study.py on a real scene: two resolutions of the Darcy column, shortened.

The Darcy column's steady velocity is reached after ~10 drag relaxation times rho k / mu (~1 ms):
at t = 0.01 s both variants are within the case's 2 % bound (measured 0.03-0.04 % at 0.02 s), so
the table must show two completed variants with finite errors below 2, the finer one with four
times the particles, and a PNG. A malformed --vary must fail with a message naming it.
Convergence mode (--converge): the hydrostatic tank at dp 0.04 / 0.02 / 0.01 for 0.2 s (~5 s) must
give a table sorted coarse to fine whose order column and exit status follow from its own errors;
a rerun with --quantity reuses the runs and reads another summary line. Stub binaries (a fake
coupler and porosph_validate with made-up errors) drive the growing-error path (exit 1) and the
Richardson column end to end; the arithmetic of tools/study/convergence.py is tested on made-up
numbers. Environment: POROSPH_SOURCE_DIR, POROSPH_BIN_DIR (set by ctest)."""
import csv
import json
import math
import os
import stat
import subprocess
import sys
import tempfile
import unittest

SOURCE = os.environ["POROSPH_SOURCE_DIR"]
BIN = os.environ["POROSPH_BIN_DIR"]
TOOL = os.path.join(SOURCE, "tools", "study", "porosph_study.py")
SCENE = os.path.join(SOURCE, "cases", "darcy_column", "scene.toml")
TANK = os.path.join(SOURCE, "cases", "hydrostatic_tank", "scene.toml")
sys.path.insert(0, os.path.join(SOURCE, "tools", "study"))
import convergence  # noqa: E402


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


def read_table(out):
    with open(os.path.join(out, "convergence.csv")) as f:
        return list(csv.DictReader(f))


class ConvergenceArithmetic(unittest.TestCase):
    def test_second_order_series_gives_order_two_and_the_exact_limit(self):
        dps = [0.02, 0.01, 0.005]
        values = [1.0 + 3.0 * d * d for d in dps]
        errors = [abs(v - 1.0) for v in values]
        orders, extrapolated, verdict, passed = convergence.analyse(dps, errors, values)
        self.assertTrue(math.isnan(orders[0]) and math.isnan(extrapolated[0]))
        for p, q in zip(orders[1:], extrapolated[1:]):
            self.assertAlmostEqual(p, 2.0, places=10)
            self.assertAlmostEqual(q, 1.0, places=12)
        self.assertEqual((verdict, passed), (convergence.FALLS, True))

    def test_uneven_ratio_and_first_order(self):
        dps = [0.03, 0.01, 0.0025]  # r = 3 then 4
        values = [2.0 - 5.0 * d for d in dps]
        orders, extrapolated, _, passed = convergence.analyse(
            dps, [abs(v - 2.0) for v in values], values)
        self.assertAlmostEqual(orders[1], 1.0, places=10)
        self.assertAlmostEqual(orders[2], 1.0, places=10)
        self.assertAlmostEqual(extrapolated[2], 2.0, places=12)
        self.assertTrue(passed)
        # by hand: p = log(0.06 / 0.03) / log 2 = 1; Q_R = 1.03 + (1.03 - 1.06) / (2 - 1) = 1.0
        self.assertAlmostEqual(convergence.observed_order(0.06, 0.03, 0.02, 0.01), 1.0)
        self.assertAlmostEqual(convergence.richardson(1.06, 1.03, 2.0, 1.0), 1.0)

    def test_growing_error_fails_even_when_it_first_falls(self):
        for errors in ([0.06, 0.11, 0.15], [0.5, 0.1, 0.2], [0.1, 0.1000001]):
            dps = [0.02, 0.01, 0.005][:len(errors)]
            orders, extrapolated, verdict, passed = convergence.analyse(dps, errors, errors)
            self.assertEqual((verdict, passed), (convergence.GROWS, False), errors)
            self.assertLess(orders[-1], 0.0)
            self.assertTrue(math.isnan(extrapolated[-1]))  # no Richardson with p <= 0
        orders, _, _, _ = convergence.analyse([0.02, 0.01, 0.005], [0.06, 0.11, 0.15], [0] * 3)
        self.assertAlmostEqual(orders[1], math.log(0.06 / 0.11) / math.log(2.0))

    def test_a_citation_is_no_reference_value(self):
        import porosph_study  # noqa: E402
        self.assertEqual(porosph_study.reference_value("0.0096889 m/s (i = 1)"), 0.0096889)
        self.assertEqual(porosph_study.reference_value(" -2 m/s"), -2.0)
        self.assertTrue(math.isnan(porosph_study.reference_value("Bui et al. (2008): n/a")))
        self.assertTrue(math.isnan(porosph_study.reference_value("rho g (H - y)")))

    def test_equal_missing_and_exact_errors(self):
        self.assertEqual(convergence.analyse([0.02, 0.01], [0.2, 0.2], [1, 1])[2:],
                         (convergence.NOT_GROWING, True))
        self.assertEqual(convergence.analyse([0.02, 0.01], [0.2, math.nan], [1, 1])[2:],
                         (convergence.MISSING, False))
        self.assertEqual(convergence.observed_order(0.2, 0.0, 0.02, 0.01), math.inf)
        with self.assertRaises(ValueError):
            convergence.analyse([0.01, 0.02], [0.1, 0.05], [1, 1])


STUB_COUPLER = """#!/usr/bin/python3
import json, os, sys
a = sys.argv
out = a[a.index("--out") + 1]
dp = float([s for s in a if s.startswith("run.dp=")][-1].split("=")[1])
os.makedirs(out, exist_ok=True)
json.dump({"status": "completed", "steps": int(1 / dp), "wall_seconds": {"total": 0.1 / dp},
           "phases": {"water": {"particles": {"total": int(1 / dp ** 2)}}}, "dp": dp},
          open(os.path.join(out, "run.json"), "w"))
"""
STUB_VALIDATE = """#!/usr/bin/python3
import json, os, sys
dp = json.load(open(os.path.join(sys.argv[2], "run.json")))["dp"]
if os.environ["STUB_MODE"] == "grows":  # error 0.1 / 0.05 / 0.08 at dp 0.02 / 0.01 / 0.005
    e = {0.02: 0.1, 0.01: 0.05, 0.005: 0.08}[dp]
    print("summary\tfront\t%.4f m\t0 m\t%.4f m\t-\tmet" % (e, e))
else:  # q = 2 + 40 dp^2 m/s against 2 m/s: order 2, Richardson value 2
    q = 2 + 40 * dp * dp
    print("summary\tother\t1\t1\t9 %\t-\tmet")
    print("summary\tspeed\t%.10f m/s\t2 m/s\t%.10f m/s\t-\tmet" % (q, q - 2))
"""


class ConvergenceMode(unittest.TestCase):
    def stub_bin(self):
        bin_dir = tempfile.mkdtemp(prefix="porosph-study-bin-")
        for name, text in (("coupler", STUB_COUPLER), ("porosph_validate", STUB_VALIDATE)):
            path = os.path.join(bin_dir, name)
            with open(path, "w") as f:
                f.write(text)
            os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
        return bin_dir

    def run_stub(self, mode, *extra):
        out = tempfile.mkdtemp(prefix="porosph-converge-stub-")
        result = subprocess.run(
            [sys.executable, TOOL, SCENE, "--check", "any", "--converge",
             "run.dp=0.005,0.02,0.01", "--out", out, "--bin", self.stub_bin(), *extra],
            capture_output=True, text=True, env=dict(os.environ, STUB_MODE=mode))
        return result, out

    def test_an_edited_scene_is_rerun_and_an_unchanged_one_is_not(self):
        scene = os.path.join(tempfile.mkdtemp(prefix="porosph-study-scene-"), "scene.toml")
        with open(SCENE) as f, open(scene, "w") as g:
            g.write(f.read())
        out = tempfile.mkdtemp(prefix="porosph-converge-stub-")
        command = [sys.executable, TOOL, scene, "--check", "any", "--converge",
                   "run.dp=0.02,0.01,0.005", "--out", out, "--bin", self.stub_bin()]
        env = dict(os.environ, STUB_MODE="falls")
        first = subprocess.run(command, capture_output=True, text=True, env=env)
        self.assertEqual(first.stdout.count("coupler run"), 3, first.stdout + first.stderr)
        same = subprocess.run(command, capture_output=True, text=True, env=env)
        self.assertNotIn("coupler run", same.stdout)
        with open(scene, "a") as g:
            g.write("# edited\n")
        edited = subprocess.run(command, capture_output=True, text=True, env=env)
        self.assertEqual(edited.stdout.count("coupler run"), 3, edited.stdout + edited.stderr)

    def test_growing_error_fails_with_exit_status_one(self):
        result, out = self.run_stub("grows")
        self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
        self.assertIn("ERROR GROWS WITH REFINEMENT - verdict fails", result.stdout)
        rows = read_table(out)
        self.assertEqual([r["run.dp"] for r in rows], ["0.02", "0.01", "0.005"])
        self.assertEqual(rows[2]["convergence_verdict"], convergence.GROWS)
        self.assertAlmostEqual(float(rows[1]["observed_order"]), 1.0, places=5)
        self.assertAlmostEqual(float(rows[2]["observed_order"]), math.log(0.05 / 0.08) / math.log(2),
                               places=5)
        self.assertEqual(rows[1]["richardson_value"], "")  # the value is the error itself
        self.assertGreater(os.path.getsize(os.path.join(out, "convergence.png")), 1000)

    def test_falling_error_passes_with_order_and_richardson_of_the_picked_quantity(self):
        result, out = self.run_stub("falls", "--quantity", "SPEED", "--error-from", "value")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("verdict: " + convergence.FALLS, result.stdout)
        rows = read_table(out)
        self.assertEqual({r["quantity"] for r in rows}, {"speed"})
        for r in rows[1:]:
            self.assertAlmostEqual(float(r["observed_order"]), 2.0, places=4)
            self.assertAlmostEqual(float(r["richardson_value"]), 2.0, places=6)

    def test_change_mode_judges_the_self_convergence_of_the_value(self):
        # q = 2 + 40 dp^2: changes 0.012 and 0.003 from the coarser level, order 2, limit 2
        result, out = self.run_stub("falls", "--quantity", "speed", "--error-from", "change")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        rows = read_table(out)
        self.assertEqual(rows[0]["error_value"], "")  # no coarser level to change from
        self.assertAlmostEqual(float(rows[1]["error_value"]), 0.012, places=9)
        self.assertAlmostEqual(float(rows[2]["error_value"]), 0.003, places=9)
        self.assertEqual(rows[1]["observed_order"], "")  # one change has no order yet
        self.assertAlmostEqual(float(rows[2]["observed_order"]), 2.0, places=6)
        self.assertAlmostEqual(float(rows[2]["richardson_value"]), 2.0, places=6)
        self.assertEqual(rows[2]["convergence_verdict"], convergence.FALLS)
        # two levels cannot show a change of the change
        out2 = tempfile.mkdtemp(prefix="porosph-converge-stub-")
        two = subprocess.run(
            [sys.executable, TOOL, SCENE, "--check", "any", "--converge", "run.dp=0.02,0.01",
             "--out", out2, "--bin", self.stub_bin(), "--error-from", "change"],
            capture_output=True, text=True, env=dict(os.environ, STUB_MODE="falls"))
        self.assertNotEqual(two.returncode, 0)
        self.assertIn("three or more levels", two.stderr)

    def test_unknown_quantity_names_the_available_ones_and_fails(self):
        result, _ = self.run_stub("falls", "--quantity", "nothing like it")
        self.assertEqual(result.returncode, 1)
        self.assertIn("it has: other; speed", result.stderr)

    def test_real_tank_table_follows_from_its_errors(self):
        out = tempfile.mkdtemp(prefix="porosph-converge-")
        command = [sys.executable, TOOL, TANK, "--check", "hydrostatic_tank", "--converge",
                   "run.dp=0.01,0.04,0.02", "--set", "run.end_time=0.2", "--set",
                   "run.output_interval=0.1", "--out", out, "--bin", BIN]
        result = subprocess.run(command, capture_output=True, text=True)
        rows = read_table(out)
        self.assertEqual([r["run.dp"] for r in rows], ["0.04", "0.02", "0.01"])
        errors = [float(r["error_value"]) for r in rows]
        for r in rows:
            self.assertEqual(r["status"], "completed")
            self.assertEqual(r["quantity"], "pressure error per particle (max)")
        self.assertLess(int(rows[0]["particles"]), int(rows[1]["particles"]))
        self.assertLess(int(rows[1]["particles"]), int(rows[2]["particles"]))
        for i in (1, 2):
            self.assertAlmostEqual(float(rows[i]["observed_order"]),
                                   math.log(errors[i - 1] / errors[i]) / math.log(2), places=4)
        grows = errors[1] > errors[0] or errors[2] > errors[1]
        self.assertEqual(result.returncode, 1 if grows else 0, result.stdout + result.stderr)
        self.assertEqual(rows[0]["convergence_verdict"],
                         convergence.GROWS if grows else convergence.FALLS)
        self.assertGreater(os.path.getsize(os.path.join(out, "convergence.png")), 1000)
        # the same levels again for another summary line: no run repeated
        again = subprocess.run(command + ["--quantity", "max speed"], capture_output=True,
                               text=True)
        self.assertNotIn("coupler run", again.stdout)
        self.assertEqual({r["quantity"] for r in read_table(out)}, {"max speed / sqrt(g H)"})


if __name__ == "__main__":
    unittest.main()
