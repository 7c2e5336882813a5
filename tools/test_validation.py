#!/usr/bin/env python3
"""Checks of validation.py on results made up for the purpose (no simulation runs): the power-law
fit recovers K and n within four of its standard errors; a point whose realisations split
between stable and collapsed is intermittent and its means carry standard errors; Table 1 fitted
from a synthetic h_stop staircase and flow map generated from the paper's values (Weinhart et
al. 2012, Table 1, with noise) comes back within four standard errors and is written to
table1.json. (The staircase's noise is kept small: the flow rule's errors are those of its own
fit, given the fitted h_stop curve, and do not carry the curve's uncertainty.) Deterministic
(fixed seed)."""
import csv
import json
import math
import os
import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation  # noqa: E402
from talus.studies import chute_fits  # noqa: E402


def write_csv(path, rows):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


class Validation(unittest.TestCase):
    def setUp(self):
        self.rng = np.random.default_rng(2021)
        self.tmp = tempfile.TemporaryDirectory()
        self.base = Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_kept_runs_are_not_run_again(self):
        # A fresh checkout has the kept runs under validation/ but no runs folder: they go back
        # into it with their summaries, so that the sweep passes over them; an interrupted one
        # does not.
        fam = validation.FAMILIES[0]
        saved = validation.VALIDATION
        validation.VALIDATION = self.base / "validation"
        try:
            kept = fam.folder(validation.VALIDATION) / "gate_position=0.04"
            for seed, reason in [(1, "collapse_over"), (2, "interrupted")]:
                (kept / f"seed_{seed}").mkdir(parents=True)
                (kept / f"seed_{seed}" / "summary.json").write_text(json.dumps({"stop_reason": reason}))
            runs = fam.folder(self.base / "runs")
            validation.restore_kept(fam, runs)
            self.assertTrue(validation.finished(runs / "gate_position=0.04" / "seed_1"))
            self.assertFalse((runs / "gate_position=0.04" / "seed_2").exists())
        finally:
            validation.VALIDATION = saved

    def test_power_fit_recovers_its_parameters(self):
        a = np.array([0.8, 1.5, 2.5, 4.0, 6.0, 9.0])
        y = 1.9 * a ** 0.67 * np.exp(self.rng.normal(0, 0.03, a.size))
        K, n, K_err, n_err = validation.power_fit(list(zip(a, y)))
        self.assertLess(abs(K - 1.9), 4 * K_err)
        self.assertLess(abs(n - 0.67), 4 * n_err)
        self.assertIsNone(validation.power_fit([(1.0, 2.0), (1.0, 3.0), (1.0, 4.0)]))  # no spread in a

    def test_mixed_outcomes_are_intermittent(self):
        point = self.base / "huet2021" / "crosses" / "gate_position=0.04"
        outcomes = [("stable", 0.05), ("collapsed", 1.9), ("collapsed", 2.3)]
        for k, (regime, runout) in enumerate(outcomes, start=1):
            (point / f"seed_{k}").mkdir(parents=True)
            summary = {"regime": regime, "aspect_ratio": 3.0 + 0.1 * k, "L0": 0.04, "H0": 0.12,
                       "dam_break": {"runout_ratio": runout, "height_ratio": 1.5,
                                     "before_gate": {"whole": {"coordination_points": 8.0 + 0.1 * k}}}}
            (point / f"seed_{k}" / "summary.json").write_text(json.dumps(summary))
        [case] = validation.huet_cases(self.base)
        self.assertEqual(case["regime"], "intermittent")
        self.assertEqual(case["regimes"], {"collapsed": 2, "stable": 1})
        runouts = [r for _, r in outcomes]
        self.assertAlmostEqual(case["runout_ratio"], np.mean(runouts))
        self.assertAlmostEqual(case["runout_ratio_err"], np.std(runouts, ddof=1) / math.sqrt(3))
        mean, sd = case["whole.coordination_points"]
        self.assertAlmostEqual(mean, 8.2)
        self.assertAlmostEqual(sd, 0.1)  # Table III quotes the standard deviation, not the error

    def test_table1_from_a_synthetic_staircase_and_flow_map(self):
        t1 = validation.TABLE1
        intervals, runs = [], []
        for h in [4, 6, 8, 10, 14, 18, 24, 30, 36]:
            theta = float(chute_fits.theta_stop35(h, t1["A"], t1["delta1"], t1["delta2"])) + self.rng.normal(0, 0.02)
            intervals.append({"lambda": 1, "kind": "angle", "H": h, "h": h, "angle_lo": theta - 0.25,
                              "angle_hi": theta + 0.25, "h_lo": "", "h_hi": ""})
        for H in [10, 20, 30, 40]:
            for theta in [22, 24, 26, 28]:
                h = 0.95 * H
                hs = chute_fits.hstop35(theta, t1["A"], t1["delta1"], t1["delta2"])
                F = t1["beta"] * h / hs - t1["gamma"] + self.rng.normal(0, 0.02)
                runs.append({"lambda": 1, "H": H, "angle": theta, "flow_state": "steady", "h": h, "froude": F,
                             "alpha": 1.1 + self.rng.normal(0, 0.01), "K": 1.0 + self.rng.normal(0, 0.01)})
        write_csv(self.base / "weinhart2012" / "hstop" / "hstop_intervals.csv", intervals)
        write_csv(self.base / "weinhart2012" / "flowmap" / "sweep_runs.csv", runs)
        lines = []
        validation.weinhart_report(lines, [], self.base)
        table = json.loads((self.base / "weinhart2012" / "table1.json").read_text())
        self.assertEqual(table["lambda"], 1)
        for name, value in t1.items():
            self.assertTrue(table[name + "_err"] > 0, name)
            self.assertLess(abs(table[name] - value), 4 * table[name + "_err"], f"{name}: {table[name]} vs {value}")
        self.assertTrue(any(line.startswith("| delta1 |") for line in lines))
        self.assertTrue(table["staircase_complete"])

    def test_a_staircase_still_running_is_reported_from_its_cases(self):
        # Thin layers only: the intervals come from hstop_runs.csv, and an Eq. 35 fit that heights
        # below 12 d cannot determine leaves Table 1 empty rather than printing its bounds.
        t1 = validation.TABLE1
        rows = []
        for H in [4, 6, 8, 10, 12]:
            h = H - 0.6
            theta_stop = float(chute_fits.theta_stop35(h, t1["A"], t1["delta1"], t1["delta2"]))
            for theta in [round(2 * theta_stop) / 2 - 0.5 * k for k in range(-1, 3)]:
                rows.append({"lambda": 1, "H": H, "angle": theta, "h": h, "flow_state": "steady",
                             "arrested": int(theta < theta_stop), "froude": 0.1, "alpha": 1.3, "K": 1.1})
        write_csv(self.base / "weinhart2012" / "hstop" / "hstop_runs.csv", rows)
        lines = []
        validation.weinhart_report(lines, [], self.base)
        table = json.loads((self.base / "weinhart2012" / "table1.json").read_text())
        self.assertFalse(table["staircase_complete"])
        self.assertEqual(table["staircase_max_H"], 12)
        self.assertTrue(any("still running" in line for line in lines))
        angle_rows = [line for line in lines if line.startswith("| H = ")]
        self.assertEqual(len(angle_rows), 5)
        for line in angle_rows:  # every interval brackets the curve that decided its cases
            self.assertTrue(line.endswith("| 0.00° |"), line)
        self.assertIn("Every case lies on the side of the paper's curve that its outcome says.", lines)
        self.assertIsNone(table["delta1"])
        self.assertTrue(any("not determined yet" in line for line in lines))


if __name__ == "__main__":
    unittest.main()
